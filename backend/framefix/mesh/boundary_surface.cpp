#include "framefix/mesh/boundary_surface.h"

namespace framefix {

BoundarySurface boundary_surface(const TetMesh& mesh) {
    BoundarySurface b;
    std::vector<int> index(size_t(mesh.num_vertices()), -1);
    auto take = [&](int v) {
        if (index[size_t(v)] < 0) index[size_t(v)] = int(b.vertex.size()), b.vertex.push_back(v);
        return index[size_t(v)];
    };
    SurfaceMesh& s = b.surface;
    s.corner_points.resize(mesh.corner_vertices.rows());
    for (Eigen::Index c = 0; c < mesh.corner_vertices.rows(); ++c) s.corner_points(c) = take(mesh.corner_vertices(c));
    s.triangles.resize(mesh.boundary_faces.rows(), 3);
    for (Eigen::Index f = 0; f < mesh.boundary_faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) s.triangles(f, k) = take(mesh.boundary_faces(f, k));
    s.face_tags = mesh.face_tags;
    s.feature_segments.resize(mesh.feature_edges.rows(), 2);
    for (Eigen::Index e = 0; e < mesh.feature_edges.rows(); ++e)
        for (int k = 0; k < 2; ++k) s.feature_segments(e, k) = take(mesh.feature_edges(e, k));
    s.segment_tags = mesh.edge_tags;
    s.points.resize(Eigen::Index(b.vertex.size()), 3);
    for (size_t i = 0; i < b.vertex.size(); ++i) s.points.row(Eigen::Index(i)) = mesh.points.row(b.vertex[i]);
    return b;
}

}  // namespace framefix
