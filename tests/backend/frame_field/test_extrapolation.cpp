// FloorExtrapolation on iterations whose limit is known: steps q_k = r^k v shrink towards the
// constant field 0, whose Dirichlet energy is 0, while v (the x coordinate in one channel) has
// energy > 0. The projector is the identity, so only the jump rule is tested.
#include <gtest/gtest.h>

#include "backend/mesh/cube_fixture.h"
#include "framefix/frame_field/extrapolation.h"

namespace framefix {
namespace {

struct Drift {
    testing::Fixture fx = testing::cube_tets(4);
    P1System sys = assemble_p1(fx.mesh, build_topology(fx.mesh), 1);
    std::vector<Eigen::Matrix3d> R = std::vector<Eigen::Matrix3d>(fx.mesh.num_vertices(), Eigen::Matrix3d::Identity());
    FloorExtrapolation ex{sys, [](FrameCoefficients&, std::vector<Eigen::Matrix3d>&, const std::vector<int>&) {}, 1};

    FrameCoefficients channel(int c) const {  // the x coordinate in channel c
        FrameCoefficients f = FrameCoefficients::Zero(fx.mesh.num_vertices(), 9);
        for (int v = 0; v < f.rows(); ++v) f(v, c) = fx.mesh.points(v, 0);
        return f;
    }
    // Two plain steps a -> b -> c; returns whether the second jumped, with c updated in place.
    bool steps(const FrameCoefficients& a, const FrameCoefficients& b, FrameCoefficients& c) {
        FrameCoefficients b_copy = b;
        EXPECT_FALSE(ex.after_step(a, b_copy, R));  // one step alone never jumps
        EXPECT_TRUE(b_copy == b);
        return ex.after_step(b, c, R);
    }
};

TEST(FloorExtrapolation, GeometricStepsJumpToTheirLimit) {
    Drift s;
    const FrameCoefficients v = s.channel(0);
    FrameCoefficients c = 0.25 * v;  // r = 0.5: the limit is r / (1 - r) = 1 step further
    ASSERT_TRUE(s.steps(v, 0.5 * v, c));
    EXPECT_LT(c.cwiseAbs().maxCoeff(), 1e-12);
}

TEST(FloorExtrapolation, SteadyDriftJumpsAsFarAsTheEnergyFalls) {
    Drift s;
    const FrameCoefficients v = s.channel(0);
    const double r = 0.99;  // Aitken says 99 steps; the doubling 8, 16, 32, 64 all lower the energy
    FrameCoefficients c = r * r * v;
    ASSERT_TRUE(s.steps(v, r * v, c));
    EXPECT_LT((c - (r * r + 64 * (r * r - r)) * v).cwiseAbs().maxCoeff(), 1e-12);
}

// MBO's fixed point is not the energy's minimum: when the step after a jump points back, the
// jump overshot it, and later jumps go at most half as far (here 32 steps instead of 64).
TEST(FloorExtrapolation, AWalkBackHalvesTheNextJump) {
    Drift s;
    const FrameCoefficients v = s.channel(0);
    const double r = 0.99, after = r * r + 64 * (r * r - r);
    FrameCoefficients c = r * r * v;
    ASSERT_TRUE(s.steps(v, r * v, c));
    FrameCoefficients back = (after + 0.01) * v;  // the walk back
    EXPECT_FALSE(s.ex.after_step(c, back, s.R));
    FrameCoefficients d = (after + 0.009) * v;     // turns again: no pair yet
    EXPECT_FALSE(s.ex.after_step(back, d, s.R));
    FrameCoefficients e = (after + 0.008) * v;     // a steady drift of 0.001 v per step
    ASSERT_TRUE(s.ex.after_step(d, e, s.R));
    EXPECT_LT((e - (after + 0.008 - 32 * 0.001) * v).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(FloorExtrapolation, TurningStepsDoNotJump) {
    Drift s;
    const FrameCoefficients v = s.channel(0), u = s.channel(1);  // M-orthogonal steps
    FrameCoefficients c = 0.5 * v + 0.5 * u;
    const FrameCoefficients before = c;
    EXPECT_FALSE(s.steps(v + u, 0.5 * v + u, c));
    EXPECT_TRUE(c == before);
}

TEST(FloorExtrapolation, AJumpThatRaisesTheEnergyIsNotTaken) {
    Drift s;
    const FrameCoefficients v = s.channel(0);
    FrameCoefficients c = 0.7 * v;  // steps away from the minimum
    EXPECT_FALSE(s.steps(0.5 * v, 0.6 * v, c));
    EXPECT_TRUE(c == 0.7 * v);
}

}  // namespace
}  // namespace framefix
