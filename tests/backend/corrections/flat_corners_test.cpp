// Flat corners: Dirichlet frames turned by 45 deg about a feature curve under a valence-5 run.
#include <gtest/gtest.h>

#include <cmath>

#include "framefix/corrections/flat_corners.h"
#include "framefix/frame_field/projection.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

// The tag of the cube edge along x at y = z = 0.
int x_edge_tag(const test::Cube& c) {
    for (int e = 0; e < c.mesh.feature_edges.rows(); ++e) {
        const Eigen::Vector3d a = c.point(c.mesh.feature_edges(e, 0)), b = c.point(c.mesh.feature_edges(e, 1));
        if (a.y() == 0 && a.z() == 0 && b.y() == 0 && b.z() == 0) return c.mesh.edge_tags(e);
    }
    return -1;
}

// True when one column of R is along u (up to sign).
bool has_axis(const Eigen::Matrix3d& R, const Eigen::Vector3d& u) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(std::abs(R.col(k).dot(u.normalized())) - 1) < 1e-9) return true;
    return false;
}

TEST(FlatCorners, VerticesUnderTheRunTurnAboutTheEdgeAndItsCornersKeepTheirFrames) {
    const test::Cube c = test::cube_tets(4);
    const int tag = x_edge_tag(c);
    ASSERT_GT(tag, 0);
    EdgeRun run{tag, Points(2, 3)};
    run.points << 0.25, 0, 0, 0.75, 0, 0;
    const FlatCorners f = flat_corner_constraints(c.mesh, c.features, c.constraints, {run});
    EXPECT_EQ(f.turned_vertices, 3);  // x = 0.25, 0.5, 0.75
    for (int i = 1; i <= 3; ++i) {
        const Eigen::Matrix3d R = project_frame(f.constraints.fixed.row(c.vertex(i, 0, 0)).transpose()).rotation;
        EXPECT_TRUE(has_axis(R, Eigen::Vector3d::UnitX()));
        EXPECT_TRUE(has_axis(R, Eigen::Vector3d(0, 1, 1)));  // the bisector of the two faces
    }
    for (int v : {c.vertex(0, 0, 0), c.vertex(4, 0, 0), c.vertex(2, 4, 0), c.vertex(0, 2, 0)})
        EXPECT_EQ(f.constraints.fixed.row(v), c.constraints.fixed.row(v));
}

TEST(FlatCorners, ARunOnAnotherEdgeOrNoRunChangesNothing) {
    const test::Cube c = test::cube_tets(4);
    EdgeRun run{x_edge_tag(c) + 1000, Points(2, 3)};
    run.points << 0.25, 0, 0, 0.75, 0, 0;
    EXPECT_EQ(flat_corner_constraints(c.mesh, c.features, c.constraints, {run}).turned_vertices, 0);
    const FlatCorners none = flat_corner_constraints(c.mesh, c.features, c.constraints, {});
    EXPECT_EQ(none.turned_vertices, 0);
    EXPECT_EQ(none.constraints.fixed, c.constraints.fixed);
}

}  // namespace
}  // namespace framefix
