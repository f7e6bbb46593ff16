// absorb_edge_curves on a hand-made graph in the cube fixture whose edge 1 (along x at y = z = 0)
// is made ambiguous (135 degrees): which curves are glued, and how the nodes they ended at are read.
#include <gtest/gtest.h>

#include "backend/mesh/cube_fixture.h"
#include "framefix/singularities/edge_absorption.h"

namespace framefix {
namespace {

using Eigen::Vector3d;

constexpr double kGlueRadius = 0.1;  // model units; the fixture's edge length is 1/6

SingularCurve curve(CurveKind kind, int a, int b, std::initializer_list<Vector3d> pts) {
    SingularCurve c;
    c.kind = kind;
    c.ends[0] = a;
    c.ends[1] = b;
    c.points.resize(int(pts.size()), 3);
    int i = 0;
    for (const Vector3d& p : pts) c.points.row(i++) = p.transpose();
    return c;
}

SingularNode node(const Vector3d& p, bool boundary) {
    SingularNode n;
    n.position = p;
    n.boundary = boundary;
    return n;
}

struct AmbiguousEdgeCube {
    testing::Fixture fx = testing::cube_tets(6);
    SingularityGraph g;
    AmbiguousEdgeCube() { fx.features.edges[0] = {1, 2, 135, 135, 1.0, false, ""}; }
    int absorb() { return absorb_edge_curves(g, fx.mesh, fx.features, kGlueRadius); }
};

// Nodes: 0 interior near edge 1, 1 boundary on x = 0 near edge 1, 2 boundary on z = 1, 3 interior
// at the centre, 4 boundary on z = 1. Curve 0 runs along edge 1 (glued); curve 1 leaves node 0
// upwards (valence 5); curve 2 is a valence-5 stub from the centre (no edge near).
AmbiguousEdgeCube graph_with_a_glued_curve() {
    AmbiguousEdgeCube c;
    for (const auto& [p, boundary] : std::vector<std::pair<Vector3d, bool>>{
             {{0.5, 0.05, 0.05}, false}, {{0, 0.05, 0.05}, true}, {{0.5, 0.05, 1}, true}, {{0.5, 0.5, 0.5}, false},
             {{0.5, 0.5, 1}, true}})
        c.g.nodes.push_back(node(p, boundary));
    c.g.curves.push_back(curve(CurveKind::Valence3, 1, 0, {{0, 0.05, 0.05}, {0.25, 0.04, 0.06}, {0.5, 0.05, 0.05}}));
    c.g.curves.push_back(curve(CurveKind::Valence5, 0, 2, {{0.5, 0.05, 0.05}, {0.5, 0.05, 0.5}, {0.5, 0.05, 1}}));
    c.g.curves.push_back(curve(CurveKind::Valence5, 3, 4, {{0.5, 0.5, 0.5}, {0.5, 0.5, 0.75}, {0.5, 0.5, 1}}));
    return c;
}

TEST(EdgeAbsorption, GluesOnlyTheCurveAlongTheAmbiguousEdge) {
    AmbiguousEdgeCube c = graph_with_a_glued_curve();
    EXPECT_EQ(c.absorb(), 1);
    ASSERT_EQ(c.g.absorbed.size(), 1u);
    EXPECT_EQ(c.g.absorbed[0].ends[0], -1);
    EXPECT_EQ(c.g.curves.size(), 2u);
    EXPECT_EQ(c.g.nodes.size(), 4u);  // node 1 is left without a curve
}

TEST(EdgeAbsorption, ANodeAGluedCurveEndedAtIsANodeOnTheFeatureCurve) {
    AmbiguousEdgeCube c = graph_with_a_glued_curve();
    c.absorb();
    const SingularCurve& up = c.g.curves[0];
    ASSERT_EQ(up.kind, CurveKind::Valence5);
    const SingularNode& foot = c.g.nodes[size_t(up.ends[0])];
    EXPECT_LT((foot.position - Vector3d(0.5, 0.05, 0.05)).norm(), 1e-12);
    EXPECT_TRUE(foot.boundary);  // one valence-5 curve end alone would be invalid inside
    EXPECT_TRUE(foot.valid);
    // The stub at the centre ends at a node no glued curve touched: still judged by the table.
    const SingularNode& centre = c.g.nodes[size_t(c.g.curves[1].ends[0])];
    EXPECT_FALSE(centre.boundary);
    EXPECT_FALSE(centre.valid);
    EXPECT_EQ(c.g.summary.invalid_nodes, 1);
}

TEST(EdgeAbsorption, NothingMovesWithoutAnAmbiguousEdge) {
    AmbiguousEdgeCube c = graph_with_a_glued_curve();
    c.fx.features.edges[0] = {1, 1, 90, 90, 1.0, false, ""};
    EXPECT_EQ(c.absorb(), 0);
    EXPECT_EQ(c.g.curves.size(), 3u);
    EXPECT_TRUE(c.g.absorbed.empty());
}

// Edges 1 (y = 0, z = 0) and 2 (y = 0, z = 1) at 135 degrees, both bounding the face y = 0 (tag
// 3), which is 1 wide: wider than a strip (2 glue radii).
AmbiguousEdgeCube chamfer_like() {
    AmbiguousEdgeCube c;
    c.fx.features.edges[0] = {1, 2, 135, 135, 1.0, false, "", {3, 5}, {}};
    c.fx.features.edges[1] = {2, 2, 135, 135, 1.0, false, "", {3, 6}, {}};
    c.g.nodes.push_back(node({0.02, 0.03, 0.03}, true));
    c.g.nodes.push_back(node({0.98, 0.03, 0.97}, true));
    return c;
}

// Along edge 1 to x = 0.4, over to edge 2 through `via`, along edge 2 from x = 0.6.
SingularCurve switching_curve(std::initializer_list<Vector3d> via) {
    std::vector<Vector3d> pts = {{0.02, 0.03, 0.03}, {0.2, 0.03, 0.03}, {0.4, 0.03, 0.03}};
    pts.insert(pts.end(), via.begin(), via.end());
    for (const Vector3d& p : {Vector3d(0.6, 0.03, 0.97), Vector3d(0.8, 0.03, 0.97), Vector3d(0.98, 0.03, 0.97)}) pts.push_back(p);
    SingularCurve c = curve(CurveKind::Valence3, 0, 1, {});
    c.points.resize(int(pts.size()), 3);
    for (int i = 0; i < int(pts.size()); ++i) c.points.row(i) = pts[size_t(i)].transpose();
    return c;
}

TEST(EdgeAbsorption, ACurveThatCrossesAWideFaceFromOneAmbiguousEdgeToTheOtherIsGlued) {
    AmbiguousEdgeCube c = chamfer_like();
    c.g.curves.push_back(switching_curve({{0.45, 0.04, 0.2}, {0.5, 0.05, 0.5}, {0.55, 0.04, 0.8}}));
    EXPECT_EQ(c.absorb(), 1);
    EXPECT_TRUE(c.g.curves.empty());
}

TEST(EdgeAbsorption, ACurveAlongTheMiddleOfAWideFaceIsNotGlued) {
    AmbiguousEdgeCube c = chamfer_like();
    // Into the face, along its middle and back: 2.3 long against 0.96 across.
    c.g.curves.push_back(switching_curve({{0.95, 0.04, 0.45}, {0.05, 0.04, 0.55}}));
    EXPECT_EQ(c.absorb(), 0);
}

TEST(EdgeAbsorption, ACurveThatCrossesInsideTheSolidIsNotGlued) {
    AmbiguousEdgeCube c = chamfer_like();
    c.g.curves.push_back(switching_curve({{0.45, 0.3, 0.2}, {0.5, 0.4, 0.5}, {0.55, 0.3, 0.8}}));
    EXPECT_EQ(c.absorb(), 0);
}

TEST(EdgeAbsorption, ACurveCrossingBetweenEdgesOfNoCommonFaceIsNotGlued) {
    AmbiguousEdgeCube c = chamfer_like();
    c.fx.features.edges[1].faces = {4, 6};
    c.g.curves.push_back(switching_curve({{0.45, 0.04, 0.2}, {0.5, 0.05, 0.5}, {0.55, 0.04, 0.8}}));
    EXPECT_EQ(c.absorb(), 0);
}

}  // namespace
}  // namespace framefix
