// extract_singularities on synthetic fields over the cube fixture: the oracles are the fields'
// constructions (a straight line of index +-1/4, a line whose stable direction flips).
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/core/error.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {
namespace {

using testing::LineField;

struct Case {
    testing::Fixture fx;
    TetTopology topo;
};

Case cube(int n) {
    Case c{testing::cube_tets(n), {}};
    c.topo = build_topology(c.fx.mesh);
    return c;
}

// Distance from x to the line through c along d.
double line_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
    const Eigen::Vector3d u = d.normalized();
    return ((x - c) - (x - c).dot(u) * u).norm();
}

const Eigen::Vector3d kC(0.53, 0.46, 0.5), kZ(0, 0, 1);

TEST(Extract, ConstantFrameHasNoSingularTriangle) {
    const Case c = cube(5);
    const Eigen::Matrix3d R = testing::rot(Eigen::Vector3d(1, 2, 3), 0.7);
    const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, [&](const Eigen::Vector3d&) { return R; }));
    EXPECT_EQ(g.summary.singular_faces, 0);
    EXPECT_EQ(g.summary.curves, 0);
    EXPECT_EQ(g.summary.nodes, 0);
    EXPECT_TRUE(g.summary.meshable);
    EXPECT_EQ(g.face_valence.size(), size_t(c.topo.faces.rows()));
}

TEST(Extract, QuarterIndexLineIsOneValence3Curve) {
    const Case c = cube(6);
    const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, LineField{kC, kZ, 0.25}));
    ASSERT_EQ(g.summary.curves, 1);
    const SingularCurve& curve = g.curves[0];
    EXPECT_EQ(curve.kind, CurveKind::Valence3);
    EXPECT_FALSE(curve.closed);
    for (int v : curve.valences) EXPECT_EQ(v, 3);
    EXPECT_EQ(g.summary.complex_faces, 0);
    EXPECT_EQ(g.summary.singular_faces, int(curve.faces.size()));
    EXPECT_GT(std::abs(curve.stable_direction.dot(kZ)), 0.99);
    EXPECT_NEAR(curve.length, 1.0, 0.15);
    const double h = 1.0 / 6;
    for (int i = 0; i < curve.points.rows(); ++i) EXPECT_LT(line_distance(curve.points.row(i).transpose(), kC, kZ), h);
    EXPECT_EQ(g.summary.valence3, 1);
    EXPECT_EQ(g.summary.curves_3_5, 0);
    EXPECT_TRUE(g.summary.meshable);
}

TEST(Extract, QuarterIndexLineEndsOnTwoValidBoundaryNodes) {
    const Case c = cube(6);
    const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, LineField{kC, kZ, 0.25}));
    ASSERT_EQ(g.summary.nodes, 2);
    for (const SingularNode& n : g.nodes) {
        EXPECT_TRUE(n.boundary);
        EXPECT_TRUE(n.valid);
        EXPECT_EQ(n.n3, 1);
        EXPECT_EQ(n.n5, 0);
        EXPECT_TRUE(std::abs(n.position.z()) < 1e-9 || std::abs(n.position.z() - 1) < 1e-9);
    }
    EXPECT_NE(g.curves[0].ends[0], g.curves[0].ends[1]);
}

TEST(Extract, MinusQuarterIndexLineIsOneValence5Curve) {
    const Case c = cube(6);
    const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, LineField{kC, kZ, -0.25}));
    ASSERT_EQ(g.summary.curves, 1);
    EXPECT_EQ(g.curves[0].kind, CurveKind::Valence5);
    for (int v : g.curves[0].valences) EXPECT_EQ(v, 5);
    EXPECT_EQ(g.summary.valence5, 1);
    for (const SingularNode& n : g.nodes) EXPECT_EQ(n.n5, 1);
}

TEST(Extract, TiltedLineKeepsItsValenceAndStableDirection) {
    const Case c = cube(7);
    const Eigen::Vector3d d = Eigen::Vector3d(0.3, -0.2, 1).normalized(), p(0.52, 0.47, 0.5);
    for (double index : {0.25, -0.25}) {
        const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, LineField{p, d, index}));
        ASSERT_EQ(g.summary.curves, 1);
        EXPECT_EQ(g.curves[0].kind, index > 0 ? CurveKind::Valence3 : CurveKind::Valence5);
        EXPECT_GT(std::abs(g.curves[0].stable_direction.dot(d)), 0.99);
        EXPECT_EQ(g.summary.complex_faces, 0);
    }
}

