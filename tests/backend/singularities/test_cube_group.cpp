// The cube group tables and the exact fast matching against brute force over the frame_field
// module's octahedral_group() and its match_frame().
#include <gtest/gtest.h>

#include <random>

#include "backend/singularities/fixtures.h"
#include "framefix/frame_field/projection.h"
#include "framefix/singularities/cube_group.h"

namespace framefix {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

TEST(CubeGroup, IdentityFirstAndClosed) {
    EXPECT_TRUE(cube::matrix(0).isIdentity());
    for (int a = 0; a < cube::kOrder; ++a) {
        EXPECT_EQ(cube::multiply(a, cube::inverse(a)), 0);
        for (int b = 0; b < cube::kOrder; ++b)
            EXPECT_TRUE((cube::matrix(cube::multiply(a, b)) - cube::matrix(a) * cube::matrix(b)).isZero());
    }
}

TEST(CubeGroup, RotationClasses) {
    int count[4] = {0, 0, 0, 0};  // trace 3, 1, 0, -1
    for (int g = 0; g < cube::kOrder; ++g) count[cube::trace(g) == 3 ? 0 : cube::trace(g) == 1 ? 1 : cube::trace(g) == 0 ? 2 : 3]++;
    EXPECT_EQ(count[0], 1);  // identity
    EXPECT_EQ(count[1], 6);  // 90 deg about face axes
    EXPECT_EQ(count[2], 8);  // 120 deg about diagonals
    EXPECT_EQ(count[3], 9);  // 180 deg about face and edge axes
}

TEST(CubeGroup, AxisAndPositiveAngle) {
    for (int g = 1; g < cube::kOrder; ++g) {
        const Eigen::Vector3d a = cube::axis(g);
        EXPECT_NEAR(a.norm(), 1, 1e-12);
        const double angle = std::acos(std::clamp((cube::trace(g) - 1) / 2.0, -1.0, 1.0));
        EXPECT_TRUE(cube::matrix(g).isApprox(testing::rot(a, angle), 1e-12)) << g;
    }
}

TEST(CubeGroup, MatchIsTheBruteForceArgmax) {
    std::mt19937 rng(7);
    const auto& O = octahedral_group();
    for (int i = 0; i < 500; ++i) {
        const Eigen::Matrix3d Ra = random_rotation(rng), Rb = random_rotation(rng);
        double best = -1e9;
        Eigen::Matrix3d brute;
        for (const Eigen::Matrix3d& g : O) {
            const double tr = (Ra.transpose() * Rb * g).trace();
            if (tr > best) best = tr, brute = Rb * g;
        }
        double c = 0;
        const Eigen::Matrix3d ours = Rb * cube::matrix(cube::match(Ra, Rb, &c));
        EXPECT_TRUE(ours.isApprox(brute, 1e-12));
        EXPECT_NEAR(c, (best - 1) / 2, 1e-12);
        EXPECT_TRUE(ours.isApprox(match_frame(Ra, Rb), 1e-9));
    }
}

TEST(CubeGroup, MatchIsEquivariant) {
    // match(Ra h, Rb) = match(Ra, Rb) h: what makes per-edge transports compose into holonomies.
    std::mt19937 rng(11);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Matrix3d Ra = random_rotation(rng), Rb = random_rotation(rng);
        const int h = i % cube::kOrder;
        EXPECT_EQ(cube::match(Ra * cube::matrix(h), Rb), cube::multiply(cube::match(Ra, Rb), h));
    }
}

}  // namespace
}  // namespace framefix
