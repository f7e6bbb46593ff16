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
