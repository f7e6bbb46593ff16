// Prism cuts carried through a neighbour (blocks/carried_cuts.cpp), on the cube grid of
// tests/backend/mesh/cube_fixture.h split at z = 0.5: the lower half's side y = 0 is two CAD faces
// (x < 0.5 and x > 0.5), which makes it a pentagonal prism under the upper half, a hexahedron.
#include <gtest/gtest.h>

#include "backend/blocks/cube_blocks.h"
#include "framefix/blocks/prism_cuts.h"

namespace framefix {
namespace {

constexpr int kCells = 12;     // h ~ 0.1; 0.5 is a grid plane
constexpr int kSplitTag = 7;   // the cube's faces are tagged 1..6

Eigen::Vector3d face_centre(const testing::CubeBlocks& c, int f) {
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) m += c.mesh.points.row(c.topo.faces(f, k)).transpose() / 3;
    return m;
}

// The boundary triangles where `where(centre)` holds get their own surface group.
template <class Where>
void split_group(testing::CubeBlocks& c, Where where) {
    for (int f = 0; f < int(c.topo.faces.rows()); ++f)
        if (c.group[size_t(f)] >= 0 && where(face_centre(c, f))) c.group[size_t(f)] = kSplitTag;
}

// `split_x`: where the lower half's side y = 0 changes CAD face.
testing::CubeBlocks prism_under_a_hexahedron(double split_x = 0.5) {
    testing::CubeBlocks c = testing::cube_blocks(kCells);
    split_group(c, [&](const Eigen::Vector3d& m) { return m.y() < 1e-9 && m.z() < 0.5 && m.x() < split_x; });
    return c;
}

int lower_and_upper(const Eigen::Vector3d& m) { return m.z() > 0.5 ? 1 : 0; }

TEST(CarriedCuts, APentagonalPrismsCutRunsOnThroughTheHexahedronOnItsCap) {
    testing::CubeBlocks c = prism_under_a_hexahedron();
    testing::label_blocks(c, 2, lower_and_upper);
    ASSERT_FALSE(c.blocks.blocks[0].valid);
    ASSERT_TRUE(prism_of(c.v.faces[0], c.blocks.blocks[0])) << c.blocks.blocks[0].reason;
    ASSERT_TRUE(c.blocks.blocks[1].valid) << c.blocks.blocks[1].reason;
    cut_prisms(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks, c.v);
    EXPECT_EQ(c.blocks.prism_cuts, 1);
    EXPECT_EQ(c.blocks.carried_cuts, 1);
    EXPECT_EQ(c.blocks.count, 4) << "the prism and the block above, each in two";
    EXPECT_EQ(c.blocks.valid, 4);
    EXPECT_EQ(c.blocks.pairs, 4);
    EXPECT_EQ(c.blocks.conforming_pairs, 4);
    for (const BlockInfo& b : c.blocks.blocks) EXPECT_NEAR(b.volume, 0.25, 0.01) << "cut at x = 0.5";
}

TEST(CarriedCuts, ACutThatCrossesAFaceNearItsEndRunsOnToo) {
    // Two cells of twelve: the cut crosses the upper block's side y = 0 where its vertices read
    // nearly all on one side.
    testing::CubeBlocks c = prism_under_a_hexahedron(2.0 / kCells);
    testing::label_blocks(c, 2, lower_and_upper);
    ASSERT_TRUE(prism_of(c.v.faces[0], c.blocks.blocks[0])) << c.blocks.blocks[0].reason;
    cut_prisms(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks, c.v);
    EXPECT_EQ(c.blocks.carried_cuts, 1);
    EXPECT_EQ(c.blocks.count, 4);
    EXPECT_EQ(c.blocks.valid, 4);
    EXPECT_EQ(c.blocks.conforming_pairs, c.blocks.pairs);
}

TEST(CarriedCuts, ASheetThatComesRoundToABlockItCutCloses) {
    // Four blocks, two by two in y and z: the prism at y, z < 0.5 is cut at x = 0.5 across its
    // side y = 0.5, which carries the cut into the block beside it, and its cap into the block
    // above; both carry it into the fourth block, which is cut once.
    testing::CubeBlocks c = prism_under_a_hexahedron();
    testing::label_blocks(c, 4, [](const Eigen::Vector3d& m) { return (m.z() > 0.5) + 2 * (m.y() > 0.5); });
    ASSERT_TRUE(prism_of(c.v.faces[0], c.blocks.blocks[0])) << c.blocks.blocks[0].reason;
    ASSERT_EQ(c.blocks.valid, 3);
    cut_prisms(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks, c.v);
    EXPECT_EQ(c.blocks.carried_cuts, 1);
    EXPECT_EQ(c.blocks.count, 8);
    EXPECT_EQ(c.blocks.valid, 8);
    EXPECT_EQ(c.blocks.conforming_pairs, c.blocks.pairs);
    for (const BlockInfo& b : c.blocks.blocks) EXPECT_NEAR(b.volume, 0.125, 0.01) << "cut at x = 0.5";
}

TEST(CarriedCuts, APrismUnderABlockThatIsNoHexahedronIsCutAlone) {
    testing::CubeBlocks c = prism_under_a_hexahedron();
    split_group(c, [](const Eigen::Vector3d& m) {  // a square at a corner of the top: 7 faces, no prism
        return m.z() > 1 - 1e-9 && m.x() < 0.4 && m.y() < 0.4;
    });
    testing::label_blocks(c, 2, lower_and_upper);
    ASSERT_FALSE(c.blocks.blocks[1].valid);
    ASSERT_FALSE(prism_of(c.v.faces[1], c.blocks.blocks[1]));
    cut_prisms(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks, c.v);
    EXPECT_EQ(c.blocks.prism_cuts, 1) << "the prism alone: no valid block is lost";
    EXPECT_EQ(c.blocks.carried_cuts, 0);
    EXPECT_EQ(c.blocks.count, 3);
    EXPECT_EQ(c.blocks.valid, 2);
}

}  // namespace
}  // namespace framefix
