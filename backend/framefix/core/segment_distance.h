#pragma once
// Distance from a point to a segment: shared by snapping (vertices near paths) and the gluing of
// curves to ambiguous edges.
#include <algorithm>

#include <Eigen/Core>

namespace framefix {

// Distance from p to segment [a, b] (a point when a == b).
inline double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + s * ab)).norm();
}

}  // namespace framefix
