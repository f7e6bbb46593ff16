#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Geometry>

namespace framefix {

double tet_volume(const TetMesh& mesh, int tet) {
    const Eigen::Vector3d p0 = mesh.points.row(mesh.tets(tet, 0));
    const Eigen::Vector3d a = mesh.points.row(mesh.tets(tet, 1)).transpose() - p0;
    const Eigen::Vector3d b = mesh.points.row(mesh.tets(tet, 2)).transpose() - p0;
    const Eigen::Vector3d c = mesh.points.row(mesh.tets(tet, 3)).transpose() - p0;
    return a.dot(b.cross(c)) / 6.0;
}

Eigen::Vector3d tet_centroid(const TetMesh& mesh, int tet) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.points.row(mesh.tets(tet, k)).transpose();
    return c / 4;
}

MeshQuality mesh_quality(const TetMesh& mesh) {
    MeshQuality q;
    if (mesh.num_tets() == 0) return q;
    q.min_volume = tet_volume(mesh, 0);
    for (int t = 0; t < mesh.num_tets(); ++t) q.min_volume = std::min(q.min_volume, tet_volume(mesh, t));
    const Segments edges = build_topology(mesh).edges;
    std::vector<double> len(size_t(edges.rows()));
    int in_range = 0;
    for (size_t e = 0; e < len.size(); ++e) {
        len[e] = (mesh.points.row(edges(int(e), 0)) - mesh.points.row(edges(int(e), 1))).norm();
        in_range += len[e] >= 0.5 * mesh.size && len[e] <= 1.6 * mesh.size;
    }
    q.edges = int(len.size());
    q.edge_fraction_in_range = double(in_range) / double(len.size());
    std::vector<double> sorted = len;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    q.median_edge = sorted[sorted.size() / 2];
    q.min_edge = *std::min_element(len.begin(), len.end());
    q.max_edge = *std::max_element(len.begin(), len.end());
    return q;
}

}  // namespace framefix
