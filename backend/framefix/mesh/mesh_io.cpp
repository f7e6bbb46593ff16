#include "framefix/mesh/mesh_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/mesh/mesh_io_text.h"

namespace framefix {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    std::string tail = s.substr(s.size() - suffix.size());
    std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return tail == suffix;
}

std::ofstream open_out(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw Error("write", "cannot open " + path + " for writing");
    out.precision(17);
    return out;
}

}  // namespace

TetMesh read_tet_mesh(const std::string& path) {
    if (ends_with(path, ".msh")) return read_msh(path);
    if (ends_with(path, ".mesh")) return read_medit(path);
    throw Error("load", path + ": unknown mesh format; expected .msh (gmsh v4 ASCII) or .mesh (Medit)");
}

namespace {

// Tet faces (tet * 4 + lf) seen by exactly one tet, ordered by their sorted vertices. The faces
// are bucketed by their smallest vertex and only each bucket (about 20 faces) is sorted: a sort
// of all 4 #T faces was a fifth of reading a 1M-tet file.
std::vector<int> boundary_tet_faces(const Tets& tets, int nv) {
    const int nt = int(tets.rows());
    std::vector<int> start(size_t(nv) + 1, 0);
    auto sorted_face = [&](int t, int lf) {
        std::array<int, 3> v = {tets(t, kTetFace[lf][0]), tets(t, kTetFace[lf][1]), tets(t, kTetFace[lf][2])};
        std::sort(v.begin(), v.end());
        return v;
    };
    for (int t = 0; t < nt; ++t)
        for (int lf = 0; lf < 4; ++lf) ++start[size_t(sorted_face(t, lf)[0]) + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<std::array<int, 3>> rec(size_t(nt) * 4);  // the two larger vertices, tet * 4 + lf
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t)
        for (int lf = 0; lf < 4; ++lf) {
            const std::array<int, 3> v = sorted_face(t, lf);
            rec[size_t(fill[v[0]]++)] = {v[1], v[2], t * 4 + lf};
        }
    std::vector<int> boundary;
    for (int v = 0; v < nv; ++v) {
        const auto first = rec.begin() + start[v], last = rec.begin() + start[v + 1];
        std::sort(first, last);
        for (auto i = first; i != last;) {
            auto j = i + 1;
            while (j != last && (*j)[0] == (*i)[0] && (*j)[1] == (*i)[1]) ++j;
            if (j - i > 2)
                throw Error("load", "a triangle is shared by " + std::to_string(j - i) + " tets; the mesh is not a manifold solid");
            if (j - i == 1) boundary.push_back((*i)[2]);
            i = j;
        }
    }
    return boundary;
}

}  // namespace

TetMesh assemble_tet_mesh(Points points, Tets tets, const Triangles& tri, const Eigen::VectorXi& tri_tags) {
    const int nt = int(tets.rows());
    if (nt == 0) throw Error("load", "the file has no tetrahedra; a volume (3D) tet mesh is needed");
    // Keep only the vertices used by tets (gmsh also stores e.g. points of embedded geometry).
    std::vector<int> remap(points.rows(), -1);
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 4; ++k) {
            const int v = tets(t, k);
            if (v < 0 || v >= points.rows())
                throw Error("load", "tet " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                                        " of " + std::to_string(points.rows()));
            remap[v] = 0;
        }
    int used = 0;
    for (int& r : remap)
        if (r == 0) r = used++;
    Points kept(used, 3);
    for (int v = 0; v < int(remap.size()); ++v)
        if (remap[v] >= 0) kept.row(remap[v]) = points.row(v);
    TetMesh mesh;
    mesh.points = std::move(kept);
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 4; ++k) tets(t, k) = remap[tets(t, k)];
    mesh.tets = std::move(tets);

    double edge_sum = 0;
    for (int t = 0; t < nt; ++t) {
        double vol = tet_volume(mesh, t);
        if (vol < 0) {
            std::swap(mesh.tets(t, 1), mesh.tets(t, 2));
            vol = -vol;
        }
        if (!(vol > 0))
            throw Error("load", "tet " + std::to_string(t) + " is flat (zero volume); the mesh is invalid");
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                edge_sum += (mesh.points.row(mesh.tets(t, a)) - mesh.points.row(mesh.tets(t, b))).norm();
    }
    mesh.size = edge_sum / (6.0 * nt);

    const std::vector<int> boundary = boundary_tet_faces(mesh.tets, used);
    std::vector<std::array<int, 4>> tagged(tri.rows());  // sorted file triangle (remapped) + tag
    for (int f = 0; f < tri.rows(); ++f) {
        std::array<int, 3> v{};
        for (int k = 0; k < 3; ++k) {
            const int p = tri(f, k);
            v[k] = p >= 0 && p < int(remap.size()) ? remap[p] : -1;
        }
        std::sort(v.begin(), v.end());
        tagged[f] = {v[0], v[1], v[2], tri_tags(f)};
    }
    std::sort(tagged.begin(), tagged.end());
    mesh.boundary_faces.resize(int(boundary.size()), 3);
    mesh.face_tags = Eigen::VectorXi::Zero(int(boundary.size()));
    for (int f = 0; f < int(boundary.size()); ++f) {
        const int t = boundary[f] / 4, lf = boundary[f] % 4;
        std::array<int, 3> v{};
        for (int k = 0; k < 3; ++k) v[k] = mesh.boundary_faces(f, k) = mesh.tets(t, kTetFace[lf][k]);
        std::sort(v.begin(), v.end());
        auto it = std::lower_bound(tagged.begin(), tagged.end(), std::array<int, 4>{v[0], v[1], v[2], INT32_MIN});
        if (it != tagged.end() && (*it)[0] == v[0] && (*it)[1] == v[1] && (*it)[2] == v[2]) mesh.face_tags(f) = (*it)[3];
    }
    mesh.feature_edges.resize(0, 2);
    mesh.edge_tags.resize(0);
    mesh.corner_vertices.resize(0);
    return mesh;
}

