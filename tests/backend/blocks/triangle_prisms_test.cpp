// fold_triangle_prisms on the cube grid of tests/backend/mesh/cube_fixture.h cut along a diagonal
// plane into two triangular prisms (a wedge each): its caps and two of its sides on the cube's
// boundary, the diagonal shared.
#include <gtest/gtest.h>

#include <vector>

#include "backend/blocks/cube_blocks.h"
#include "framefix/blocks/triangle_prisms.h"

namespace framefix {
namespace {

constexpr int kCells = 12;  // h ~ 0.1, the wedges' sides 1 and 1.4 long

using Wedges = testing::CubeBlocks;

Wedges diagonal_wedges() {
    Wedges w = testing::cube_blocks(kCells);
    testing::label_blocks(w, 2, [](const Eigen::Vector3d& c) { return c.x() > c.y() ? 0 : 1; });  // along tet faces
    return w;
}

TEST(TrianglePrisms, EachWedgeSplitsABoundarySideAndBecomesAHexahedron) {
    Wedges w = diagonal_wedges();
    for (const BlockInfo& b : w.blocks.blocks) {
        ASSERT_FALSE(b.valid);
        ASSERT_EQ(b.reason, "faces 5");
        ASSERT_EQ(b.corners, 6);
    }
    fold_triangle_prisms(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks, w.v);
    EXPECT_EQ(w.blocks.triangle_folds, 2);
    EXPECT_EQ(w.blocks.valid, 2);
    EXPECT_EQ(w.blocks.conforming_pairs, 1) << "the diagonal keeps its 4 corners on both sides";
    for (int b = 0; b < 2; ++b) {
        const BlockInfo& info = w.blocks.blocks[size_t(b)];
        EXPECT_TRUE(info.valid) << info.reason;
        EXPECT_GE(info.flat_edges, 1) << "the split side meets itself at 180 degrees";
        const std::vector<int>& label = w.v.faces[size_t(b)].label;
        EXPECT_EQ(std::count(label.begin(), label.end(), 1 - b), 1) << "the shared diagonal is not split";
    }
}

TEST(TrianglePrisms, AHexahedronIsLeftAlone) {
    Wedges w = diagonal_wedges();
    testing::label_blocks(w, 1, [](const Eigen::Vector3d&) { return 0; });
    ASSERT_EQ(w.blocks.valid, 1);
    fold_triangle_prisms(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks, w.v);
    EXPECT_EQ(w.blocks.triangle_folds, 0);
    EXPECT_EQ(w.v.faces[0].label.size(), 6u);
}

}  // namespace
}  // namespace framefix
