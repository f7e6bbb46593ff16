#pragma once
// The 24 rotations of the cube (signed permutation matrices, det +1) as small integers, with the
// products, inverses and rotation classes that holonomy needs. Kept inside singularities/ so the
// per-edge transport is a table lookup instead of 3x3 products (O(#faces) holonomy).
#include <array>

#include <Eigen/Core>

namespace framefix::cube {

constexpr int kOrder = 24;

// Element g as a matrix: g(col_row[j], j) = col_sign[j] for column j = 0..2, zeros elsewhere.
struct Element {
    std::array<int, 3> col_row;
    std::array<int, 3> col_sign;
};

const std::array<Element, kOrder>& elements();  // fixed order; index 0 is the identity
Eigen::Matrix3d matrix(int g);
int multiply(int a, int b);                     // index of a * b
int inverse(int g);
int trace(int g);                               // 3 identity, 1 (90 deg), 0 (120 deg), -1 (180 deg)
Eigen::Vector3d axis(int g);                    // unit rotation axis with angle in (0, pi]; 0 for identity

// g maximising trace(Ra^T Rb g): Rb * g is the representative of frame b closest to frame a.
// Exact argmax over the 24 elements (the first maximum in index order, so deterministic).
// `cos_angle` receives (trace - 1) / 2 of the remaining rotation Ra^T Rb g.
int match(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb, double* cos_angle = nullptr);

}  // namespace framefix::cube