TEST(Extract, FlippingStableDirectionGivesOne35Curve) {
    // Valence 3 near the bottom, 5 near the top; the stable direction turns by 180 deg over
    // z in [0.1, 0.9]. (Turning it over 0.6 on an 8^3 grid is under-resolved: frames 75 deg
    // apart along an edge, and the discrete field has extra curves and a junction.)
    const Case c = cube(10);
    const LineField field{kC, kZ, 0.25, -0.4, 0.4};
    const SingularityGraph g = extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, field));
    ASSERT_EQ(g.summary.curves, 1);
    const SingularCurve& curve = g.curves[0];
    EXPECT_EQ(curve.kind, CurveKind::ThreeFive);
    EXPECT_EQ(g.summary.curves_3_5, 1);
    EXPECT_FALSE(g.summary.meshable);
    ASSERT_GE(curve.transition, 0);
    EXPECT_NEAR(curve.points(curve.transition, 2), 0.5, 0.2);
    // The valence-3 end is the bottom one.
    const int bottom = curve.points(0, 2) < 0.5 ? 0 : 1;
    EXPECT_EQ(curve.end_valence[bottom], 3);
    EXPECT_EQ(curve.end_valence[1 - bottom], 5);
    EXPECT_EQ(g.summary.nodes, 2);
    EXPECT_EQ(g.summary.invalid_nodes, 0);
}

TEST(Extract, CurvesEndAtNodesWhoseCountsMatch) {
    // An under-resolved flip (see above): a junction, boundary nodes, several curves.
    const Case c = cube(8);
    const SingularityGraph g =
        extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, LineField{kC, kZ, 0.25, -0.3, 0.3}));
    ASSERT_GE(g.summary.curves, 3);
    std::vector<int> n3(g.nodes.size(), 0), n5(g.nodes.size(), 0);
    for (const SingularCurve& curve : g.curves) {
        if (curve.closed) continue;
        for (int k = 0; k < 2; ++k) {
            ASSERT_GE(curve.ends[k], 0);
            ASSERT_LT(curve.ends[k], int(g.nodes.size()));
            (curve.end_valence[k] == 3 ? n3 : n5)[curve.ends[k]] += 1;
        }
    }
    for (size_t i = 0; i < g.nodes.size(); ++i) {
        EXPECT_EQ(g.nodes[i].n3, n3[i]);
        EXPECT_EQ(g.nodes[i].n5, n5[i]);
        EXPECT_GT(n3[i] + n5[i], 0);  // no node without a curve
    }
}

TEST(Extract, DeterministicAcrossRunsAndThreadCounts) {
    const Case c = cube(8);
    const FrameField f = testing::field_of(c.fx.mesh, LineField{kC, Eigen::Vector3d(0.2, 0.1, 1), 0.25, -0.1, 0.1});
    SingularityOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const SingularityGraph a = extract_singularities(c.fx.mesh, c.topo, f, one);
    const SingularityGraph b = extract_singularities(c.fx.mesh, c.topo, f, two);
    const SingularityGraph a2 = extract_singularities(c.fx.mesh, c.topo, f, one);
    EXPECT_EQ(a.face_valence, b.face_valence);
    EXPECT_EQ(a.face_valence, a2.face_valence);
    ASSERT_EQ(a.curves.size(), b.curves.size());
    for (size_t i = 0; i < a.curves.size(); ++i) {
        EXPECT_EQ(a.curves[i].faces, b.curves[i].faces);
        EXPECT_EQ(a.curves[i].points, b.curves[i].points);
    }
}

TEST(Extract, DirectMatchingOfCloseFramesChangesNothing) {
    const Case c = cube(8);
    const FrameField f = testing::field_of(c.fx.mesh, LineField{kC, Eigen::Vector3d(0.2, 0.1, 1), 0.25, -0.1, 0.1});
    SingularityOptions always;
    always.direct_match_deg = 0;
    const SingularityGraph a = extract_singularities(c.fx.mesh, c.topo, f);
    const SingularityGraph b = extract_singularities(c.fx.mesh, c.topo, f, always);
    EXPECT_EQ(a.face_valence, b.face_valence);
    EXPECT_LT(a.subsampled_edges, b.subsampled_edges);
}

TEST(Extract, RejectsAFieldOfTheWrongSize) {
    const Case c = cube(3);
    FrameField f = testing::field_of(c.fx.mesh, [](const Eigen::Vector3d&) { return Eigen::Matrix3d::Identity(); });
    f.coefficients.conservativeResize(f.coefficients.rows() - 1, 9);
    EXPECT_THROW(extract_singularities(c.fx.mesh, c.topo, f), Error);
    SingularityOptions bad;
    bad.majority_window = 0;
    EXPECT_THROW(extract_singularities(c.fx.mesh, c.topo, testing::field_of(c.fx.mesh, [](const Eigen::Vector3d&) {
                     return Eigen::Matrix3d::Identity();
                 }), bad),
                 Error);
}

}  // namespace
}  // namespace framefix
