// The fillet correction's rims (pipeline/fillet_plan.h): the convex edge across a strip face from
// a concave one, on the samples whose geometry is known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "framefix/brep/brep_model.h"
#include "framefix/pipeline/fillet_plan.h"

namespace framefix {
namespace {

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

std::vector<int> concave_edges(const FeatureSet& fs) {
    std::vector<int> out;
    for (const EdgeFeature& e : fs.edges)
        if (e.valence == 3) out.push_back(e.edge);
    return out;
}

// Distance of an edge's middle from the vertical axis through (1, 1), and its height.
Eigen::Vector2d radius_and_z(const BrepModel& m, int edge) {
    const Eigen::Vector3d p = edge_points(m, edge, 3).row(1).transpose();
    return {std::hypot(p.x() - 1, p.y() - 1), p.z()};
}

TEST(FilletRims, EachGrooveFloorArcHasTheRimAboveIt) {
    // groove.step: floor arcs of radii 0.4 and 0.6 about (1, 1) at z = 0.8, rims at z = 1.
    const BrepModel groove = load_shape(sample("groove"));
    const FeatureSet fs = classify_features(groove);
    const std::vector<int> floor = concave_edges(fs);
    ASSERT_EQ(floor.size(), 2u);
    for (int arc : floor) {
        const std::vector<int> rims = rims_of(groove, fs, arc);
        ASSERT_EQ(rims.size(), 1u) << "Edge" << arc;
        EXPECT_EQ(fs.valence_of(rims[0]), 1);
        EXPECT_NEAR(radius_and_z(groove, rims[0]).x(), radius_and_z(groove, arc).x(), 1e-6);
        EXPECT_NEAR(radius_and_z(groove, rims[0]).y(), 1, 1e-6);
    }
}

TEST(FilletRims, AHoleInAPlaneIsNoStrip) {
    // The half-sphere box's concave circle lies in the top face, whose outer edges are convex but
    // not at one distance from the circle: no rim. The notch's arc has its top edge across the wall.
    const BrepModel box = load_shape(sample("half_sphere_box"));
    const FeatureSet fs = classify_features(box);
    for (int circle : concave_edges(fs)) EXPECT_TRUE(rims_of(box, fs, circle).empty());
    const BrepModel notch = load_shape(sample("notch"));
    const FeatureSet nf = classify_features(notch);
    ASSERT_EQ(concave_edges(nf).size(), 1u);
    const std::vector<int> rims = rims_of(notch, nf, concave_edges(nf)[0]);
    ASSERT_EQ(rims.size(), 1u);
    EXPECT_NEAR(radius_and_z(notch, rims[0]).y(), 1, 1e-6);
}

}  // namespace
}  // namespace framefix
