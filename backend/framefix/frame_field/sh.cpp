// Band-4 SH basis, generators and closed-form rotations (docs/algorithms.md#frames-as-spherical-harmonics), checked
// against an independent numerical derivation by tests/backend/frame_field/test_sh.cpp.
#include "framefix/frame_field/sh.h"

#include <algorithm>
#include <cmath>

namespace framefix {
namespace {

const double kPi = 3.14159265358979323846;

struct Entry {
    int i, j;
    double v;
};

// Upper-triangle non-zeros of Lx, Ly, Lz, the generators of D(R); L[j][i] = -L[i][j].
Mat9 antisymmetric(std::initializer_list<Entry> upper) {
    Mat9 L = Mat9::Zero();
    for (const Entry& e : upper) {
        L(e.i, e.j) = e.v;
        L(e.j, e.i) = -e.v;
    }
    return L;
}

std::array<Mat9, 3> make_generators() {
    const double s2 = std::sqrt(2.0), s72 = std::sqrt(3.5), s92 = 3.0 / std::sqrt(2.0), s10 = std::sqrt(10.0);
    return {antisymmetric({{0, 7, -s2}, {1, 6, -s72}, {1, 8, -s2}, {2, 5, -s92}, {2, 7, -s72}, {3, 4, -s10}, {3, 6, -s92}}),
            antisymmetric({{0, 1, s2}, {1, 2, s72}, {2, 3, s92}, {4, 5, -s10}, {5, 6, -s92}, {6, 7, -s72}, {7, 8, -s2}}),
            antisymmetric({{0, 8, 4.0}, {1, 7, 3.0}, {2, 6, 2.0}, {3, 5, 1.0}})};
}

Mat9 make_x90() {
    const double s2 = std::sqrt(2.0), s5 = std::sqrt(5.0), s7 = std::sqrt(7.0), s14 = std::sqrt(14.0),
                 s35 = std::sqrt(35.0);
    Mat9 X = Mat9::Zero();
    X(0, 5) = s14 / 4;  X(0, 7) = -s2 / 4;
    X(1, 1) = -0.75;    X(1, 3) = s7 / 4;
    X(2, 5) = s2 / 4;   X(2, 7) = s14 / 4;
    X(3, 1) = s7 / 4;   X(3, 3) = 0.75;
    X(4, 4) = 3.0 / 8;  X(4, 6) = s5 / 4;  X(4, 8) = s35 / 8;
    X(5, 0) = -s14 / 4; X(5, 2) = -s2 / 4;
    X(6, 4) = s5 / 4;   X(6, 6) = 0.5;     X(6, 8) = -s7 / 4;
    X(7, 0) = s2 / 4;   X(7, 2) = -s14 / 4;
    X(8, 4) = s35 / 8;  X(8, 6) = -s7 / 4; X(8, 8) = 1.0 / 8;
    return X;
}

// 1 / |sum_k Y4(e_k)|: makes C0 * sum_k Y4(R e_k) the unit vector D(R) f_ref (exact).
double frame_scale() {
    const SH9 s = sh_basis(Eigen::Vector3d::UnitX()) + sh_basis(Eigen::Vector3d::UnitY()) +
                  sh_basis(Eigen::Vector3d::UnitZ());
    return 1.0 / s.norm();
}

// D(R) = Z(a) X90^T Z(b) X90 Z(c) for R = rot_z(a) rot_y(b) rot_z(c).
Mat9 zyz(double a, double b, double c) {
    const Mat9& X = sh_rotation_x90();
    return sh_rotation_z(a) * X.transpose() * sh_rotation_z(b) * X * sh_rotation_z(c);
}

}  // namespace

SH9 reference_frame() {
    SH9 f = SH9::Zero();
    f(4) = std::sqrt(7.0 / 12.0);
    f(8) = std::sqrt(5.0 / 12.0);
    return f;
}

const Mat9& sh_generator(int axis) {
    static const std::array<Mat9, 3> L = make_generators();
    return L.at(axis);
}

Mat9 sh_rotation_z(double angle) {
    Mat9 Z = Mat9::Zero();
    Z(4, 4) = 1;
    for (int m = 1; m <= 4; ++m) {
        const int i = 4 - m, j = 4 + m;
        const double c = std::cos(m * angle), s = std::sin(m * angle);
        Z(i, i) = c;
        Z(i, j) = s;
        Z(j, i) = -s;
        Z(j, j) = c;
    }
    return Z;
}

const Mat9& sh_rotation_x90() {
    static const Mat9 X = make_x90();
    return X;
}

Mat9 sh_rotation(const Eigen::Matrix3d& R) {
    // ZYZ angles of R = rot_z(a) rot_y(b) rot_z(c) without a gimbal-lock branch. With s = a + c,
    // d = a - c the entries give each of s, d twice, at different scales:
    //   R00 + R11 = (1 + cos b) cos s,   R10 - R01 = (1 + cos b) sin s,
    //   R11 - R00 = (1 - cos b) cos d,   -(R10 + R01) = (1 - cos b) sin d,
    //   (R02, R12) = sin b (cos a, sin a),   (-R20, R21) = sin b (cos c, sin c).
    // Taking each from its larger-scale entries bounds the error of D(R) by a few ulps for every
    // b, including b = 0 and b = pi where the Euler angles themselves are undefined.
    const double cb = std::clamp(R(2, 2), -1.0, 1.0);
    const double sb = std::hypot(R(0, 2), R(1, 2));
    const double b = std::atan2(sb, cb);  // in [0, pi]
    const double a_side = std::atan2(R(1, 2), R(0, 2)), c_side = std::atan2(R(2, 1), -R(2, 0));
    const double s = 1 + cb >= sb ? std::atan2(R(1, 0) - R(0, 1), R(0, 0) + R(1, 1)) : a_side + c_side;
    const double d = 1 - cb >= sb ? std::atan2(-(R(1, 0) + R(0, 1)), R(1, 1) - R(0, 0)) : a_side - c_side;
    const double a = 0.5 * (s + d), c = 0.5 * (s - d);
    // (a, c) from (s, d) are known modulo (pi, pi), which is rot_y(-b): R02 = cos a sin b, R12 = sin a sin b.
    const double sign = std::cos(a) * R(0, 2) + std::sin(a) * R(1, 2) < 0 ? -1.0 : 1.0;
    return zyz(a, sign * b, c);
}

SH9 sh_basis(const Eigen::Vector3d& p) {
    static const double k0 = 0.75 * std::sqrt(35.0 / kPi), k1 = 0.75 * std::sqrt(35.0 / (2 * kPi)),
                        k2 = 0.75 * std::sqrt(5.0 / kPi), k3 = 0.75 * std::sqrt(5.0 / (2 * kPi)),
                        k4 = 3.0 / 16.0 * std::sqrt(1.0 / kPi), k6 = 3.0 / 8.0 * std::sqrt(5.0 / kPi),
                        k8 = 3.0 / 16.0 * std::sqrt(35.0 / kPi);
    const double x = p.x(), y = p.y(), z = p.z(), x2 = x * x, y2 = y * y, z2 = z * z;
    SH9 Y;
    Y << k0 * x * y * (x2 - y2), k1 * (3 * x2 - y2) * y * z, k2 * x * y * (7 * z2 - 1), k3 * y * z * (7 * z2 - 3),
        k4 * (35 * z2 * z2 - 30 * z2 + 3), k3 * x * z * (7 * z2 - 3), k6 * (x2 - y2) * (7 * z2 - 1),
        k1 * (x2 - 3 * y2) * x * z, k8 * (x2 * (x2 - 3 * y2) - y2 * (3 * x2 - y2));
    return Y;
}

SH9 frame_from_rotation(const Eigen::Matrix3d& R) {
    static const double c0 = frame_scale();
    return c0 * (sh_basis(R.col(0)) + sh_basis(R.col(1)) + sh_basis(R.col(2)));
}

NormalAligned normal_aligned(const Eigen::Vector3d& n) {
    const Eigen::Vector3d z = n.normalized();
    // Any rotation taking e_z to n: its angle about n only rotates y = (a, b) of c + P y.
    const Eigen::Vector3d helper = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = z.cross(helper).normalized();
    Eigen::Matrix3d Rn;
    Rn << u, z.cross(u), z;
    const Mat9 B = sh_rotation(Rn);
    NormalAligned out;
    out.c = std::sqrt(7.0 / 12.0) * B.col(4);
    out.P << B.col(0), B.col(8);
    out.R = Rn;
    return out;
}

Eigen::Matrix3d normal_aligned_rotation(const NormalAligned& family, const Eigen::Vector2d& y) {
    // (a, b) = sqrt(5/12) (sin 4 theta, cos 4 theta) is the frame R_n rot_z(theta).
    const double theta = 0.25 * std::atan2(y(0), y(1));
    return family.R * Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

const std::array<Eigen::Matrix3d, 24>& octahedral_group() {
    static const std::array<Eigen::Matrix3d, 24> group = [] {
        std::array<Eigen::Matrix3d, 24> g;
        const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        int n = 0;
        for (const auto& p : perms)
            for (int signs = 0; signs < 8; ++signs) {
                Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
                for (int i = 0; i < 3; ++i) M(i, p[i]) = (signs >> i) & 1 ? -1.0 : 1.0;
                if (M.determinant() > 0) g[n++] = M;  // the identity comes first
            }
        return g;
    }();
    return group;
}

}  // namespace framefix
