// A wedge shared between the two blocks it lies between (blocks/join_blocks.cpp, split_between), on
// the cube grid of tests/backend/mesh/cube_fixture.h: the cube is two blocks, x < 0.5 and x > 0.5,
// and a V-shaped wedge between them, its edge at z = 0.4 on x = 0.5, opening to the top.
#include <cmath>

#include <gtest/gtest.h>

#include "backend/blocks/cube_blocks.h"
#include "framefix/blocks/join_blocks.h"

namespace framefix {
namespace {

constexpr int kCells = 12;          // h ~ 0.1
constexpr double kEdgeZ = 0.4;      // the wedge's edge
constexpr double kHalfOpening = 0.3;  // the wedge's half-width per unit of height above its edge

int left_right_wedge(const Eigen::Vector3d& m) {
    if (m.z() > kEdgeZ && std::abs(m.x() - 0.5) < kHalfOpening * (m.z() - kEdgeZ)) return 2;
    return m.x() > 0.5 ? 1 : 0;
}

TEST(SplitWedge, AWedgeBetweenTwoBlocksIsSharedAtItsMiddle) {
    testing::CubeBlocks c = testing::cube_blocks(kCells);
    testing::label_blocks(c, 3, left_right_wedge);
    ASSERT_FALSE(c.blocks.blocks[2].valid);
    ASSERT_LT(c.blocks.blocks[2].faces, 6) << c.blocks.blocks[2].reason;
    const auto split = split_between(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks, c.v, 2, 0, 1);
    ASSERT_TRUE(split);
    const BlockDecomposition& b = split->first;
    EXPECT_EQ(b.count, 2);
    EXPECT_EQ(b.valid, 2);
    EXPECT_EQ(b.conforming_pairs, b.pairs);
    // Shared at its middle, not given to one side: the halves of the cube, within a staircase.
    for (const BlockInfo& x : b.blocks) EXPECT_NEAR(x.volume, 0.5, 0.02);
}

}  // namespace
}  // namespace framefix
