// Medit .mesh ASCII reader (INRIA libMesh keywords; indices 1-based, each entity ends with a reference).
#include <map>
#include <vector>

#include "framefix/mesh/mesh_io.h"
#include "framefix/mesh/mesh_io_text.h"

namespace framefix {

TetMesh read_medit(const std::string& path) {
    TextTokens tok(path, '#');
    // Sections we skip: keyword -> numbers per entity.
    static const std::map<std::string, int> skipped = {
        {"Edges", 3},          {"Corners", 1},       {"RequiredVertices", 1}, {"Ridges", 1},
        {"RequiredEdges", 1},  {"Quadrilaterals", 5}, {"Normals", 3},         {"NormalAtVertices", 2},
        {"Tangents", 3},       {"TangentAtVertices", 2}, {"RequiredTriangles", 1}};
    if (tok.word() != "MeshVersionFormatted") tok.fail("not a Medit .mesh file (no MeshVersionFormatted)");
    tok.integer();
    Points points(0, 3);
    Tets tets(0, 4);
    Triangles tris(0, 3);
    Eigen::VectorXi tri_tags;
    bool have_vertices = false, ended = false;
    const long long limit = tok.max_items();
    auto index = [&](int n) {
        const long long v = tok.integer();
        if (v < 1 || v > n) tok.fail("vertex index " + std::to_string(v) + " out of range 1.." + std::to_string(n));
        return int(v - 1);
    };
    while (!tok.at_end()) {
        const std::string key = tok.word();
        if (key == "End") {
            ended = true;
            break;
        }
        if (key == "Dimension") {
            if (tok.integer() != 3) tok.fail("only 3D meshes are supported (Dimension 3)");
        } else if (key == "Vertices") {
            const int n = tok.count(limit, "vertex");
            points.resize(n, 3);
            for (int v = 0; v < n; ++v) {
                for (int k = 0; k < 3; ++k) points(v, k) = tok.real();
                tok.integer();
            }
            have_vertices = true;
        } else if (key == "Triangles" || key == "Tetrahedra") {
            if (!have_vertices) tok.fail(key + " before Vertices");
            const bool tet = key == "Tetrahedra";
            const int n = tok.count(limit, tet ? "tet" : "triangle");
            const int nn = tet ? 4 : 3;
            if (tet) tets.resize(n, 4);
            else {
                tris.resize(n, 3);
                tri_tags.resize(n);
            }
            for (int e = 0; e < n; ++e) {
                for (int k = 0; k < nn; ++k) (tet ? tets(e, k) : tris(e, k)) = index(int(points.rows()));
                const int ref = int(tok.integer());
                if (!tet) tri_tags(e) = ref;
            }
        } else if (key == "Hexahedra" || key == "Prisms" || key == "Pyramids") {
            tok.fail("the mesh has " + key + "; a tet mesh is needed");
        } else if (auto it = skipped.find(key); it != skipped.end()) {
            const int n = tok.count(limit, key.c_str());
            for (long long i = 0; i < (long long)n * it->second; ++i) tok.real();
        } else {
            tok.fail("unknown keyword '" + key + "'");
        }
    }
    if (!ended) tok.fail("missing End keyword (truncated file?)");
    return assemble_tet_mesh(std::move(points), std::move(tets), tris, tri_tags);
}

}  // namespace framefix
