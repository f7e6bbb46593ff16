#pragma once
// Frames as band-4 real spherical harmonics (docs/algorithms.md#frames-as-spherical-harmonics). A frame is a rotation R modulo
// the 24 rotations of the cube group; its 9-vector is q = D(R) f_ref, unit norm. Index i = 0..8
// is the SH order m = i - 4.
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace framefix {

using SH9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

SH9 reference_frame();                          // f_ref = (0,0,0,0,sqrt(7/12),0,0,0,sqrt(5/12))
const Mat9& sh_generator(int axis);             // L_x, L_y, L_z (antisymmetric), axis 0..2
Mat9 sh_rotation_z(double angle);               // Z(a) = D(rot_z(a)), closed form
const Mat9& sh_rotation_x90();                  // X90 = D(rot_x(+90 deg))
Mat9 sh_rotation(const Eigen::Matrix3d& R);     // D(R) for any rotation (ZYZ factorisation)
SH9 frame_from_rotation(const Eigen::Matrix3d& R);  // D(R) f_ref (cheap: C0 * sum_k Y4(R e_k))
SH9 sh_basis(const Eigen::Vector3d& s);         // Y_4m(s) for a unit vector s

// The normal-aligned family: q = c + P y with y in R^2, frames with one axis along n.
struct NormalAligned {
    SH9 c;                                 // sqrt(7/12) B_n e4
    Eigen::Matrix<double, 9, 2> P;         // [B_n e0, B_n e8], orthonormal columns
    Eigen::Matrix3d R;                     // R_n: R_n e_z = n, B_n = D(R_n)
};
NormalAligned normal_aligned(const Eigen::Vector3d& n);
// The rotation of the family member q = c + P y (y is rescaled to radius sqrt(5/12) first):
// R_n rot_z(theta) with y = sqrt(5/12) (sin 4 theta, cos 4 theta). Axis 3 of the result is n.
Eigen::Matrix3d normal_aligned_rotation(const NormalAligned& family, const Eigen::Vector2d& y);

// Frame of a feature-curve vertex (docs/algorithms.md#feature-and-corner-frames): axis along t, the others the average modulo 90 deg
// of the two face normals projected orthogonal to t.
Eigen::Matrix3d feature_frame(const Eigen::Vector3d& t, const Eigen::Vector3d& n1, const Eigen::Vector3d& n2);
// Frame of a corner with three surfaces: polar factor of [n1 n2 n3], one column negated if det < 0.
Eigen::Matrix3d corner_frame(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2, const Eigen::Vector3d& n3);

const std::array<Eigen::Matrix3d, 24>& octahedral_group();  // signed permutations, det +1

}  // namespace framefix
