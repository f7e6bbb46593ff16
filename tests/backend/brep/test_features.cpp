#include <cmath>

#include <gtest/gtest.h>

#include "fixtures.h"
#include "framefix/brep/brep_model.h"

namespace framefix {
namespace {

using test::sample;

constexpr double kPi = 3.14159265358979323846;

// Features of valence k whose length is near `length`.
int count(const FeatureSet& fs, int valence, double length = -1) {
    int n = 0;
    for (const auto& e : fs.edges) n += e.valence == valence && (length < 0 || std::abs(e.length - length) < 1e-3);
    return n;
}

int count_reason(const FeatureSet& fs, const std::string& reason) {
    int n = 0;
    for (const auto& e : fs.edges) n += e.reason == reason;
    return n;
}

TEST(Features, BoxHasTwelveConvexEdges) {
    const FeatureSet fs = classify_features(test::box(1, 2, 3));
    ASSERT_EQ(fs.edges.size(), 12u);
    for (const auto& e : fs.edges) {
        EXPECT_EQ(e.valence, 1) << "Edge" << e.edge;
        EXPECT_NEAR(e.angle_min_deg, 90, 1e-6);
        EXPECT_NEAR(e.angle_max_deg, 90, 1e-6);
        EXPECT_FALSE(e.valence_varies);
    }
    EXPECT_EQ(fs.by_valence()[1], 12);
}

TEST(Features, EdgesAreNumberedLikeFreeCAD) {
    const FeatureSet fs = classify_features(load_shape(sample("notch")));
    for (size_t i = 0; i < fs.edges.size(); ++i) EXPECT_EQ(fs.edges[i].edge, int(i) + 1);
}

TEST(Features, BlindHoleFloorConcaveRimConvexSeamNot) {
    const FeatureSet fs = classify_features(test::box_with_blind_hole());
    const double circle = 2 * kPi * 0.25;
    EXPECT_EQ(count(fs, 3, circle), 1) << "floor circle is concave (270 deg)";
    EXPECT_EQ(count(fs, 1, circle), 1) << "rim circle is convex (90 deg)";
    EXPECT_EQ(count(fs, 0, 0.5), 1) << "the seam of the hole";
    EXPECT_EQ(count_reason(fs, "seam"), 1);
    EXPECT_EQ(count(fs, 1, 1.0), 12) << "the box edges";
}

TEST(Features, ImprintedArcHasValenceTwo) {
    const FeatureSet fs = classify_features(load_shape(sample("box_arc")));
    EXPECT_EQ(count(fs, 2), 1);
    EXPECT_EQ(count(fs, 2, kPi / 4), 1) << "the quarter circle of radius 0.5";
}

TEST(Features, ImprintedArcOnCurvedTopHasValenceTwo) {
    const FeatureSet fs = classify_features(load_shape(sample("box_arc_curved")));
    EXPECT_EQ(count(fs, 2), 1);
}

TEST(Features, FilletJunctionsAreTangent) {
    const FeatureSet fs = classify_features(test::box_with_fillet());
    EXPECT_EQ(count_reason(fs, "tangent"), 2) << "the two straight junctions of the rounded edge";
    EXPECT_EQ(count(fs, 3), 0);
}

TEST(Features, NotchHasOneConcaveArc) {
    const FeatureSet fs = classify_features(load_shape(sample("notch")));
    EXPECT_EQ(count(fs, 3), 1);
    EXPECT_EQ(count(fs, 3, kPi / 4), 1) << "the floor arc";
    EXPECT_EQ(count(fs, 1, kPi / 4), 1) << "the top arc";
}

TEST(Features, CylinderHasTwoCirclesAndASeam) {
    const FeatureSet fs = classify_features(load_shape(sample("cylinder")));
    EXPECT_EQ(count(fs, 1), 2);
    EXPECT_EQ(count_reason(fs, "seam"), 1);
}

TEST(Features, HalfSphereJoinIsConcave) {
    const FeatureSet fs = classify_features(load_shape(sample("half_sphere_box")));
    EXPECT_EQ(count(fs, 3), 1);
    EXPECT_EQ(count(fs, 3, 2 * kPi * 0.6), 1);
}

TEST(Features, LPrismHasOneConcaveEdge) {
    const FeatureSet fs = classify_features(load_shape(sample("l_prism")));
    EXPECT_EQ(count(fs, 3), 1);
    EXPECT_EQ(count(fs, 1), 17);
}

TEST(Features, CylinderIntersectionAngleVariesAlongTheCurve) {
    const FeatureSet fs = classify_features(load_shape(sample("two_cylinders")));
    int concave = 0;
    for (const auto& e : fs.edges)
        if (e.valence == 3) {
            ++concave;
            EXPECT_GT(e.angle_max_deg - e.angle_min_deg, 10) << "Edge" << e.edge;
        }
    EXPECT_EQ(concave, 2);
}

}  // namespace
}  // namespace framefix
