#pragma once
// Distances from a point to a segment (snapping: vertices near paths; the gluing of curves to
// ambiguous edges) and to a triangle (the gluing, near chamfer strips).
#include <algorithm>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace framefix {

// Distance from p to segment [a, b] (a point when a == b).
inline double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + s * ab)).norm();
}

// Distance from p to the triangle (a, b, c): to its plane where p projects inside it, else to the
// nearest side. Degenerate triangles fall back to their sides.
inline double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    if (n2 > 0) {
        const Eigen::Vector3d q = p - n * ((p - a).dot(n) / n2);  // projection onto the plane
        const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                            (a - c).cross(q - c).dot(n) >= 0;
        if (inside) return (p - q).norm();
    }
    return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c), point_segment_distance(p, c, a)});
}

}  // namespace framefix
