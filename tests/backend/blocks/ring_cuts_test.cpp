// Meridian cuts of rings (blocks/ring_cuts.h) on the tube sample, its wall split by radius into two
// concentric rings: both go round the same hole, and the meridians of the larger (the outer,
// r > 0.4), which run to the boundary both ways, cross the inner one too. So the tube gets four
// meridians, not eight at two sets of angles that would cut slivers between them.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "framefix/blocks/ambiguous_edges.h"
#include "framefix/blocks/partition.h"
#include "framefix/blocks/ring_cuts.h"
#include "framefix/blocks/validation.h"
#include "framefix/pipeline/pipeline.h"

namespace framefix {
namespace {

constexpr double kSplitRadius = 0.4;  // the tube's wall runs from r = 0.3 to 0.5

TEST(RingCuts, ConcentricRingsShareOneSetOfMeridians) {
    RunOptions options;
    options.stop_after = Stage::singularities;
    const RunResult r = run(RunInput::file(std::string(FRAMEFIX_SAMPLES_DIR) + "/tube.step"), options);
    const TetMesh& mesh = r.mesh->tets;
    const TetTopology& topo = r.mesh->topology;
    const double h = mean_edge_length(mesh, topo, 1);
    BlockDecomposition blocks;
    blocks.count = 2;
    blocks.tet_block.resize(mesh.num_tets());
    for (int t = 0; t < mesh.num_tets(); ++t) {
        const Eigen::Vector3d m = tet_centroid(mesh, t);
        blocks.tet_block[t] = std::hypot(m.x(), m.y()) > kSplitRadius ? 0 : 1;
    }
    blocks.tet_block = clean_staircase(mesh, topo, blocks.tet_block);  // a manifold boundary, as the partition's
    ASSERT_EQ(compact_labels(blocks.tet_block), 2);
    const std::vector<int> group = surface_groups(mesh, topo, r.mesh->features, {}, {});
    const Validated v = validate_blocks(mesh, topo, group, h, BlockOptions{}, blocks);
    for (const BlockInfo& b : blocks.blocks) ASSERT_TRUE(b.manifold && b.euler == 0) << "both blocks are rings";

    const TetLocator locator(mesh, topo);
    TraceOptions trace;
    trace.step = 0.4 * h, trace.stop_distance = 1.5 * h;
    const std::vector<SheetSource> rings = ring_sources(mesh, r.field->frames, locator, blocks, v.surface, h, trace);
    ASSERT_EQ(rings.size(), 4u);
    for (const SheetSource& s : rings) {
        EXPECT_EQ(s.name, "ring:0");  // the outer ring is the larger
        double r_min = 1, r_max = 0;  // each meridian crosses the whole wall
        for (const SheetSeed& seed : s.seeds) {
            const double rad = std::hypot(seed.point.x(), seed.point.y());
            r_min = std::min(r_min, rad), r_max = std::max(r_max, rad);
        }
        EXPECT_LT(r_min, 0.3 + 1.5 * h);
        EXPECT_GT(r_max, 0.5 - 1.5 * h);
    }
}

}  // namespace
}  // namespace framefix
