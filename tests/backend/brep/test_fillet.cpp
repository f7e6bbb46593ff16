// Fillets on the B-rep (brep/fillet.h): OCCT's fillet builder on the samples, with the volume a
// fillet must add to a concave edge, (1 - pi/4) r^2 per unit length, as the oracle.
#include <cmath>

#include <gtest/gtest.h>

#include "fixtures.h"
#include "framefix/brep/fillet.h"
#include "framefix/core/error.h"

namespace framefix {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<const EdgeFeature*> concave(const FeatureSet& fs) {
    std::vector<const EdgeFeature*> out;
    for (const EdgeFeature& e : fs.edges)
        if (e.valence == 3) out.push_back(&e);
    return out;
}

TEST(Fillet, SectionAreaOfRightAngleEdges) {
    EXPECT_NEAR(fillet_section_area(1, 270), 1 - kPi / 4, 1e-12);
    EXPECT_NEAR(fillet_section_area(1, 90), -(1 - kPi / 4), 1e-12);
    EXPECT_NEAR(fillet_section_area(2, 270), 4 * (1 - kPi / 4), 1e-12);
    EXPECT_NEAR(fillet_section_area(1, 180), 0, 1e-12);
}

TEST(Fillet, NotchArcGetsTheVolumeOfItsFillet) {
    const BrepModel notch = load_shape(test::sample("notch"));
    const FeatureSet fs = classify_features(notch);
    const auto arcs = concave(fs);
    ASSERT_EQ(arcs.size(), 1u);
    const double r = 0.05;
    const FilletResult f = fillet_edges(notch, {{arcs[0]->edge, r, 270}});
    ASSERT_EQ(f.fillets.size(), 1u);
    EXPECT_TRUE(f.fillets[0].done) << f.fillets[0].reason;
    EXPECT_EQ(f.fillets[0].radius, r);
    EXPECT_EQ(f.how, "all at once");
    EXPECT_NEAR(f.volume_change, (1 - kPi / 4) * r * r * arcs[0]->length, 0.1 * (1 - kPi / 4) * r * r * arcs[0]->length);
    EXPECT_EQ(f.model.num_faces, notch.num_faces + 1);
    EXPECT_EQ(concave(classify_features(f.model)).size(), 0u);  // the fillet joins its faces smoothly
    EXPECT_EQ(load_shape(test::sample("notch")).volume, notch.volume);  // the input is untouched
}

TEST(Fillet, AnEdgeThatCannotBeFilletedIsReportedAndTheOthersAreDone) {
    // The groove's two concave floor arcs; the inner one gets a radius larger than the groove is
    // wide, which OCCT cannot build.
    const BrepModel groove = load_shape(test::sample("groove"));
    const auto arcs = concave(classify_features(groove));
    ASSERT_EQ(arcs.size(), 2u);
    const FilletResult f = fillet_edges(groove, {{arcs[0]->edge, 0.5, 270}, {arcs[1]->edge, 0.04, 270}});
    ASSERT_EQ(f.fillets.size(), 2u);
    EXPECT_EQ(f.how, "edge by edge");
    EXPECT_FALSE(f.fillets[0].done);
    EXPECT_FALSE(f.fillets[0].reason.empty());
    EXPECT_TRUE(f.fillets[1].done) << f.fillets[1].reason;
    EXPECT_GT(f.volume_change, 0);
    EXPECT_EQ(f.model.num_faces, groove.num_faces + 1);
}

TEST(Fillet, BadRequestsAreRefused) {
    const BrepModel cube = test::box(1, 1, 1);
    EXPECT_THROW(fillet_edges(cube, {{13, 0.1, 90}}), Error);
    EXPECT_THROW(fillet_edges(cube, {{1, 0, 90}}), Error);
    const FilletResult none = fillet_edges(cube, {});
    EXPECT_TRUE(none.fillets.empty());
    EXPECT_EQ(none.model.volume, cube.volume);
}

}  // namespace
}  // namespace framefix

namespace framefix {
namespace {

TEST(Fillet, RoomIsTheDistanceToTheNearestOtherEdgeOrFace) {
    // The notch's floor arc (radius 0.5 about x = y = 1, at z = 0.5): its midpoint lies
    // 0.5 sin 45 deg = 0.354 from the box's side faces x = 1 and y = 1.
    const BrepModel notch = load_shape(test::sample("notch"));
    for (const EdgeFeature& e : classify_features(notch).edges)
        if (e.valence == 3) EXPECT_NEAR(fillet_room(notch, e.edge), 0.5 * std::sqrt(0.5), 1e-3);
    // A unit cube's edge: the edges meeting it, and the faces at its ends, lie 0.5 from its midpoint.
    EXPECT_NEAR(fillet_room(test::box(1, 1, 1), 1), 0.5, 1e-9);
}

}  // namespace
}  // namespace framefix
