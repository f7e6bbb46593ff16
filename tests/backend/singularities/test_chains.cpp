// trace_chains on hand-made face labels: straight segments through the cube fixture mark the
// faces they cross, so curve ends, junctions, dead ends and joins are known by construction.
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/core/error.h"
#include "framefix/singularities/chain_ends.h"
#include "framefix/singularities/chains.h"

namespace framefix {
namespace {

using Eigen::Vector3d;

struct Grid {
    testing::Fixture fx = testing::cube_tets(6);
    TetTopology topo = build_topology(fx.mesh);
    std::vector<int> val = std::vector<int>(topo.faces.rows(), 0);

    int segment(const Vector3d& p, const Vector3d& q, int label = 3) {
        return testing::label_segment(fx.mesh, topo, p, q, label, val);
    }
    ChainGraph trace() const { return trace_chains(fx.mesh, topo, val); }
};

int interior_nodes(const ChainGraph& g) {
    int n = 0;
    for (const ChainNode& node : g.nodes) n += !node.boundary;
    return n;
}

// A point inside tet 0's neighbourhood at the cube centre, off every mesh plane.
const Vector3d kP(0.513, 0.481, 0.467);

TEST(Chains, StraightLineIsOneCurveBetweenTwoBoundaryNodes) {
    Grid g;
    const int crossed = g.segment(Vector3d(0.53, 0.46, -0.1), Vector3d(0.53, 0.46, 1.1));
    const ChainGraph c = g.trace();
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_EQ(int(c.curves[0].faces.size()), crossed);
    ASSERT_EQ(c.nodes.size(), 2u);
    EXPECT_TRUE(c.nodes[0].boundary && c.nodes[1].boundary);
    EXPECT_EQ(c.nodes[0].boundary_faces.size(), 1u);
    EXPECT_EQ(c.curves[0].face_point.size(), c.curves[0].faces.size());
}

TEST(Chains, FourRaysMeetAtOneJunction) {
    Grid g;
    for (const Vector3d& d : {Vector3d(1, 0.11, 0.07), Vector3d(-0.13, 1, 0.05), Vector3d(-1, -1.07, 0.09),
                              Vector3d(0.08, 0.1, -1)})
        g.segment(kP, kP + 2 * d);
    const ChainGraph c = g.trace();
    EXPECT_EQ(c.curves.size(), 4u);
    ASSERT_EQ(interior_nodes(c), 1);
    int junction = -1;
    for (int i = 0; i < int(c.nodes.size()); ++i)
        if (!c.nodes[i].boundary) junction = i;
    EXPECT_LT((c.nodes[junction].position - kP).norm(), 2 * c.h_mean);
    for (const ChainCurve& curve : c.curves) {
        EXPECT_TRUE(curve.ends[0] == junction || curve.ends[1] == junction);
        EXPECT_TRUE(c.nodes[curve.ends[0]].boundary != c.nodes[curve.ends[1]].boundary);
    }
}

TEST(Chains, CurveEndingInsideMakesADeadEndNode) {
    Grid g;
    g.segment(Vector3d(0.53, 0.46, -0.1), Vector3d(0.53, 0.46, 0.5));
    const ChainGraph c = g.trace();
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_EQ(c.dead_ends, 1);
    EXPECT_EQ(c.dead_ends_attached, 0);
    EXPECT_EQ(interior_nodes(c), 1);
}

TEST(Chains, DeadEndNearAJunctionIsAttachedToIt) {
    Grid g;
    for (const Vector3d& d : {Vector3d(1, 0.11, 0.07), Vector3d(-0.13, 1, 0.05), Vector3d(0.08, 0.1, -1)})
        g.segment(kP, kP + 2 * d);
    // The fourth curve stops about one cell short of the junction (ring curves do, docs/algorithms.md#chain-ends-and-nodes).
    const Vector3d d = Vector3d(-1, -1.07, 0.09).normalized();
    g.segment(kP + 0.25 * d, kP + 2 * d);
    const ChainGraph c = g.trace();
    EXPECT_EQ(c.curves.size(), 4u);
    EXPECT_EQ(c.dead_ends_attached, 1);
    EXPECT_EQ(interior_nodes(c), 1);
}

TEST(Chains, GapInACurveIsJoined) {
    Grid g;
    g.segment(Vector3d(0.53, 0.46, -0.1), Vector3d(0.53, 0.46, 0.45));
    g.segment(Vector3d(0.53, 0.46, 0.6), Vector3d(0.53, 0.46, 1.1));
    const ChainGraph c = g.trace();
    EXPECT_EQ(c.dead_ends, 2);
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_EQ(c.joined, 1);
    EXPECT_EQ(interior_nodes(c), 0);
}

TEST(Chains, ComplexFaceInsideACurveIsJoinedThrough) {
    Grid g;
    g.segment(Vector3d(0.53, 0.46, -0.1), Vector3d(0.53, 0.46, 0.5), 3);
    g.segment(Vector3d(0.53, 0.46, 0.5), Vector3d(0.53, 0.46, 1.1), 5);
    // One crossed face in the middle becomes complex: its tets are node material.
    int middle = -1;
    for (int f = 0; f < int(g.val.size()); ++f)
        if (g.val[f] == 5 && (middle < 0 || f < middle)) middle = f;
    g.val[middle] = -1;
    const ChainGraph c = g.trace();
    ASSERT_EQ(c.curves.size(), 1u);  // one curve (a 3-5 one), not two curves and a (1,1) node
    EXPECT_EQ(c.joined, 1);
    EXPECT_EQ(interior_nodes(c), 0);
    bool has3 = false, has5 = false;
    for (int f : c.curves[0].faces) has3 |= g.val[f] == 3, has5 |= g.val[f] == 5;
    EXPECT_TRUE(has3 && has5);
}

TEST(Chains, ClosedLoop) {
    // A skew quadrilateral through tet interiors; the corners are chosen so that no tet holds two
    // of its sides (hand-made labels, unlike a field's holonomy, can make junction tets there).
    Grid g;
    const std::vector<Vector3d> corners = {Vector3d(0.2933, 0.2071, 0.5847), Vector3d(0.7931, 0.2102, 0.4153),
                                           Vector3d(0.7905, 0.7093, 0.5851), Vector3d(0.2912, 0.7077, 0.4172)};
    for (int i = 0; i < 4; ++i) g.segment(corners[i], corners[(i + 1) % 4]);
    const ChainGraph c = g.trace();
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_TRUE(c.curves[0].closed);
    EXPECT_TRUE(c.nodes.empty());
    EXPECT_EQ(c.curves[0].ends[0], -1);
    EXPECT_EQ(c.curves[0].points.size(), c.curves[0].faces.size());  // cyclic, no end nodes
}

TEST(Chains, CornerArtefactsStillCloseTheLoop) {
    // Here one corner makes a junction tet with a one-face stub: the stub is junk, the junction
    // keeps two curve ends and is joined through.
    Grid g;
    const std::vector<Vector3d> corners = {Vector3d(0.2517, 0.2931, 0.5433), Vector3d(0.7489, 0.2903, 0.3742),
                                           Vector3d(0.7508, 0.7921, 0.5409), Vector3d(0.2493, 0.7912, 0.3761)};
    for (int i = 0; i < 4; ++i) g.segment(corners[i], corners[(i + 1) % 4]);
    const ChainGraph c = g.trace();
    ASSERT_EQ(c.curves.size(), 1u);
    EXPECT_TRUE(c.curves[0].closed);
    EXPECT_TRUE(c.nodes.empty());
    EXPECT_GE(c.joined, 1);
}

TEST(Chains, ShortChainsBackIntoTheSameJunctionAreJunk) {
    Grid g;
    // All four faces of one interior tet singular: a junction whose neighbours each hold one face.
    int tet = -1;
    for (int t = 0; t < g.fx.mesh.num_tets() && tet < 0; ++t) {
        bool interior = true;
        for (int k = 0; k < 4; ++k) interior &= !g.topo.on_boundary[g.fx.mesh.tets(t, k)];
        if (interior) tet = t;
    }
    for (int lf = 0; lf < 4; ++lf) g.val[g.topo.tet_faces(tet, lf)] = 3;
    const ChainGraph c = g.trace();
    EXPECT_EQ(c.junk_chains, 4);
    EXPECT_TRUE(c.curves.empty());
    EXPECT_TRUE(c.nodes.empty());
}


// Four rays from kP, plus a 12-gon loop of diameter d out of the junction and back.
ChainGraph rays_and_loop(double d) {
    Grid g;
    for (const Vector3d& r : {Vector3d(1, 0.11, 0.07), Vector3d(-0.13, 1, 0.05), Vector3d(-1, -1.07, 0.09),
                              Vector3d(0.08, 0.1, -1)})
        g.segment(kP, kP + 2 * r);
    const Vector3d u = Vector3d(0.31, 0.12, 0.95).normalized();
    const Vector3d v = u.cross(Vector3d(-0.28, 0.9, 0.62)).cross(u).normalized();
    constexpr int kSides = 12;
    auto at = [&](int k) {
        const double t = 2 * testing::kPi * k / kSides;
        return Vector3d(kP + d / 2 * (1 - std::cos(t)) * u + d / 2 * std::sin(t) * v);
    };
    for (int k = 0; k < kSides; ++k) g.segment(at(k), at(k + 1));
    return g.trace();
}

int junction_loops(const ChainGraph& c) {
    int n = 0;
    for (const ChainCurve& curve : c.curves) n += !curve.closed && curve.ends[0] == curve.ends[1];
    return n;
}

TEST(Chains, LoopsThatStayCloseToTheirJunctionAreJunk) {
    // h_mean is 0.21 here. Loops of 1.2 h to 1.7 h: the smaller ones leave and come back directly,
    // the largest is split by a corner of the polygon into two chains joined again, and is judged
    // once joined.
    for (double d : {0.25, 0.3, 0.35}) {
        const ChainGraph c = rays_and_loop(d);
        EXPECT_EQ(c.curves.size(), 4u) << d;
        EXPECT_EQ(junction_loops(c), 0) << d;
        EXPECT_EQ(interior_nodes(c), 1) << d;
    }
}

TEST(Chains, ALoopThatLeavesItsJunctionIsACurve) {
    for (double d : {0.4, 0.5}) {  // its farthest triangles 2.2 h and 2.6 h from the junction's tets
        const ChainGraph c = rays_and_loop(d);
        EXPECT_EQ(c.curves.size(), 5u) << d;
        EXPECT_EQ(junction_loops(c), 1) << d;
        EXPECT_EQ(interior_nodes(c), 1) << d;
    }
}

// A vertical curve B from the bottom face up through the cube, past a horizontal curve A at
// height z_a, `gap` apart in y, out through the top face (z = 1). Finer than the other tests
// (h_mean 0.13), so that the middle lies beyond the crossing reach (3 h) from both faces.
ChainGraph crossing_pair(double z_a, double gap, bool accept = true) {
    Grid g{testing::cube_tets(10)};
    g.segment(Vector3d(0.53, 0.46, -0.1), Vector3d(0.53, 0.46, 1.1));
    g.segment(Vector3d(-0.1, 0.46 + gap, z_a), Vector3d(1.1, 0.46 + gap, z_a + 0.02));
    ChainGraph c = g.trace();
    c.crossings = detail::join_crossings(c, g.topo, [&](const ChainGraph&, const ChainGraph&, int, int, int) { return accept; });
    return c;
}

TEST(Chains, ACurvePassingAnotherJustBeforeTheBoundaryCrossesItAtANode) {
    // B passes A about 0.7 h apart, about 1 h below the top face.
    const ChainGraph c = crossing_pair(0.87, 0.09);
    ASSERT_NEAR(c.h_mean, 0.13, 0.01);
    EXPECT_EQ(c.crossings, 1);
    ASSERT_EQ(interior_nodes(c), 1);
    ASSERT_EQ(c.curves.size(), 4u);  // A on either side of the node, B below it and its tail above
    int node = -1;
    for (int i = 0; i < int(c.nodes.size()); ++i)
        if (!c.nodes[i].boundary) node = i;
    EXPECT_TRUE(c.nodes[node].crossing);
    EXPECT_LT(std::abs(c.nodes[node].position.z() - 0.88), c.h_mean);
    for (const ChainCurve& curve : c.curves) EXPECT_EQ((curve.ends[0] == node) + (curve.ends[1] == node), 1);
}

TEST(Chains, CurvesApartOrFarFromTheBoundaryDoNotCross) {
    // 1.6 h apart; 4 h from either face.
    for (const auto& [z, gap] : {std::pair{0.87, 0.2}, std::pair{0.5, 0.09}}) {
        const ChainGraph c = crossing_pair(z, gap);
        EXPECT_EQ(c.crossings, 0) << z << " " << gap;
        EXPECT_EQ(c.curves.size(), 2u) << z << " " << gap;
        EXPECT_EQ(interior_nodes(c), 0) << z << " " << gap;
    }
}

TEST(Chains, ACrossingTheCheckRefusesIsNotJoined) {
    const ChainGraph c = crossing_pair(0.87, 0.09, false);
    EXPECT_EQ(c.crossings, 0);
    EXPECT_EQ(c.curves.size(), 2u);
    EXPECT_EQ(interior_nodes(c), 0);
}

TEST(Chains, RejectsLabelsOfTheWrongSize) {
    Grid g;
    g.val.pop_back();
    EXPECT_THROW(g.trace(), Error);
}

}  // namespace
}  // namespace framefix
