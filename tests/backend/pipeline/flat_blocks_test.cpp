// Flat corners refined in the blocks (pipeline/flat_blocks.h): the notch's block under the snapped
// arc has a flat edge (paper Fig. 6b); the template cuts it in three (Fig. 6c) and the run's blocks
// become the hex mesh's blocks, tet by tet.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "framefix/pipeline/pipeline.h"

namespace framefix {
namespace {

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

RunResult notch(double factor, bool refine = true, double conform_tolerance = 0) {
    RunOptions o;
    o.stop_after = Stage::hexmesh;
    o.size_factor = factor;
    o.hexmesh.refine_flat = refine;
    if (conform_tolerance > 0) o.blocks.conform_tolerance = conform_tolerance, o.remesh_thin = false;
    return run(RunInput::file(sample("notch")), o);
}

TEST(FlatBlocks, TheNotchsFlatBlockIsCutIntoTheHexMeshsBlocks) {
    for (double f : {1.0, 0.7}) {
        SCOPED_TRACE(f);
        const RunResult r = notch(f);
        ASSERT_TRUE(r.flat && r.blocks && r.hexmesh && r.hexmesh->done);
        const BlockRefinement& flat = *r.flat;
        ASSERT_TRUE(flat.kept) << flat.reason;
        EXPECT_EQ(flat.refined, 1);
        EXPECT_EQ(flat.count_before, 7);  // the graph's blocks (the snapped notch)
        EXPECT_EQ(flat.conforming_before, 9);
        const BlockDecomposition& b = *r.blocks;
        EXPECT_EQ(b.count, 9);  // the flat block and the block along its edge, each in three
        EXPECT_EQ(b.valid, b.count);
        EXPECT_EQ(b.conforming_pairs, b.pairs);
        EXPECT_EQ(b.pairs, flat.pairs_before + 3);
        EXPECT_LT(b.flat_corners, flat.flat_corners_before);
        ASSERT_EQ(int(r.hexmesh->blocks.size()), b.count);  // the hexmesh stage meshed these blocks
        // Each block's tets fill what its hexes fill: ids agree, and the cut follows the template.
        std::vector<double> hexes(size_t(b.count), 0.0);
        for (size_t h = 0; h < r.hexmesh->hexes.size(); ++h) {
            std::array<Eigen::Vector3d, 8> p;
            for (int c = 0; c < 8; ++c) p[size_t(c)] = r.hexmesh->points.row(r.hexmesh->hexes[h][size_t(c)]).transpose();
            hexes[size_t(r.hexmesh->hex_block[h])] += hex_volume(p);
        }
        for (int k = 0; k < b.count; ++k)
            EXPECT_NEAR(b.blocks[size_t(k)].volume, hexes[size_t(k)], 0.15 * hexes[size_t(k)]) << "block " << k;
    }
}

TEST(FlatBlocks, TurnedOffTheBlocksStayAsCut) {
    const RunResult r = notch(1, false);
    ASSERT_TRUE(r.flat && r.blocks);
    EXPECT_FALSE(r.flat->tried);
    EXPECT_NE(r.flat->reason.find("turned off"), std::string::npos) << r.flat->reason;
    EXPECT_EQ(r.blocks->count, 7);
    EXPECT_EQ(r.flat->count_before, 7);
}

TEST(FlatBlocks, BlocksThatDoNotAllConformAreNotRefined) {
    // A conformity tolerance far below h fails every pair's corner test (hexmesh_test meshes them).
    const RunResult r = notch(1, true, 1e-6);
    ASSERT_TRUE(r.flat && r.blocks);
    EXPECT_FALSE(r.flat->tried);
    EXPECT_NE(r.flat->reason.find("not every block"), std::string::npos) << r.flat->reason;
    EXPECT_EQ(r.blocks->count, 7);
    ASSERT_TRUE(r.hexmesh && r.hexmesh->done);
    EXPECT_TRUE(r.hexmesh->refinement.kept);  // the hex mesh still refines its own complex
}

}  // namespace
}  // namespace framefix
