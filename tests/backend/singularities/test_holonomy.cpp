// Per-loop holonomy and the valence sign rule (docs/algorithms.md#valence-sign-rule).
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/singularities/cube_group.h"
#include "framefix/singularities/holonomy.h"

namespace framefix {
namespace {

using testing::kPi;
using testing::rot;

// Frames rot_axis(index * phi) * base at `samples` points on a circle about `axis`, loop order
// counter-clockwise seen from +axis; returns the loop valence.
int circle_valence(const Eigen::Vector3d& axis, double index, const Eigen::Matrix3d& base, bool reversed,
                   Eigen::Vector3d* w = nullptr) {
    const Eigen::Matrix3d A = testing::basis_along(axis);
    std::vector<Eigen::Matrix3d> frames;
    std::vector<Eigen::Vector3d> x;
    for (int k = 0; k < 12; ++k) {
        const double phi = 2 * kPi * k / 12;
        frames.push_back(rot(axis, index * phi) * base);
        x.push_back(A * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0));
    }
    if (reversed) {
        std::reverse(frames.begin() + 1, frames.end());
        std::reverse(x.begin() + 1, x.end());
    }
    const int g = loop_holonomy(frames);
    // Three loop points in loop order give the loop normal.
    return loop_valence(g, frames[0], x[0], x[4], x[8], w);
}

TEST(Holonomy, QuarterIndexIsValence3) {
    EXPECT_EQ(circle_valence(Eigen::Vector3d::UnitZ(), 0.25, Eigen::Matrix3d::Identity(), false), 3);
}

TEST(Holonomy, MinusQuarterIndexIsValence5) {
    EXPECT_EQ(circle_valence(Eigen::Vector3d::UnitZ(), -0.25, Eigen::Matrix3d::Identity(), false), 5);
}

TEST(Holonomy, ValenceDoesNotDependOnLoopOrientation) {
    for (double index : {0.25, -0.25}) {
        Eigen::Vector3d w1, w2;
        const int a = circle_valence(Eigen::Vector3d::UnitZ(), index, Eigen::Matrix3d::Identity(), false, &w1);
        const int b = circle_valence(Eigen::Vector3d::UnitZ(), index, Eigen::Matrix3d::Identity(), true, &w2);
        EXPECT_EQ(a, b);
        EXPECT_TRUE(w1.isApprox(-w2, 1e-12));  // both the axis and the normal flip
    }
}

TEST(Holonomy, ValenceDoesNotDependOnTheLineDirection) {
    // A tilted line whose frames keep one axis along it (base = basis_along(d)).
    const Eigen::Vector3d d = Eigen::Vector3d(0.4, -0.7, 0.2).normalized();
    const Eigen::Matrix3d base = testing::basis_along(d);
    Eigen::Vector3d w;
    EXPECT_EQ(circle_valence(d, 0.25, base, false, &w), 3);
    EXPECT_GT(std::abs(w.dot(d)), 1 - 1e-9);
    EXPECT_EQ(circle_valence(d, -0.25, base, false), 5);
    EXPECT_EQ(circle_valence(d, 0.25, base, true), 3);
}

TEST(Holonomy, HalfIndexIsComplex) {
    EXPECT_EQ(circle_valence(Eigen::Vector3d::UnitZ(), 0.5, Eigen::Matrix3d::Identity(), false), -1);
}

TEST(Holonomy, FullTurnIsRegular) {
    EXPECT_EQ(circle_valence(Eigen::Vector3d::UnitZ(), 1.0, Eigen::Matrix3d::Identity(), false), 0);
}

TEST(Holonomy, EdgeTransportMatchesDirectMatchingForCloseFrames) {
    const Eigen::Matrix3d Ra = rot(Eigen::Vector3d(1, 2, 3), 0.4);
    for (double angle : {0.05, 0.2, 0.5}) {
        const Eigen::Matrix3d Rb = rot(Eigen::Vector3d(-1, 0.5, 2), angle) * Ra * cube::matrix(5);
        const int direct = cube::match(Ra, Rb);
        bool sampled = false;
        EXPECT_EQ(edge_transport(frame_from_rotation(Ra), frame_from_rotation(Rb), Ra, Rb, 0, &sampled), direct);
        EXPECT_TRUE(sampled);
    }
}

TEST(Holonomy, EdgeTransportTakesTheInterpolatedPath) {
    // Frames 60 deg apart about z are -30 deg apart modulo the cube group. The linear
    // interpolation of q runs along the chord of the m = +-4 circle (angle 4 phi), i.e. the short
    // way, so the sampled transport agrees with matching the two ends directly.
    const Eigen::Matrix3d Ra = Eigen::Matrix3d::Identity(), Rb = rot(Eigen::Vector3d::UnitZ(), kPi / 3);
    bool sampled = false;
    EXPECT_EQ(edge_transport(frame_from_rotation(Ra), frame_from_rotation(Rb), Ra, Rb, 20, &sampled),
              cube::match(Ra, Rb));
    EXPECT_TRUE(sampled);
}

}  // namespace
}  // namespace framefix
