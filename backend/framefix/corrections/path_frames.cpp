// 45 deg Dirichlet frames along snapped paths.
#include "framefix/corrections/path_frames.h"

#include <algorithm>
#include <cmath>

#include "framefix/core/error.h"

namespace framefix {

namespace {

// Any unit vector orthogonal to n (only reached for degenerate chords).
Eigen::Vector3d some_orthogonal(const Eigen::Vector3d& n) {
    const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return n.cross(a).normalized();
}

}  // namespace

std::vector<Eigen::Matrix3d> path_frames(const Points& points, const BoundaryGraph& graph, const std::vector<int>& path,
                                         double angle_deg, int tangent_half_width) {
    const int n = int(path.size());
    FF_ASSERT(n >= 2);
    const int w = std::max(1, tangent_half_width);
    const double angle = angle_deg * M_PI / 180.0;
    std::vector<Eigen::Matrix3d> frames(n);
    for (int k = 0; k < n; ++k) {
        // A feature vertex's averaged normal mixes two faces: use the neighbour's on the path.
        int normal_vertex = path[k];
        if (graph.is_feature[normal_vertex] && (k == 0 || k == n - 1)) normal_vertex = path[k == 0 ? 1 : n - 2];
        Eigen::Vector3d normal = graph.normal.row(normal_vertex).transpose();
        if (normal.squaredNorm() < 0.5) normal = graph.normal.row(path[k]).transpose();
        FF_ASSERT(normal.squaredNorm() > 0.5);

        // Raw Dijkstra tangents zig-zag by up to 45 deg; the chord over +-w vertices does not.
        const Eigen::Vector3d chord =
            points.row(path[std::min(k + w, n - 1)]) - points.row(path[std::max(k - w, 0)]);
        Eigen::Vector3d t = chord - chord.dot(normal) * normal;
        t = t.norm() > 1e-12 * (1 + chord.norm()) ? Eigen::Vector3d(t.normalized()) : some_orthogonal(normal);
        Eigen::Vector3d nn = normal - normal.dot(t) * t;
        nn.normalize();

        const Eigen::Vector3d a2 = std::cos(angle) * nn + std::sin(angle) * t.cross(nn);
        frames[k].col(0) = t;
        frames[k].col(1) = a2;
        frames[k].col(2) = t.cross(a2);
    }
    return frames;
}

}  // namespace framefix
