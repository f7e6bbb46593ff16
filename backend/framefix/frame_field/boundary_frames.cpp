// Dirichlet frames of feature-curve vertices and corners (docs/algorithms.md#feature-and-corner-frames).
#include <cmath>

#include <Eigen/SVD>

#include "framefix/core/error.h"
#include "framefix/frame_field/sh.h"

namespace framefix {

Eigen::Matrix3d feature_frame(const Eigen::Vector3d& tangent, const Eigen::Vector3d& n1, const Eigen::Vector3d& n2) {
    const Eigen::Vector3d t = tangent.normalized();
    Eigen::Vector3d u = n1 - n1.dot(t) * t;
    if (u.norm() < 1e-12) throw Error("constraints", "feature frame: the face normal is parallel to the curve tangent");
    u.normalize();
    const Eigen::Vector3d w = t.cross(u);
    // Angles of the normals around t, averaged modulo 90 deg (frames are invariant under 90 deg
    // turns): a 90 or 270 deg dihedral gives exactly (t, n1, n2), 100 deg splits the error 5/5.
    const double phi2 = std::atan2(n2.dot(w), n2.dot(u));
    const double phi = 0.25 * std::atan2(std::sin(4 * phi2), 1.0 + std::cos(4 * phi2));
    const Eigen::Vector3d a2 = std::cos(phi) * u + std::sin(phi) * w;
    Eigen::Matrix3d R;
    R << t, a2, t.cross(a2);
    return R;
}

Eigen::Matrix3d corner_frame(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2, const Eigen::Vector3d& n3) {
    Eigen::Matrix3d A;
    A << n1.normalized(), n2.normalized(), n3.normalized();
    // Frame axes carry no sign: a left-handed triple of normals is as good as its mirror.
    if (A.determinant() < 0) A.col(2) = -A.col(2);
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d U = svd.matrixU();
    const Eigen::Matrix3d V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0) U.col(2) = -U.col(2);  // only for a degenerate (flat) A
    return U * V.transpose();
}

}  // namespace framefix
