// Extremities, targets and the fixed point on hand-made singularity graphs in the cube.
#include <gtest/gtest.h>

#include <algorithm>

#include "framefix/corrections/snap_plan.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

using test::curve_between;
using test::node_at;

struct Fixture {
    test::Cube cube = test::cube_tets(8);
    BoundaryGraph boundary = build_boundary_graph(cube.mesh, cube.topo, cube.features, cube.constraints);
};

// Nodes: 0 boundary near the edge y=0,z=0; 1 junction above the face z=0; 2 boundary end within
// 3 hb of node 1's target; 3 boundary end far away near the edge x=1,z=0; 4, 5 an unrelated curve.
SingularityGraph two_chains_sharing_a_node() {
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.03}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.5, 0.2}, false));
    g.nodes.push_back(node_at(2, {0.55, 0.55, 0.0}, true));
    g.nodes.push_back(node_at(3, {0.97, 0.5, 0.02}, true));
    g.nodes.push_back(node_at(4, {0.5, 0.5, 1.0}, true));
    g.nodes.push_back(node_at(5, {0.5, 0.99, 0.9}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive));
    g.curves.push_back(curve_between(1, 1, 2, CurveKind::Valence3, 3));
    g.curves.push_back(curve_between(2, 1, 3, CurveKind::Valence3));
    g.curves.push_back(curve_between(3, 4, 5, CurveKind::Valence3));
    return g;
}

TEST(SnapPlan, SnappingOneChainForcesTheOtherAtTheirSharedNode) {
    Fixture f;
    const SingularityGraph g = two_chains_sharing_a_node();
    const CurveEnds ends = classify_curve_ends(g, 3 * f.boundary.h_mean);
    EXPECT_EQ(ends.node_kind[1], EndKind::Junction);
    const SnapPlan plan = plan_snapping(g, ends, f.boundary, f.cube.mesh.points, SnapOptions{});
    EXPECT_EQ(plan.three_five_curves, 1);
    EXPECT_EQ(plan.curves, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(plan.forced, (std::vector<char>{0, 1, 1}));
    // Boundary end -> nearest feature vertex; interior node -> nearest boundary vertex.
    EXPECT_EQ(plan.node_target[0], f.cube.vertex(4, 0, 0));
    EXPECT_EQ(plan.node_target[1], f.cube.vertex(4, 4, 0));
    EXPECT_EQ(plan.node_target[3], f.cube.vertex(8, 4, 0));
    // The unrelated curve keeps its nodes.
    EXPECT_EQ(plan.node_target[4], -1);
    EXPECT_EQ(plan.node_target[5], -1);
}

// An invalid interior node (three valence-3 curves to the boundary) and no 3-5 curve.
SingularityGraph invalid_junction() {
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.5, 0.3}, false));
    g.nodes[0].valid = false;
    g.nodes.push_back(node_at(1, {0.5, 0.5, 1.0}, true));
    g.nodes.push_back(node_at(2, {0.0, 0.5, 0.3}, true));
    g.nodes.push_back(node_at(3, {1.0, 0.5, 0.3}, true));
    for (int k = 1; k <= 3; ++k) g.curves.push_back(curve_between(k - 1, 0, k, CurveKind::Valence3));
    return g;
}

TEST(SnapPlan, InvalidInteriorNodesAreSnappedOnlyWhenAsked) {
    Fixture f;
    const SingularityGraph g = invalid_junction();
    const CurveEnds ends = classify_curve_ends(g, 3 * f.boundary.h_mean);
    ASSERT_EQ(ends.node_kind[0], EndKind::Junction);
    const SnapPlan off = plan_snapping(g, ends, f.boundary, f.cube.mesh.points, SnapOptions{});
    EXPECT_TRUE(off.curves.empty());
    EXPECT_EQ(off.invalid_nodes, 0);
    SnapOptions on;
    on.snap_invalid_nodes = true;
    const SnapPlan plan = plan_snapping(g, ends, f.boundary, f.cube.mesh.points, on);
    EXPECT_EQ(plan.invalid_nodes, 1);
    EXPECT_EQ(plan.three_five_curves, 0);
    EXPECT_EQ(plan.curves, (std::vector<int>{0, 1, 2}));  // the node's curves, by the fixed point
    EXPECT_EQ(plan.forced, (std::vector<char>{1, 1, 1}));
    EXPECT_EQ(plan.node_target[0], f.cube.vertex(4, 4, 0));  // the nearest boundary vertex: z = 0 below it
}

