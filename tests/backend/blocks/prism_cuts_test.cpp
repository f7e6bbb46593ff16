// prism_of and prism_cut_sides on block faces written down by hand: an n-gon extruded has two
// n-cornered caps and n quads around them, corner i of the bottom cap under corner n + i of the top.
#include <gtest/gtest.h>

#include <vector>

#include "framefix/blocks/prism_cuts.h"

namespace framefix {
namespace {

// Patches 0..n-1 the laterals (lateral i between corners i and i + 1), n the bottom cap, n + 1 the top.
struct PrismFaces {
    BlockFaces faces;
    BlockInfo info;
};

PrismFaces prism_faces(int n) {
    PrismFaces p;
    for (int level = 0; level < 2; ++level)
        for (int i = 0; i < n; ++i) {
            std::vector<int> patches{(i + n - 1) % n, i, n + level};
            std::sort(patches.begin(), patches.end());
            p.faces.corner_patches.push_back(patches);
            p.faces.corner_position.push_back(Eigen::Vector3d(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), level));
        }
    p.faces.label.assign(size_t(n + 2), -1);
    p.info.manifold = true;
    p.info.euler = 2;
    p.info.faces = n + 2, p.info.edges = 3 * n, p.info.corners = 2 * n;
    return p;
}

TEST(PrismCuts, APentagonExtrudedIsAPrismItsLateralsInCyclicOrder) {
    const PrismFaces p = prism_faces(5);
    const std::optional<Prism> prism = prism_of(p.faces, p.info);
    ASSERT_TRUE(prism);
    EXPECT_EQ(prism->n, 5);
    EXPECT_EQ(std::min(prism->caps[0], prism->caps[1]), 5);
    ASSERT_EQ(prism->laterals.size(), 5u);
    for (int i = 0; i < 5; ++i) {  // consecutive laterals are neighbours in the pentagon
        const int a = prism->laterals[i], b = prism->laterals[(i + 1) % 5];
        EXPECT_TRUE((a + 1) % 5 == b || (b + 1) % 5 == a) << i;
    }
    for (const auto& e : prism->edge) EXPECT_EQ(std::abs(e[0] - e[1]), 5);  // one corner per cap, one above the other
}

TEST(PrismCuts, HexahedraTrianglesAndBrokenShapesAreNoPrisms) {
    for (int n : {3, 4}) {  // a triangle needs three cuts (not done); four sides is a hexahedron
        const PrismFaces p = prism_faces(n);
        EXPECT_FALSE(prism_of(p.faces, p.info)) << n;
    }
    PrismFaces p = prism_faces(6);
    p.info.euler = 0;  // a ring
    EXPECT_FALSE(prism_of(p.faces, p.info));
    p = prism_faces(6);
    p.faces.corner_patches[0].push_back(7);  // a corner of four faces
    EXPECT_FALSE(prism_of(p.faces, p.info));
}

TEST(PrismCuts, AHexagonIsCutBetweenOppositeEdgesIntoTwoQuads) {
    const PrismFaces p = prism_faces(6);
    const std::optional<Prism> prism = prism_of(p.faces, p.info);
    ASSERT_TRUE(prism);
    const auto cuts = prism_cut_sides(*prism);
    EXPECT_EQ(cuts.size(), 3u);  // three pairs of opposite lateral edges
    for (const std::vector<int>& side : cuts)
        EXPECT_EQ(std::count(side.begin(), side.end(), 0), 3);  // three faces and the cut on each side
}

TEST(PrismCuts, AnOddPrismIsCutAcrossALateralFaceWhichMayBeANeighbours) {
    PrismFaces p = prism_faces(5);
    p.faces.label = {3, 4, 5, 6, 7, -1, -1};  // every lateral face shared with another block
    std::optional<Prism> prism = prism_of(p.faces, p.info);
    ASSERT_TRUE(prism);
    const auto cuts = prism_cut_sides(*prism);
    ASSERT_EQ(cuts.size(), 5u) << "one from each lateral edge";
    for (const std::vector<int>& side : cuts) {
        EXPECT_EQ(std::count(side.begin(), side.end(), 2), 1);
        EXPECT_EQ(std::count(side.begin(), side.end(), 0), 2);  // two faces, half of the third and the cut
        EXPECT_EQ(std::count(side.begin(), side.end(), 1), 2);
        EXPECT_TRUE(cuts_a_neighbour_across(*prism, side, p.faces.label));
    }
    p.faces.label[2] = -1;  // lateral 2 on the part's boundary
    int alone = 0;
    for (const std::vector<int>& side : cuts)
        if (!cuts_a_neighbour_across(*prism, side, p.faces.label)) {
            ++alone;
            for (int i = 0; i < 5; ++i) EXPECT_EQ(side[i] == 2, prism->laterals[i] == 2) << i;
        }
    EXPECT_EQ(alone, 1) << "only the cut across lateral 2 leaves the neighbours whole";
}

}  // namespace
}  // namespace framefix
