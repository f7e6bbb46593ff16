// Block decompositions with known answers (docs/algorithms.md#blocks): the cube is one block,
// the L-shaped prism three, the cylinder five (a centre block and four around it; needs h <= 0.035
// so that the outer blocks are >= 3 elements thick), the sphere seven (a cube and six around it), the
// tube four (quarters, cut at its ring),
// the notch after boundary snapping seven, all valid hexahedra, all neighbour pairs conforming,
// with the flat edge under the pocket reported.
// Every decomposition must cover the part exactly once with face-connected blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <memory>

#include "backend/corrections/cube_frames.h"
#include "framefix/blocks/blocks.h"
#include "framefix/core/disjoint_set.h"
#include "framefix/core/error.h"
#include "framefix/pipeline/pipeline.h"

namespace framefix {
namespace {

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

struct SampleRun {
    RunResult result;
    std::vector<SnappedPath> paths;
    BlockDecomposition blocks;
};

// One pipeline run per sample and mesh size (size 0: the default size times `factor`), shared by
// the tests of this file.
const SampleRun& run(const std::string& name, double size, double factor = 1) {
    static std::map<std::tuple<std::string, double, double>, std::unique_ptr<SampleRun>> cache;
    auto& slot = cache[{name, size, factor}];
    if (!slot) {
        slot = std::make_unique<SampleRun>();
        RunOptions options;
        options.stop_after = Stage::blocks;
        options.hexmesh.refine_flat = false;  // the blocks as the sheets cut them (the graph's)
        options.mesh.size = size;
        options.size_factor = factor;
        slot->result = framefix::run(RunInput::file(sample(name)), options);
        if (slot->result.correction) slot->paths = slot->result.correction->snap.paths;
        slot->blocks = *slot->result.blocks;
    }
    return *slot;
}

// Every tet in exactly one block, blocks face-connected, tet lists consistent with tet_block.
void expect_partition(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& d) {
    ASSERT_EQ(d.tet_block.size(), mesh.num_tets());
    ASSERT_EQ(int(d.blocks.size()), d.count);
    EXPECT_GE(d.tet_block.minCoeff(), 0);
    EXPECT_LT(d.tet_block.maxCoeff(), d.count);
    size_t listed = 0;
    double volume = 0, total = 0;
    for (int b = 0; b < d.count; ++b) {
        listed += d.blocks[b].tets.size();
        volume += d.blocks[b].volume;
        for (int t : d.blocks[b].tets) EXPECT_EQ(d.tet_block[t], b);
    }
    EXPECT_EQ(listed, size_t(mesh.num_tets()));
    for (int t = 0; t < mesh.num_tets(); ++t) total += tet_volume(mesh, t);
    EXPECT_NEAR(volume, total, 1e-9 * total);
    // Face-connectivity: union-find over faces inside one block gives one component per block.
    DisjointSet sets(mesh.num_tets());
    for (int f = 0; f < int(topo.face_tets.rows()); ++f) {
        const int a = topo.face_tets(f, 0), b = topo.face_tets(f, 1);
        if (b >= 0 && d.tet_block[a] == d.tet_block[b]) sets.unite(a, b);
    }
    for (int b = 0; b < d.count; ++b) {
        const int root = sets.find(d.blocks[b].tets.front());
        for (int t : d.blocks[b].tets) ASSERT_EQ(sets.find(t), root) << "block " << b << " is not face-connected";
    }
}

void expect_all_valid(const BlockDecomposition& d) {
    EXPECT_EQ(d.valid, d.count);
    for (int b = 0; b < d.count; ++b) {
        const BlockInfo& i = d.blocks[b];
        EXPECT_TRUE(i.valid) << "block " << b << ": " << i.reason;
        EXPECT_TRUE(i.reason.empty()) << "block " << b << " is valid but says: " << i.reason;
        EXPECT_EQ(i.faces, 6);
        EXPECT_EQ(i.edges, 12);
        EXPECT_EQ(i.corners, 8);
        EXPECT_EQ(i.euler, 2);
        EXPECT_TRUE(i.manifold);
    }
}

TEST(Blocks, CubeFixtureWithoutSingularitiesIsOneBlock) {
    const test::Cube c = test::cube_tets(6);
    const BlockDecomposition d = build_blocks(c.mesh, c.topo, c.features, c.field, SingularityGraph{}, {});
    EXPECT_EQ(d.count, 1);
    expect_all_valid(d);
    EXPECT_EQ(d.pairs, 0);
    EXPECT_EQ(d.flat_edges, 0);
    EXPECT_EQ(d.sheets.triangles.rows(), 0);
    expect_partition(c.mesh, c.topo, d);
}

TEST(Blocks, RejectsAFieldOfAnotherMesh) {
    const test::Cube c = test::cube_tets(3), other = test::cube_tets(2);
    EXPECT_THROW(build_blocks(c.mesh, c.topo, c.features, other.field, SingularityGraph{}, {}), Error);
}

TEST(BlocksOnSamples, CubeIsOneValidBlock) {
    const SampleRun& r = run("cube", 0.08);
    EXPECT_EQ(r.blocks.count, 1);
    expect_all_valid(r.blocks);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

TEST(BlocksOnSamples, LPrismIsThreeConformingBlocks) {
    const SampleRun& r = run("l_prism", 0.05);
    EXPECT_EQ(r.blocks.count, 3);
    expect_all_valid(r.blocks);
    EXPECT_EQ(r.blocks.pairs, 2);
    EXPECT_EQ(r.blocks.conforming_pairs, 2);
    EXPECT_EQ(r.blocks.flat_edges, 0);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

TEST(BlocksOnSamples, CylinderIsACentreAndFourBlocks) {
    const SampleRun& r = run("cylinder", 0.035);
    ASSERT_EQ(r.result.singularities->summary.valence3, 4);
    EXPECT_EQ(r.blocks.count, 5);
    expect_all_valid(r.blocks);
    EXPECT_EQ(r.blocks.pairs, 8);  // centre-outer 4, outer-outer 4
    EXPECT_EQ(r.blocks.conforming_pairs, r.blocks.pairs);
    // The centre block touches the four others, and contains the axis.
    int centre = -1;
    for (int b = 0; b < r.blocks.count; ++b)
        if (r.blocks.blocks[b].neighbours.size() == 4) centre = b;
    ASSERT_GE(centre, 0);
    EXPECT_LT(r.blocks.blocks[centre].centroid.head<2>().norm(), 0.05);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

TEST(BlocksOnSamples, SnappedNotchIsSevenConformingBlocks) {
    const SampleRun& r = run("notch", 0.05);
    ASSERT_EQ(r.paths.size(), 1u);
    EXPECT_EQ(r.result.singularities->summary.curves_3_5, 0);
    EXPECT_EQ(r.blocks.count, 7);
    expect_all_valid(r.blocks);
    EXPECT_EQ(r.blocks.pairs, 9);
    EXPECT_EQ(r.blocks.conforming_pairs, 9);
    // The path lies on the pocket's concave wall: it cuts the solid itself, no curtain corner.
    EXPECT_TRUE(r.blocks.convex_paths.empty());
    EXPECT_EQ(r.blocks.curtain_corners, 0);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

// A cube inside the sphere: 20 valence-3 curves (the cube's edges and 8 radial ones) cut it into
// the cube and six blocks over its faces, 7 hexahedra and 18 conforming pairs (12 around the
// cube's edges, 6 between the cube and the others). At the default size the radial curves are
// about 1.6 edges long, so each outer block has corners one mesh edge apart.
TEST(BlocksOnSamples, SphereIsACubeAndSixBlocksAtTwoSizes) {
    for (double f : {1.0, 0.7}) {
        SCOPED_TRACE("sphere at " + std::to_string(f));
        const SampleRun& r = run("sphere", 0, f);
        ASSERT_EQ(r.result.singularities->summary.valence3, 20);
        EXPECT_EQ(r.blocks.count, 7);
        expect_all_valid(r.blocks);
        EXPECT_EQ(r.blocks.pairs, 18);
        EXPECT_EQ(r.blocks.conforming_pairs, 18);
        int inner = 0;  // the cube touches the six others, and contains the centre
        for (const BlockInfo& b : r.blocks.blocks)
            if (b.neighbours.size() == 6) {
                ++inner;
                EXPECT_LT(b.centroid.norm(), 0.05);
            }
        EXPECT_EQ(inner, 1);
        expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
    }
}

// docs/algorithms.md#ring-cuts: the tube has no singular curve and no concave edge, so no sheet
// of the graph cuts it; its one block would be a solid torus. Four meridian sheets at quarter
// turns make four hexahedra, each a quarter of the tube (volume and angle), each meeting its two
// neighbours face to face.
TEST(BlocksOnSamples, TubeIsCutIntoFourQuartersAtTwoSizes) {
    for (double f : {1.0, 0.7}) {
        SCOPED_TRACE("tube at " + std::to_string(f));
        const SampleRun& r = run("tube", 0, f);
        ASSERT_EQ(r.result.singularities->summary.curves, 0);
        EXPECT_EQ(r.blocks.ring_cuts, 4);
        int ring_sources = 0;
        for (const std::string& k : r.blocks.sheets.source_kind) ring_sources += k.rfind("ring:", 0) == 0;
        EXPECT_EQ(ring_sources, 4);
        ASSERT_EQ(r.blocks.count, 4);
        expect_all_valid(r.blocks);
        EXPECT_EQ(r.blocks.pairs, 4);
        EXPECT_EQ(r.blocks.conforming_pairs, 4);
        std::vector<double> angles;
        for (const BlockInfo& b : r.blocks.blocks) {
            EXPECT_NEAR(b.volume, 0.30159 / 4, 0.15 * 0.30159 / 4);
            EXPECT_EQ(b.neighbours.size(), 2u);
            angles.push_back(std::atan2(b.centroid.y(), b.centroid.x()));
        }
        std::sort(angles.begin(), angles.end());
        for (int k = 0; k < 4; ++k)  // consecutive centroids a quarter turn apart
            EXPECT_NEAR(std::remainder(angles[(k + 1) % 4] - angles[k], 2 * M_PI), M_PI / 2, 0.2);
        expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
    }
}

// A part without a ring gets no ring cut.
TEST(BlocksOnSamples, NoRingNoRingCut) {
    EXPECT_EQ(run("sphere", 0).blocks.ring_cuts, 0);
    EXPECT_EQ(run("cylinder", 0.035).blocks.ring_cuts, 0);
}

// docs/algorithms.md#curtain-corners: the dome's snapped paths lie on a convex surface and emit
// no sheet; the four that reach the base circle give its curtain four corner lines. The part is
// then an O-grid of 9 columns around and below the dome, and the dome one block: 10 hexahedra.
TEST(BlocksOnSamples, SnappedSmallDomeIsAnOGridUnderOneDomeBlock) {
    const SampleRun& r = run("half_sphere_box_small", 0);
    ASSERT_FALSE(r.paths.empty());
    EXPECT_EQ(r.blocks.convex_paths.size(), r.paths.size());
    EXPECT_EQ(r.blocks.curtain_corners, 4);
    EXPECT_EQ(r.blocks.count, 10);
    expect_all_valid(r.blocks);
    EXPECT_EQ(r.blocks.conforming_pairs, r.blocks.pairs);
    int above = 0;  // blocks above the box top (z = 0): the dome only
    for (const BlockInfo& b : r.blocks.blocks) above += b.centroid.z() > 0;
    EXPECT_EQ(above, 1);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

// Every block valid and every pair conforming at the default size and at 0.7 x: the paper's
// half-sphere box (the dome over an O-grid, 10 blocks) and the wide groove (15 blocks: the
// island over its column, the ring below the groove floor cut in three by the island's curtain
// corner, the outer part cut by the outer path's sheets and by that corner's).
TEST(BlocksOnSamples, HalfSphereBoxAndWideGrooveAreValidAtTwoSizes) {
    for (auto [name, count] : {std::pair{"half_sphere_box", 10}, std::pair{"groove_wide", 15}})
        for (double f : {1.0, 0.7}) {
            SCOPED_TRACE(std::string(name) + " at " + std::to_string(f));
            const SampleRun& r = run(name, 0, f);
            EXPECT_EQ(r.blocks.count, count);
            expect_all_valid(r.blocks);
            EXPECT_EQ(r.blocks.conforming_pairs, r.blocks.pairs);
            expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
        }
}

// The groove's two snapped paths: the one on the island's wall (radius 0.4 about the corner
// (1, 1)) is convex and emits no sheet, so the island above the groove floor stays one valid
// block; the one on the outer wall (radius 0.6) is concave and keeps its sheets.
TEST(BlocksOnSamples, GrooveIslandPathIsConvexAndTheIslandOneBlock) {
    const SampleRun& r = run("groove", 0);
    ASSERT_EQ(r.paths.size(), 2u);
    ASSERT_EQ(r.blocks.convex_paths.size(), 1u);
    const Points& P = r.result.mesh->tets.points;
    for (size_t pi = 0; pi < r.paths.size(); ++pi) {
        const Eigen::Vector3d mid = P.row(r.paths[pi].vertices[r.paths[pi].vertices.size() / 2]).transpose();
        const double radius = (mid.head<2>() - Eigen::Vector2d(1, 1)).norm();
        const bool convex = r.blocks.convex_paths.front() == int(pi);
        EXPECT_NEAR(radius, convex ? 0.4 : 0.6, 0.02) << "path " << pi;
    }
    EXPECT_EQ(r.blocks.curtain_corners, 1);  // the island path's foot on the floor arc
    int island = -1;
    for (int b = 0; b < r.blocks.count; ++b) {
        const Eigen::Vector3d c = r.blocks.blocks[b].centroid;
        if (c.z() > 0.8 && (c.head<2>() - Eigen::Vector2d(1, 1)).norm() < 0.4) island = b;
    }
    ASSERT_GE(island, 0);
    EXPECT_TRUE(r.blocks.blocks[island].valid) << r.blocks.blocks[island].reason;
    bool corner_sheet = false;
    for (const std::string& k : r.blocks.sheets.source_kind) corner_sheet |= k.rfind("curtain:", 0) == 0;
    EXPECT_TRUE(corner_sheet);
    expect_partition(r.result.mesh->tets, r.result.mesh->topology, r.blocks);
}

TEST(BlocksOnSamples, SnappedNotchReportsTheFlatEdgeUnderThePocket) {
    const SampleRun& r = run("notch", 0.05);
    // The block under the pocket (x, y > 0.5, z < 0.5) has two faces on the continuation of the
    // pocket wall, split by the snapped path's sheets: a flat (180 deg) edge between them.
    int flat_under_pocket = 0, flat_elsewhere = 0;
    for (const BlockInfo& b : r.blocks.blocks) {
        const bool under = b.centroid.x() > 0.5 && b.centroid.y() > 0.5 && b.centroid.z() < 0.5;
        (under ? flat_under_pocket : flat_elsewhere) += b.flat_edges;
    }
    EXPECT_GE(flat_under_pocket, 1);
    EXPECT_EQ(flat_elsewhere, 0);
}

// A run up to the correction (snapping where the graph is not meshable), whose blocks are then
// made with or without the glued curves' sheets.
RunResult corrected(const std::string& name, double factor) {
    RunOptions options;
    options.stop_after = Stage::correction;
    options.size_factor = factor;
    return framefix::run(RunInput::file(sample(name)), options);
}

BlockDecomposition blocks_of(const RunResult& r, bool try_glued, int join_rounds = BlockOptions{}.join_rounds,
                             int prism_rounds = BlockOptions{}.prism_rounds, bool split_wedges = true) {
    BlockOptions o;
    o.split_wedges = split_wedges;
    o.try_glued = try_glued;
    o.join_rounds = join_rounds;
    o.prism_rounds = prism_rounds;
    static const std::vector<SnappedPath> no_paths;
    return build_blocks(r.mesh->tets, r.mesh->topology, r.mesh->features, r.field->frames, *r.singularities,
                        r.correction ? r.correction->snap.paths : no_paths, o);
}

TEST(BlocksOnSamples, GluedCurvesEmitSheetsOnlyWhereTheBlocksAreBetter) {
    // The chamfered box is one hexahedron: the curves glued to its chamfer must not cut it.
    const RunResult box = corrected("chamfer_box", 1);
    ASSERT_FALSE(box.singularities->absorbed.empty());
    ASSERT_TRUE(box.singularities->summary.meshable);
    const BlockDecomposition one = blocks_of(box, true);
    EXPECT_EQ(one.glued_sources, 0);
    EXPECT_EQ(one.count, 1);
    expect_all_valid(one);
    // The gusset at 0.8 x, snapped (its two 3-5 curves): its web's 45 and 225 degree edges carry
    // glued curves, and the blocks with their sheets have more valid blocks than without.
    const RunResult gusset = corrected("gusset", 0.8);
    ASSERT_FALSE(gusset.singularities->absorbed.empty());
    ASSERT_TRUE(gusset.singularities->summary.meshable);
    const BlockDecomposition with = blocks_of(gusset, true), without = blocks_of(gusset, false);
    EXPECT_GT(with.glued_sources, 0);
    EXPECT_EQ(without.glued_sources, 0);
    EXPECT_GT(2 * with.valid - with.count, 2 * without.valid - without.count);
    expect_partition(gusset.mesh->tets, gusset.mesh->topology, with);
}

int under_faced(const BlockDecomposition& d) {
    int n = 0;
    for (const BlockInfo& b : d.blocks) n += !b.valid && b.faces < 6;
    return n;
}

TEST(BlocksOnSamples, WedgesCutOffABlockJoinTheNeighbourTheyMakeAHexahedronWith) {
    // The wide groove with every curve filleted: its sheets cut wedges of 4 and 5 faces off
    // blocks next to the fillets; joined to a neighbour, each makes a hexahedron.
    const RunResult r = corrected("groove_wide_filleted", 1);
    const BlockDecomposition joined = blocks_of(r, true), apart = blocks_of(r, true, 0);
    EXPECT_EQ(apart.joined_blocks, 0);
    ASSERT_GT(joined.joined_blocks, 0);
    EXPECT_LT(under_faced(joined), under_faced(apart));
    EXPECT_LT(joined.count, apart.count);
    EXPECT_GE(joined.valid, apart.valid);  // each join makes a hexahedron: no valid block is lost
    EXPECT_GT(2 * joined.valid - joined.count, 2 * apart.valid - apart.count);
    expect_partition(r.mesh->tets, r.mesh->topology, joined);
}

TEST(BlocksOnSamples, AWedgeNoNeighbourTakesIsSharedBetweenTwo) {
    // The narrow groove: a 5-faced wedge that no single neighbour makes a hexahedron with; shared
    // between two, both are hexahedra, and a 7-faced block beside it is one too.
    const RunResult r = corrected("groove_narrow", 1);
    const BlockDecomposition split = blocks_of(r, true), apart = blocks_of(r, true, 10, 20, false);
    EXPECT_EQ(apart.split_blocks, 0);
    ASSERT_GT(split.split_blocks, 0);
    EXPECT_LT(under_faced(split), under_faced(apart));
    EXPECT_GE(split.valid, apart.valid);
    EXPECT_LT(split.count - split.valid, apart.count - apart.valid);
    EXPECT_GE(split.conforming_pairs - split.pairs, apart.conforming_pairs - apart.pairs);
    expect_partition(r.mesh->tets, r.mesh->topology, split);
}

TEST(BlocksOnSamples, PrismBlocksAreCutIntoHexahedra) {
    // The half-sphere box with its concave circle filleted: a block around the fillet is a
    // pentagon extruded, one of its sides on the part's boundary; cut from the opposite edge to
    // the middle of that side, it makes two hexahedra.
    const RunResult r = corrected("half_sphere_box_filleted", 1);
    const BlockDecomposition cut = blocks_of(r, true), whole = blocks_of(r, true, BlockOptions{}.join_rounds, 0);
    EXPECT_EQ(whole.prism_cuts, 0);
    ASSERT_GT(cut.prism_cuts, 0);
    EXPECT_GT(cut.valid, whole.valid);
    EXPECT_LE(cut.pairs - cut.conforming_pairs, whole.pairs - whole.conforming_pairs);
    expect_partition(r.mesh->tets, r.mesh->topology, cut);
}

TEST(BlocksOnSamples, SheetsAreTaggedWithTheirSources) {
    const SampleRun& r = run("notch", 0.05);
    const SheetSoup& s = r.blocks.sheets;
    ASSERT_GT(s.triangles.rows(), 0);
    EXPECT_EQ(s.source.size(), s.triangles.rows());
    EXPECT_GE(s.source.minCoeff(), 0);
    EXPECT_LT(s.source.maxCoeff(), int(s.source_kind.size()));
    EXPECT_LT(s.triangles.maxCoeff(), s.points.rows());
    bool concave = false, snapped = false;
    for (const std::string& k : s.source_kind) concave |= k.rfind("concave:", 0) == 0, snapped |= k.rfind("snapped:", 0) == 0;
    EXPECT_TRUE(concave);
    EXPECT_TRUE(snapped);
}

}  // namespace
}  // namespace framefix
