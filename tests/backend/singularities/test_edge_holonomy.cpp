// The per-edge holonomy (Holonomy::Edges) on the synthetic fields of test_extract.cpp: the
// oracles are the fields' constructions, and the per-triangle reading of the same field.
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/singularities/edge_holonomy.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {
namespace {

using testing::LineField;

const Eigen::Vector3d kC(0.53, 0.46, 0.5), kZ(0, 0, 1);

SingularityOptions edges() {
    SingularityOptions o;
    o.holonomy = Holonomy::Edges;
    return o;
}

TEST(EdgeHolonomy, BoundaryEdgesHaveNoRingAndInteriorEdgesAClosedOne) {
    const testing::Fixture fx = testing::cube_tets(3);
    const TetTopology topo = build_topology(fx.mesh);
    int interior = 0;
    for (int e = 0; e < topo.edges.rows(); ++e) {
        const std::vector<int> ring = edge_ring(fx.mesh, topo, e);
        const bool on_surface = topo.on_boundary[topo.edges(e, 0)] && topo.on_boundary[topo.edges(e, 1)];
        if (!on_surface) EXPECT_GE(ring.size(), 3u) << "edge " << e;
        interior += !ring.empty();
    }
    EXPECT_GT(interior, 0);
}

TEST(EdgeHolonomy, ConstantFrameHasNoSingularEdge) {
    const testing::Fixture fx = testing::cube_tets(4);
    const TetTopology topo = build_topology(fx.mesh);
    const Eigen::Matrix3d R = testing::rot(Eigen::Vector3d(1, 2, 3), 0.7);
    const SingularityGraph g =
        extract_singularities(fx.mesh, topo, testing::field_of(fx.mesh, [&](const Eigen::Vector3d&) { return R; }), edges());
    EXPECT_EQ(g.summary.singular_faces, 0);
    EXPECT_EQ(g.summary.curves, 0);
    EXPECT_EQ(g.face_valence.size(), size_t(topo.edges.rows()));
}

TEST(EdgeHolonomy, QuarterIndexLinesAreOneCurveOfTheirValenceBetweenBoundaryNodes) {
    const testing::Fixture fx = testing::cube_tets(6);
    const TetTopology topo = build_topology(fx.mesh);
    for (double index : {0.25, -0.25}) {
        const SingularityGraph g = extract_singularities(fx.mesh, topo, testing::field_of(fx.mesh, LineField{kC, kZ, index}), edges());
        ASSERT_EQ(g.summary.curves, 1) << index;
        for (int v : g.curves[0].valences) EXPECT_EQ(v, index > 0 ? 3 : 5);  // the staircase's steps too
        EXPECT_EQ(g.curves[0].kind, index > 0 ? CurveKind::Valence3 : CurveKind::Valence5);
        EXPECT_GT(std::abs(g.curves[0].stable_direction.dot(kZ)), 0.99);
        EXPECT_NEAR(g.curves[0].length, 1.0, 0.2);
        ASSERT_EQ(g.summary.nodes, 2);
        for (const SingularNode& n : g.nodes) EXPECT_TRUE(n.boundary && n.valid);
        EXPECT_TRUE(g.summary.meshable);
    }
}

TEST(EdgeHolonomy, FlippingStableDirectionGivesOne35CurveAsTrianglesDo) {
    const testing::Fixture fx = testing::cube_tets(10);
    const TetTopology topo = build_topology(fx.mesh);
    const FrameField f = testing::field_of(fx.mesh, LineField{kC, kZ, 0.25, -0.4, 0.4});
    const SingularityGraph by_edges = extract_singularities(fx.mesh, topo, f, edges());
    const SingularityGraph by_triangles = extract_singularities(fx.mesh, topo, f);
    ASSERT_EQ(by_edges.summary.curves, 1);
    EXPECT_EQ(by_edges.curves[0].kind, CurveKind::ThreeFive);
    EXPECT_EQ(by_edges.summary.curves_3_5, by_triangles.summary.curves_3_5);
    const int bottom = by_edges.curves[0].points(0, 2) < 0.5 ? 0 : 1;
    EXPECT_EQ(by_edges.curves[0].end_valence[bottom], 3);
}

TEST(EdgeHolonomy, SameResultWithOneAndTwoThreads) {
    const testing::Fixture fx = testing::cube_tets(8);
    const TetTopology topo = build_topology(fx.mesh);
    const FrameField f = testing::field_of(fx.mesh, LineField{kC, Eigen::Vector3d(0.2, 0.1, 1), 0.25, -0.1, 0.1});
    SingularityOptions one = edges(), two = edges();
    one.threads = 1;
    two.threads = 2;
    const SingularityGraph a = extract_singularities(fx.mesh, topo, f, one);
    const SingularityGraph b = extract_singularities(fx.mesh, topo, f, two);
    EXPECT_EQ(a.face_valence, b.face_valence);
    ASSERT_EQ(a.curves.size(), b.curves.size());
    for (size_t i = 0; i < a.curves.size(); ++i) EXPECT_EQ(a.curves[i].faces, b.curves[i].faces);
}

}  // namespace
}  // namespace framefix
