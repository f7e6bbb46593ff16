#include "framefix/tetgen/tet_output.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "framefix/core/error.h"
#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

double signed_volume(const Points& p, int a, int b, int c, int d) {
    const Eigen::Vector3d p0 = p.row(a);
    return (p.row(b).transpose() - p0).dot((p.row(c).transpose() - p0).cross(p.row(d).transpose() - p0)) / 6.0;
}

void copy_tets(const tetgenio& out, TetMesh& mesh) {
    mesh.points.resize(out.numberofpoints, 3);
    for (int i = 0; i < out.numberofpoints; ++i)
        for (int k = 0; k < 3; ++k) mesh.points(i, k) = out.pointlist[3 * i + k];
    mesh.tets.resize(out.numberoftetrahedra, 4);
    for (int t = 0; t < out.numberoftetrahedra; ++t) {
        for (int k = 0; k < 4; ++k) mesh.tets(t, k) = out.tetrahedronlist[t * out.numberofcorners + k];
        // TetGen's own orientation is the opposite of ours; test each tet rather than trust that.
        if (signed_volume(mesh.points, mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)) < 0)
            std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
    }
}

// Boundary triangles turned so that the tet behind them lies on their negative side.
void copy_boundary(const tetgenio& out, TetMesh& mesh) {
    const int n = out.numberoftrifaces;
    mesh.boundary_faces.resize(n, 3);
    mesh.face_tags.resize(n);
    std::unordered_map<TriangleKey, int, TriangleKeyHash> index;
    index.reserve(size_t(n) * 2);
    for (int f = 0; f < n; ++f) {
        for (int k = 0; k < 3; ++k) mesh.boundary_faces(f, k) = out.trifacelist[3 * f + k];
        mesh.face_tags(f) = out.trifacemarkerlist ? out.trifacemarkerlist[f] : 0;
        index.emplace(triangle_key(mesh.boundary_faces(f, 0), mesh.boundary_faces(f, 1), mesh.boundary_faces(f, 2)), f);
    }
    std::vector<char> oriented(size_t(n), 0);
    for (int t = 0; t < mesh.num_tets(); ++t)
        for (int lf = 0; lf < 4; ++lf) {
            const int a = mesh.tets(t, kTetFace[lf][0]), b = mesh.tets(t, kTetFace[lf][1]), c = mesh.tets(t, kTetFace[lf][2]);
            const auto it = index.find(triangle_key(a, b, c));
            if (it == index.end()) continue;
            mesh.boundary_faces.row(it->second) << a, b, c;  // kTetFace is outward from the tet
            oriented[size_t(it->second)] = 1;
        }
    for (int f = 0; f < n; ++f) FF_ASSERT(oriented[size_t(f)]);
}

void copy_feature_edges(const tetgenio& out, TetMesh& mesh) {
    std::vector<std::array<int, 3>> edges;  // (a, b, tag)
    for (int e = 0; e < out.numberofedges; ++e) {
        const int marker = out.edgemarkerlist ? out.edgemarkerlist[e] : 0;
        if (marker > kFeatureMarker) edges.push_back({out.edgelist[2 * e], out.edgelist[2 * e + 1], marker - kFeatureMarker});
    }
    mesh.feature_edges.resize(Eigen::Index(edges.size()), 2);
    mesh.edge_tags.resize(Eigen::Index(edges.size()));
    for (size_t e = 0; e < edges.size(); ++e) {
        mesh.feature_edges.row(Eigen::Index(e)) << edges[e][0], edges[e][1];
        mesh.edge_tags(Eigen::Index(e)) = edges[e][2];
    }
}

}  // namespace

TetMesh tet_mesh_from_tetgen(const tetgenio& out, const SurfaceMesh& surface) {
    TetMesh mesh;
    copy_tets(out, mesh);
    copy_boundary(out, mesh);
    copy_feature_edges(out, mesh);
    // TetGen keeps input points first and in order; corners are B-rep vertices of the input.
    mesh.corner_vertices = surface.corner_points;
    for (Eigen::Index c = 0; c < surface.corner_points.rows(); ++c) {
        const int p = surface.corner_points(c);
        FF_ASSERT(p < mesh.num_vertices() && mesh.points.row(p) == surface.points.row(p));
    }
    return mesh;
}

}  // namespace framefix
