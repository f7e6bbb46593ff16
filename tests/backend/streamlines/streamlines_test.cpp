// Streamlines in fields whose integral curves are known: a constant (identity) field on the unit
// cube (straight lines along the axes that leave through the opposite face), a rotated field,
// and the stop reasons.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "backend/corrections/cube_frames.h"
#include "framefix/core/error.h"
#include "framefix/frame_field/sh.h"
#include "framefix/streamlines/streamlines.h"

namespace framefix {
namespace {

double distance_to_line(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& dir) {
    const Eigen::Vector3d d = p - a;
    return (d - d.dot(dir) * dir).norm();
}

TEST(TetLocator, FindsPointsInsideAndRejectsOutside) {
    const test::Cube c = test::cube_tets(4);
    const TetLocator locator(c.mesh, c.topo);
    const Eigen::Vector3d p(0.3, 0.6, 0.7);
    const TetLocation grid = locator.locate(p);
    ASSERT_GE(grid.tet, 0);
    EXPECT_GT(grid.bary.minCoeff(), -1e-9);
    EXPECT_NEAR(grid.bary.sum(), 1, 1e-12);
    const TetLocation walked = locator.locate(p, 0);
    EXPECT_GE(walked.tet, 0);
    EXPECT_GT(walked.bary.minCoeff(), -1e-9);
    EXPECT_EQ(locator.locate(Eigen::Vector3d(1.2, 0.5, 0.5)).tet, -1);
    EXPECT_EQ(locator.locate(Eigen::Vector3d(1.2, 0.5, 0.5), grid.tet).tet, -1);
}

TEST(Streamlines, ConstantFieldGivesStraightLinesThatLeaveTheCube) {
    const test::Cube c = test::cube_tets(5);
    const TetLocator locator(c.mesh, c.topo);
    const Eigen::Vector3d seed(0.31, 0.42, 0.53);
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            const Eigen::Vector3d dir = sign * Eigen::Vector3d::Unit(axis);
            const Streamline s = trace_streamline(c.mesh, c.field, locator, seed, dir);
            EXPECT_EQ(s.reason, StopReason::LeftSolid);
            ASSERT_GE(s.points.rows(), 3);
            double off = 0;
            for (int i = 0; i < s.points.rows(); ++i) off = std::max(off, distance_to_line(s.points.row(i).transpose(), seed, dir));
            EXPECT_LT(off, 1e-9) << "axis " << axis;
            // Clipped onto the face it leaves through.
            const double end = s.points(s.points.rows() - 1, axis);
            EXPECT_NEAR(end, sign > 0 ? 1.0 : 0.0, 1e-4);
            EXPECT_NEAR(s.length, sign > 0 ? 1 - seed[axis] : seed[axis], 1e-4);
        }
}

TEST(Streamlines, FollowsTheAxisClosestToTheStartDirection) {
    const test::Cube c = test::cube_tets(4);
    const TetLocator locator(c.mesh, c.topo);
    // 30 degrees off the x axis: the streamline snaps onto x.
    const Eigen::Vector3d dir(std::cos(0.5), std::sin(0.5), 0);
    const Streamline s = trace_streamline(c.mesh, c.field, locator, Eigen::Vector3d(0.2, 0.5, 0.5), dir);
    EXPECT_EQ(s.reason, StopReason::LeftSolid);
    EXPECT_NEAR(s.points(s.points.rows() - 1, 1), 0.5, 1e-9);
    EXPECT_NEAR(s.points(s.points.rows() - 1, 0), 1.0, 1e-4);
}

TEST(Streamlines, RotatedConstantFieldGivesRotatedLines) {
    test::Cube c = test::cube_tets(4);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (int v = 0; v < c.mesh.num_vertices(); ++v)
        for (int k = 0; k < 3; ++k) c.field.axes.row(v).segment<3>(3 * k) = R.col(k).transpose();
    const TetLocator locator(c.mesh, c.topo);
    const Eigen::Vector3d seed(0.5, 0.5, 0.5);
    const Streamline s = trace_streamline(c.mesh, c.field, locator, seed, R.col(2));
    EXPECT_EQ(s.reason, StopReason::LeftSolid);
    for (int i = 0; i < s.points.rows(); ++i) EXPECT_LT(distance_to_line(s.points.row(i).transpose(), seed, R.col(2)), 1e-9);
}

TEST(Streamlines, StopReasons) {
    const test::Cube c = test::cube_tets(4);
    const TetLocator locator(c.mesh, c.topo);
    TraceOptions o;
    EXPECT_EQ(trace_streamline(c.mesh, c.field, locator, Eigen::Vector3d(2, 0, 0), Eigen::Vector3d::UnitX(), o).reason,
              StopReason::StartOutside);

    o.max_steps = 3;
    EXPECT_EQ(trace_streamline(c.mesh, c.field, locator, Eigen::Vector3d(0.1, 0.5, 0.5), Eigen::Vector3d::UnitX(), o).reason,
              StopReason::MaxSteps);

    o = TraceOptions{};
    o.max_length = 0.2;
    const Streamline cycle = trace_streamline(c.mesh, c.field, locator, Eigen::Vector3d(0.1, 0.5, 0.5), Eigen::Vector3d::UnitX(), o);
    EXPECT_EQ(cycle.reason, StopReason::LimitCycle);
    EXPECT_LT(cycle.length, 0.2 + 0.2);

    o = TraceOptions{};
    o.singular_points.resize(1, 3);
    o.singular_points << 0.7, 0.5, 0.5;  // a singular curve point on the way
    o.stop_distance = 0.1;
    const Streamline sing = trace_streamline(c.mesh, c.field, locator, Eigen::Vector3d(0.1, 0.5, 0.5), Eigen::Vector3d::UnitX(), o);
    EXPECT_EQ(sing.reason, StopReason::ReachedSingularity);
    EXPECT_NEAR(sing.points(sing.points.rows() - 1, 0), 0.7, 1e-12);  // ends ON the curve

    // Axes turned by 40 deg about z beyond x = 0.6: the interpolated direction turns within about
    // one tet, i.e. by > 10 deg per step (a singularity-like kink) but < 45 deg per step.
    test::Cube turned = test::cube_tets(4);
    const double a = 40 * M_PI / 180;
    for (int v = 0; v < turned.mesh.num_vertices(); ++v)
        if (turned.mesh.points(v, 0) > 0.6)
            turned.field.axes.row(v) << std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1;
    const TetLocator locator2(turned.mesh, turned.topo);
    o = TraceOptions{};
    o.max_turn_deg = 10;
    const Eigen::Vector3d start(0.1, 0.5, 0.5);
    EXPECT_EQ(trace_streamline(turned.mesh, turned.field, locator2, start, Eigen::Vector3d::UnitX(), o).reason,
              StopReason::SharpTurn);
    EXPECT_EQ(trace_streamline(turned.mesh, turned.field, locator2, start, Eigen::Vector3d::UnitX()).reason,
              StopReason::LeftSolid);
}

// start_picks_axis: 46 degrees off the x axis (more than max_turn_deg) the streamline still runs
// along x to the boundary; without it the start counts as a sharp turn.
TEST(Streamlines, StartDirectionPicksTheNearestAxis) {
    const test::Cube c = test::cube_tets(4);
    const TetLocator locator(c.mesh, c.topo);
    const Eigen::Vector3d off = Eigen::Vector3d(1, 1, 0.3).normalized(), start(0.1, 0.4, 0.5);
    TraceOptions o;
    ASSERT_GT(std::acos(off.x()) * 180 / M_PI, o.max_turn_deg);
    EXPECT_EQ(trace_streamline(c.mesh, c.field, locator, start, off, o).reason, StopReason::SharpTurn);
    o.start_picks_axis = true;
    const Streamline s = trace_streamline(c.mesh, c.field, locator, start, off, o);
    EXPECT_EQ(s.reason, StopReason::LeftSolid);
    EXPECT_NEAR(s.points(s.points.rows() - 1, 0), 1.0, 1e-4);
    EXPECT_NEAR(s.points(s.points.rows() - 1, 1), 0.4, 1e-9);
}

TEST(Streamlines, ManyInParallelMatchOneByOne) {
    const test::Cube c = test::cube_tets(4);
    const TetLocator locator(c.mesh, c.topo);
    Points seeds(3, 3), dirs(3, 3);
    seeds << 0.2, 0.3, 0.4, 0.5, 0.5, 0.5, 0.9, 0.1, 0.2;
    dirs << 1, 0, 0, 0, -1, 0, 0, 0, 1;
    const std::vector<Streamline> all = trace_streamlines(c.mesh, c.field, locator, seeds, dirs);
    ASSERT_EQ(all.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const Streamline one = trace_streamline(c.mesh, c.field, locator, seeds.row(i).transpose(), dirs.row(i).transpose());
        EXPECT_EQ(all[i].reason, one.reason);
        EXPECT_TRUE(all[i].points.isApprox(one.points));
    }
}

TEST(Streamlines, RejectsAFieldOfAnotherMesh) {
    const test::Cube c = test::cube_tets(3), d = test::cube_tets(2);
    const TetLocator locator(c.mesh, c.topo);
    EXPECT_THROW(trace_streamline(c.mesh, d.field, locator, Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d::UnitX()), Error);
}

}  // namespace
}  // namespace framefix
