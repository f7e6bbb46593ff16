#include <cmath>

#include <gtest/gtest.h>

#include "backend/mesh/cube_fixture.h"
#include "framefix/mesh/crease_features.h"

namespace framefix {
namespace {

TEST(CreaseFeatures, CubeHasSixFacesTwelveConvexCurvesEightCorners) {
    const CreaseFeatures cf = detect_crease_features(testing::cube_tets(3).mesh);
    EXPECT_EQ(cf.mesh.face_tags.maxCoeff(), 6);
    EXPECT_EQ(cf.mesh.face_tags.minCoeff(), 1);
    ASSERT_EQ(cf.features.curves(), 12);
    for (const EdgeFeature& e : cf.features.edges) {
        EXPECT_EQ(e.valence, 1);
        EXPECT_NEAR(e.angle_min_deg, 90, 1e-9);
        EXPECT_NEAR(e.length, 1.0, 1e-12);
    }
    EXPECT_EQ(cf.mesh.feature_edges.rows(), 12 * 3);
    EXPECT_EQ(cf.mesh.corner_vertices.size(), 8);
}

// docs/algorithms.md#curves-along-ambiguous-edges: halfway between two hex corner types at every
// sample (a chamfer's 135, a wedge's 45 or 60, a gusset's 225), never near a right multiple.
TEST(CreaseFeatures, AmbiguousEdgesAreHalfwayBetweenCornerTypesAlongTheirWholeLength) {
    auto edge = [](double lo, double hi) {
        EdgeFeature e;
        e.valence = int(std::lround(lo / 90)) > 0 ? int(std::lround(lo / 90)) : 1;
        e.angle_min_deg = lo, e.angle_max_deg = hi;
        return e;
    };
    for (double a : {45.0, 60.0, 117.0, 135.0, 138.0, 225.0}) EXPECT_TRUE(ambiguous_edge(edge(a, a))) << a;
    for (double a : {90.0, 109.5, 180.0, 250.0, 270.0}) EXPECT_FALSE(ambiguous_edge(edge(a, a))) << a;
    EXPECT_FALSE(ambiguous_edge(edge(135, 170)));  // near flat somewhere along it
    EdgeFeature smooth = edge(135, 135);
    smooth.valence = 0;
    EXPECT_FALSE(ambiguous_edge(smooth));          // not a feature at all
}

TEST(CreaseFeatures, LPrismHasOneConcaveCurve) {
    const CreaseFeatures cf = detect_crease_features(testing::l_prism_tets(4));
    EXPECT_EQ(cf.mesh.face_tags.maxCoeff(), 8);  // top, bottom and six sides
    const auto n = cf.features.by_valence();
    EXPECT_EQ(n[3], 1);                          // the re-entrant edge: 270 deg inside
    EXPECT_EQ(n[1], 17);                         // 6 + 6 around top/bottom, 5 convex vertical
    EXPECT_EQ(cf.mesh.corner_vertices.size(), 12);
}

TEST(CreaseFeatures, FlatThresholdFindsNothingOnASmoothPatch) {
    CreaseOptions o;
    o.angle_deg = 95;  // no cube edge is sharper than 90 deg between normals
    const CreaseFeatures cf = detect_crease_features(testing::cube_tets(2).mesh, o);
    EXPECT_EQ(cf.features.curves(), 0);
    EXPECT_EQ(cf.mesh.face_tags.maxCoeff(), 1);
}

}  // namespace
}  // namespace framefix