void write_msh(const TetMesh& mesh, const std::string& path) {
    std::ofstream out = open_out(path);
    std::vector<int> tags;
    for (int f = 0; f < mesh.face_tags.size(); ++f) tags.push_back(mesh.face_tags(f));
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    const int nv = mesh.num_vertices(), nt = mesh.num_tets(), nb = int(mesh.boundary_faces.rows());
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    out << "$Nodes\n1 " << nv << " 1 " << nv << "\n3 1 0 " << nv << "\n";
    for (int v = 0; v < nv; ++v) out << v + 1 << "\n";
    for (int v = 0; v < nv; ++v) out << mesh.points(v, 0) << " " << mesh.points(v, 1) << " " << mesh.points(v, 2) << "\n";
    out << "$EndNodes\n$Elements\n" << tags.size() + 1 << " " << nb + nt << " 1 " << nb + nt << "\n";
    int id = 1;
    for (int tag : tags) {
        int n = 0;
        for (int f = 0; f < nb; ++f) n += mesh.face_tags(f) == tag;
        out << "2 " << tag << " 2 " << n << "\n";
        for (int f = 0; f < nb; ++f)
            if (mesh.face_tags(f) == tag)
                out << id++ << " " << mesh.boundary_faces(f, 0) + 1 << " " << mesh.boundary_faces(f, 1) + 1 << " "
                    << mesh.boundary_faces(f, 2) + 1 << "\n";
    }
    out << "3 1 4 " << nt << "\n";
    for (int t = 0; t < nt; ++t)
        out << id++ << " " << mesh.tets(t, 0) + 1 << " " << mesh.tets(t, 1) + 1 << " " << mesh.tets(t, 2) + 1 << " "
            << mesh.tets(t, 3) + 1 << "\n";
    out << "$EndElements\n";
    if (!out) throw Error("write", "writing " + path + " failed");
}

void write_medit(const TetMesh& mesh, const std::string& path) {
    std::ofstream out = open_out(path);
    out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << mesh.num_vertices() << "\n";
    for (int v = 0; v < mesh.num_vertices(); ++v)
        out << mesh.points(v, 0) << " " << mesh.points(v, 1) << " " << mesh.points(v, 2) << " 0\n";
    out << "Triangles\n" << mesh.boundary_faces.rows() << "\n";
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f)
        out << mesh.boundary_faces(f, 0) + 1 << " " << mesh.boundary_faces(f, 1) + 1 << " "
            << mesh.boundary_faces(f, 2) + 1 << " " << (mesh.face_tags.size() ? mesh.face_tags(f) : 0) << "\n";
    out << "Tetrahedra\n" << mesh.num_tets() << "\n";
    for (int t = 0; t < mesh.num_tets(); ++t)
        out << mesh.tets(t, 0) + 1 << " " << mesh.tets(t, 1) + 1 << " " << mesh.tets(t, 2) + 1 << " "
            << mesh.tets(t, 3) + 1 << " 0\n";
    out << "End\n";
    if (!out) throw Error("write", "writing " + path + " failed");
}

}  // namespace framefix
