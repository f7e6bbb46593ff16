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

// The groove's four arcs (radii 0.4 and 0.6 about x = y = 1): floor arcs (concave) at z = 0.8,
// rims (convex) at z = 1, with the dihedral angles of their valences.
std::vector<FilletRequest> groove_arcs(const BrepModel& groove, double r, int valence) {
    std::vector<FilletRequest> out;
    for (const EdgeFeature& e : classify_features(groove).edges) {
        const Eigen::Vector3d mid = edge_points(groove, e.edge, 3).row(1).transpose();
        const double from_axis = std::hypot(mid.x() - 1, mid.y() - 1);
        if (e.valence == valence && from_axis > 0.35 && from_axis < 0.65 && mid.z() > 0.7 && e.length > 0.5)
            out.push_back({e.edge, r, valence == 3 ? 270.0 : 90.0});
    }
    return out;
}

TEST(Fillet, AGrooveFilletedAllRoundKeepsItsVolumeAndNamesItsFilletFaces) {
    // Floor arcs (concave) and rims (convex) of equal lengths: the added and removed volumes
    // cancel, which the volume check must accept. Each fillet surface is reported with its radius.
    const BrepModel groove = load_shape(test::sample("groove"));
    std::vector<FilletRequest> all = groove_arcs(groove, 0.04, 3);
    for (const FilletRequest& rim : groove_arcs(groove, 0.04, 1)) all.push_back(rim);
    ASSERT_EQ(all.size(), 4u);
    const FilletResult f = fillet_edges(groove, all);
    EXPECT_EQ(f.how, "all at once");
    for (const FilletOutcome& o : f.fillets) EXPECT_TRUE(o.done) << "Edge" << o.edge << ": " << o.reason;
    EXPECT_NEAR(f.volume_change, 0, 0.05 * (1 - kPi / 4) * 0.04 * 0.04);
    ASSERT_EQ(f.fillet_faces.size(), 4u);
    for (const auto& [face, radius] : f.fillet_faces) {
        EXPECT_GE(face, 1);
        EXPECT_LE(face, f.model.num_faces);
        EXPECT_EQ(radius, 0.04);
    }
}

TEST(Fillet, EdgeByEdgeFollowsTheEdgesAnEarlierFilletLeftInPlace) {
    // The inner floor arc cannot take r = 0.5, so the fillets go one by one; the outer arc and its
    // rim come after a fillet that rebuilt their neighbours' faces, and must still be found.
    const BrepModel groove = load_shape(test::sample("groove"));
    std::vector<FilletRequest> req = groove_arcs(groove, 0.04, 3);
    ASSERT_EQ(req.size(), 2u);
    req[0].radius = 0.5;
    for (const FilletRequest& rim : groove_arcs(groove, 0.04, 1)) req.push_back(rim);
    ASSERT_EQ(req.size(), 4u);
    const FilletResult f = fillet_edges(groove, req);
    EXPECT_EQ(f.how, "edge by edge");
    EXPECT_FALSE(f.fillets[0].done);
    for (size_t i = 1; i < req.size(); ++i) EXPECT_TRUE(f.fillets[i].done) << "Edge" << req[i].edge << ": " << f.fillets[i].reason;
    EXPECT_EQ(f.fillet_faces.size(), 3u);
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