TEST(SnapPlan, CollapseRuleMapsANearbyBoundaryEndOntoTheSnappedNode) {
    Fixture f;
    const SingularityGraph g = two_chains_sharing_a_node();
    const SnapPlan plan = plan_snapping(g, classify_curve_ends(g, 3 * f.boundary.h_mean), f.boundary,
                                        f.cube.mesh.points, SnapOptions{});
    EXPECT_EQ(plan.collapsed_ends, 1);
    EXPECT_EQ(plan.node_target[2], plan.node_target[1]);
    EXPECT_EQ(plan.targets[1][0], plan.targets[1][1]);  // curve 1 becomes a single vertex: no path
    SnapOptions literal;
    literal.collapse_radius_hb = 0;
    const SnapPlan plan2 = plan_snapping(g, classify_curve_ends(g, 3 * f.boundary.h_mean), f.boundary,
                                         f.cube.mesh.points, literal);
    EXPECT_EQ(plan2.collapsed_ends, 0);
    EXPECT_TRUE(f.boundary.is_feature[plan2.node_target[2]]);
}

TEST(SnapPlan, FixedPointFollowsAChainOfCurves) {
    Fixture f;
    // 3-5 curve 0-1, then 1-2 and 2-3 through interior junctions: all three get snapped.
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.02}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.3, 0.2}, false));
    g.nodes.push_back(node_at(2, {0.5, 0.6, 0.3}, false));
    g.nodes.push_back(node_at(3, {0.5, 0.98, 0.5}, true));
    g.nodes.push_back(node_at(4, {0.3, 0.3, 0.5}, true));   // dangling curves keep 1 and 2 junctions
    g.nodes.push_back(node_at(5, {0.3, 0.6, 0.5}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive));
    g.curves.push_back(curve_between(1, 2, 3, CurveKind::Valence5));
    g.curves.push_back(curve_between(2, 1, 2, CurveKind::Valence3));
    g.curves.push_back(curve_between(3, 1, 4, CurveKind::Valence3));
    g.curves.push_back(curve_between(4, 2, 5, CurveKind::Valence3));
    const SnapPlan plan = plan_snapping(g, classify_curve_ends(g, 3 * f.boundary.h_mean), f.boundary,
                                        f.cube.mesh.points, SnapOptions{});
    EXPECT_EQ(plan.curves.size(), 5u);  // the whole connected graph
    for (int n = 0; n < 6; ++n) EXPECT_GE(plan.node_target[n], 0) << "node " << n;
}

TEST(SnapPlan, DeadEndJoinsTheNearbyJunction) {
    Fixture f;
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.02}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.5, 0.3}, false));   // junction (3 ends)
    g.nodes.push_back(node_at(2, {0.5, 0.55, 0.3}, false));  // dead end next to it
    g.nodes.push_back(node_at(3, {0.5, 0.98, 0.5}, true));
    g.nodes.push_back(node_at(4, {0.1, 0.5, 0.5}, true));
    g.nodes.push_back(node_at(5, {0.9, 0.5, 0.5}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive));
    g.curves.push_back(curve_between(1, 1, 4, CurveKind::Valence3));
    g.curves.push_back(curve_between(2, 1, 5, CurveKind::Valence3));
    g.curves.push_back(curve_between(3, 2, 3, CurveKind::Valence3));  // stops one tet short of node 1
    const CurveEnds ends = classify_curve_ends(g, 3 * f.boundary.h_mean);
    EXPECT_EQ(ends.node_rep[2], 1);
    const SnapPlan plan = plan_snapping(g, ends, f.boundary, f.cube.mesh.points, SnapOptions{});
    EXPECT_NE(std::find(plan.curves.begin(), plan.curves.end(), 3), plan.curves.end());
    const CurveEnds far = classify_curve_ends(g, 0.01);
    EXPECT_EQ(far.node_kind[2], EndKind::DeadEnd);
}

TEST(SnapPlan, JunkChainsAndClosedLoopsAreNeverSnapped) {
    Fixture f;
    SingularityGraph g;
    g.nodes.push_back(node_at(0, {0.5, 0.02, 0.02}, true));
    g.nodes.push_back(node_at(1, {0.5, 0.5, 0.3}, false));
    g.nodes.push_back(node_at(2, {0.1, 0.5, 0.5}, true));
    g.curves.push_back(curve_between(0, 0, 1, CurveKind::ThreeFive));
    g.curves.push_back(curve_between(1, 1, 2, CurveKind::Valence3));
    g.curves.push_back(curve_between(2, 1, 1, CurveKind::Valence3, 2));  // 2-triangle stub at the junction
    SingularCurve loop = curve_between(3, -1, -1, CurveKind::ThreeFive);
    loop.closed = true;
    g.curves.push_back(loop);
    const CurveEnds ends = classify_curve_ends(g, 3 * f.boundary.h_mean);
    EXPECT_TRUE(ends.excluded[2]);
    EXPECT_TRUE(ends.excluded[3]);
    const SnapPlan plan = plan_snapping(g, ends, f.boundary, f.cube.mesh.points, SnapOptions{});
    EXPECT_EQ(plan.curves, (std::vector<int>{0, 1}));
    EXPECT_EQ(plan.three_five_curves, 1);
}

}  // namespace
}  // namespace framefix
