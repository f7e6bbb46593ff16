#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "framefix/frame_field/projection.h"
#include "framefix/frame_field/sh.h"

namespace framefix {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

Eigen::Matrix3d axis_rotation(int axis, double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

TEST(Sh, ReferenceFrameIsTheCubeOfTheIdentity) {
    const SH9 f = reference_frame();
    EXPECT_NEAR(f.norm(), 1.0, 1e-15);
    EXPECT_LT((frame_from_rotation(Eigen::Matrix3d::Identity()) - f).norm(), 1e-14);
}

TEST(Sh, OctahedralInvariance) {
    const auto& group = octahedral_group();
    EXPECT_TRUE(group[0].isIdentity());
    for (const Eigen::Matrix3d& g : group) {
        EXPECT_NEAR(g.determinant(), 1.0, 1e-15);
        EXPECT_LT((sh_rotation(g) * reference_frame() - reference_frame()).norm(), 1e-13);
    }
    // 45 deg is not a symmetry of the cube.
    EXPECT_GT((sh_rotation(axis_rotation(2, M_PI / 4)) * reference_frame() - reference_frame()).norm(), 0.5);
}

TEST(Sh, RotationIsAnOrthogonalHomomorphism) {
    std::mt19937 rng(3);
    for (int i = 0; i < 50; ++i) {
        const Eigen::Matrix3d R1 = random_rotation(rng), R2 = random_rotation(rng);
        const Mat9 D1 = sh_rotation(R1), D2 = sh_rotation(R2);
        EXPECT_LT((sh_rotation(R1 * R2) - D1 * D2).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((D1 * D1.transpose() - Mat9::Identity()).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((D1 * reference_frame() - frame_from_rotation(R1)).norm(), 1e-12);
    }
}

TEST(Sh, ZyzHandlesGimbalLock) {
    // b = 0 and b = pi, exactly and nearly: D(R) must still match the cheap frame vector and
    // act on rotated SH functions correctly (checked through the homomorphism with Rz).
    for (double b : {0.0, 1e-9, 1e-5, M_PI, M_PI - 1e-9, M_PI - 1e-5}) {
        const Eigen::Matrix3d R = axis_rotation(2, 0.7) * axis_rotation(1, b) * axis_rotation(2, -1.9);
        EXPECT_LT((sh_rotation(R) * reference_frame() - frame_from_rotation(R)).norm(), 1e-12) << b;
        EXPECT_LT((sh_rotation(R) - sh_rotation_z(0.7) * sh_rotation(axis_rotation(1, b)) * sh_rotation_z(-1.9))
                      .cwiseAbs().maxCoeff(), 1e-11) << b;
    }
}

TEST(Sh, ClosedFormZAndX90MatchTheRotations) {
    // D(R) maps the coefficients of f to those of s -> f(R^T s): check on point values.
    std::mt19937 rng(5);
    std::normal_distribution<double> n;
    SH9 f;
    for (int i = 0; i < 9; ++i) f(i) = n(rng);
    for (int k = 0; k < 20; ++k) {
        const Eigen::Vector3d s = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
        const Eigen::Matrix3d Rz = axis_rotation(2, 0.37), Rx = axis_rotation(0, M_PI / 2);
        EXPECT_NEAR(sh_basis(s).dot(sh_rotation_z(0.37) * f), sh_basis(Rz.transpose() * s).dot(f), 1e-12);
        EXPECT_NEAR(sh_basis(s).dot(sh_rotation_x90() * f), sh_basis(Rx.transpose() * s).dot(f), 1e-12);
    }
    // A few entries of X90 from a numerical derivation, independent of the closed form in sh.cpp.
    const Mat9& X = sh_rotation_x90();
    EXPECT_NEAR(X(4, 8), 0.7395099728874516, 1e-12);
    EXPECT_NEAR(X(6, 6), 0.5, 1e-12);
    EXPECT_NEAR(X(1, 1), -0.75, 1e-12);
    EXPECT_NEAR(X(0, 5), 0.9354143466934842, 1e-12);
}

TEST(Sh, GeneratorsAreTheDerivativesOfTheRotations) {
    const double eps = 1e-6;
    for (int axis = 0; axis < 3; ++axis) {
        const Mat9 fd = (sh_rotation(axis_rotation(axis, eps)) - sh_rotation(axis_rotation(axis, -eps))) / (2 * eps);
        EXPECT_LT((fd - sh_generator(axis)).cwiseAbs().maxCoeff(), 1e-8) << axis;
        EXPECT_LT((sh_generator(axis) + sh_generator(axis).transpose()).cwiseAbs().maxCoeff(), 1e-15);
    }
    // Entries of L from finite differences of sampled rotations.
    EXPECT_NEAR(sh_generator(0)(0, 7), -1.41421356237381, 1e-9);
    EXPECT_NEAR(sh_generator(0)(3, 4), -3.1622776601475406, 1e-9);
    EXPECT_NEAR(sh_generator(1)(4, 5), -3.1622776601503357, 1e-9);
    EXPECT_NEAR(sh_generator(2)(0, 8), 4.0, 1e-9);
}

TEST(Sh, NormalAlignedFamilyHasTheNormalAsAxis) {
    std::mt19937 rng(7);
    std::normal_distribution<double> n;
    for (int i = 0; i < 30; ++i) {
        const Eigen::Vector3d normal = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
        const NormalAligned fam = normal_aligned(normal);
        EXPECT_LT((fam.P.transpose() * fam.P - Eigen::Matrix2d::Identity()).norm(), 1e-12);
        EXPECT_NEAR(fam.c.norm(), std::sqrt(7.0 / 12.0), 1e-12);
        const double theta = n(rng);
        const Eigen::Vector2d y = std::sqrt(5.0 / 12.0) * Eigen::Vector2d(std::sin(4 * theta), std::cos(4 * theta));
        const SH9 q = fam.c + fam.P * y;
        const Eigen::Matrix3d R = normal_aligned_rotation(fam, y);
        EXPECT_LT((frame_from_rotation(R) - q).norm(), 1e-12);
        EXPECT_LT((R.col(2) - normal).norm(), 1e-12);
        const ProjectedFrame p = project_frame(q);
        EXPECT_LT(p.distance, 1e-8);
        EXPECT_NEAR(closest_direction(normal, p.rotation).dot(normal), 1.0, 1e-8);
    }
}

TEST(Sh, FeatureAndCornerFrames) {
    const Eigen::Vector3d t(0, 0, 1), n1(1, 0, 0), n2(0, 1, 0);
    const Eigen::Matrix3d F = feature_frame(t, n1, n2);
    Eigen::Matrix3d expected;
    expected << t, n1, n2;
    EXPECT_LT((F - expected).norm(), 1e-12);  // 90 deg: exactly (t, n1, n2)
    // 100 deg dihedral: the 10 deg error is split 5/5.
    const Eigen::Vector3d n2b(std::cos(100 * M_PI / 180), std::sin(100 * M_PI / 180), 0);
    const Eigen::Matrix3d G = feature_frame(t, n1, n2b);
    EXPECT_NEAR(std::acos(std::abs(G.col(1).dot(n1))) * 180 / M_PI, 5.0, 1e-9);
    // Imprinted curve (180 deg): (t, n, t x n).
    const Eigen::Matrix3d H = feature_frame(t, n1, n1);
    EXPECT_LT((H.col(1) - n1).norm(), 1e-12);
    // A corner whose normals are a left-handed triple still gives the axis frame.
    const Eigen::Matrix3d C = corner_frame(Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1));
    EXPECT_NEAR(C.determinant(), 1.0, 1e-12);
    EXPECT_LT((frame_from_rotation(C) - reference_frame()).norm(), 1e-12);
}

}  // namespace
}  // namespace framefix
