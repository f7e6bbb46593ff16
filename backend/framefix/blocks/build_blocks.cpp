#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <omp.h>

#include "framefix/blocks/ambiguous_edges.h"
#include "framefix/blocks/block_surfaces.h"
#include "framefix/blocks/blocks.h"
#include "framefix/blocks/curtain_corners.h"
#include "framefix/blocks/join_blocks.h"
#include "framefix/blocks/partition.h"
#include "framefix/blocks/prism_cuts.h"
#include "framefix/blocks/ring_cuts.h"
#include "framefix/blocks/sheets.h"
#include "framefix/blocks/triangle_prisms.h"
#include "framefix/blocks/validation.h"
#include "framefix/core/disjoint_set.h"
#include "framefix/core/error.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check_inputs(const TetMesh& mesh, const TetTopology& topo, const FrameField& field, const SingularityGraph& graph) {
    const std::string nv = std::to_string(mesh.num_vertices());
    if (field.axes.rows() != mesh.num_vertices() || field.coefficients.rows() != mesh.num_vertices())
        throw Error("blocks", "frame field has " + std::to_string(field.axes.rows()) + " rows for " + nv +
                                  " vertices; solve the field on this mesh");
    if (topo.tet_faces.rows() != mesh.num_tets())
        throw Error("blocks", "topology has " + std::to_string(topo.tet_faces.rows()) + " tets, mesh " +
                                  std::to_string(mesh.num_tets()) + "; rebuild the topology");
    if (!graph.face_valence.empty() && int(graph.face_valence.size()) != int(topo.faces.rows()))
        throw Error("blocks", "singularity graph has " + std::to_string(graph.face_valence.size()) +
                                  " faces, topology " + std::to_string(topo.faces.rows()) + "; re-extract singularities");
}

// Each block with at most 3 faces joins the neighbour it shares the most boundary triangles with
// (a non-lens one first). A ring of 3 faces does so only with options.ring_lenses, and is counted
// in out.ring_lenses (docs/algorithms.md#lenses). True if any block changed.
bool merge_lenses(const std::vector<std::map<int, int>>& shared, const BlockOptions& options, BlockDecomposition& out) {
    auto ring = [&](int b) {
        const BlockInfo& i = out.blocks[b];
        return i.manifold && i.euler == 0 && i.faces == 3;
    };
    auto lens = [&](int b) {
        const BlockInfo& i = out.blocks[b];
        return i.faces <= 3 && !i.neighbours.empty() && (options.ring_lenses || !ring(b));
    };
    for (int b = 0; b < out.count; ++b) out.ring_lenses += lens(b) && ring(b);
    std::vector<int> into(out.count, -1);
    for (int b = 0; b < out.count; ++b) {
        if (!lens(b)) continue;
        int best = -1;
        for (int o : out.blocks[b].neighbours)
            if (best < 0 || (lens(best) && !lens(o)) ||
                (lens(best) == lens(o) && shared[b].at(o) > shared[b].at(best)))
                best = o;
        into[b] = best;
    }
    bool any = false;
    for (int b = 0; b < out.count; ++b) {
        if (into[b] < 0 || (lens(into[b]) && into[into[b]] == b && b < into[b])) continue;  // no swaps
        any = true;
    }
    if (!any) return false;
    for (int t = 0; t < int(out.tet_block.size()); ++t) {
        const int b = out.tet_block[t];
        if (into[b] >= 0 && !(into[into[b]] == b && b < into[b])) out.tet_block[t] = into[b];
    }
    return true;
}

// A concave curve's direction jumps this close to a curtain corner's foot (in h) are the corner's
// own turn: the corner line emits it (curtain_corners.h).
constexpr double kMuteReach = 3;

// Sources of the corner lines below the convex paths' feet (docs/algorithms.md#curtain-corners).
void add_curtain_corners(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                         const std::vector<FeatureSeeds>& curves, const std::vector<SnappedPath>& paths,
                         const std::vector<char>& convex, const Points& singular, double h,
                         const BlockOptions& options, std::vector<SheetSource>& sources, BlockDecomposition& out) {
    TraceOptions trace;
    trace.step = options.step * h, trace.stop_distance = options.stop_distance * h, trace.singular_points = singular;
    std::vector<SheetSource> corners = curtain_corner_sources(mesh, field, locator, curves, paths, convex, h, trace);
    out.curtain_corners = int(corners.size());
    mute_jumps_near_corners(sources, corners, kMuteReach * h);
    sources.insert(sources.end(), corners.begin(), corners.end());
}

// Staircase cleaning, then (with `merge`) the few tets it can cut off a block merged into a
// neighbour, and the staircase cleaned again where that happened; `merged` counts those pieces.
Eigen::VectorXi clean_labels(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi lab,
                             const BlockOptions& options, bool merge, int& merged) {
    lab = clean_staircase(mesh, topo, std::move(lab));
    if (!merge) return lab;
    const Eigen::VectorXi before = lab;
    const int m = merge_small_pieces(topo, lab, small_piece_tets(mesh.num_tets(), options));
    merged += m + (m == 0 && lab != before);  // a block in two big pieces is two blocks now
    return m > 0 ? clean_staircase(mesh, topo, std::move(lab)) : lab;
}

// Cut edges from the sheets and the singular-curve tubes, the vertex partition, its cleaning,
// then validation with the lens rounds (docs/algorithms.md#partition).
Validated partition_and_validate(const TetMesh& mesh, const TetTopology& topo, const Points& singular,
                                 const std::vector<int>& group, double h, const BlockOptions& options,
                                 BlockDecomposition& out, bool merge, int& merged) {
    const auto t1 = Clock::now();
    std::vector<char> cut = cut_by_sheets(mesh, topo, out.sheets, options.threads);
    cut_near_polylines(mesh, topo, singular, options.tube_radius * h, cut);
    out.stats.cut_edges = int(std::count(cut.begin(), cut.end(), 1));
    out.tet_block = clean_labels(mesh, topo, partition_tets(mesh, topo, cut, options), options, merge, merged);
    out.count = compact_labels(out.tet_block);
    out.seconds_partition += since(t1);
    const auto t2 = Clock::now();
    Validated v = validate_blocks(mesh, topo, group, h, options, out);
    for (int round = 0; round < options.lens_rounds && merge_lenses(v.shared, options, out); ++round) {
        out.tet_block = clean_labels(mesh, topo, out.tet_block, options, merge, merged);
        out.count = compact_labels(out.tet_block);
        v = validate_blocks(mesh, topo, group, h, options, out);
    }
    out.seconds_validation += since(t2);
    return v;
}

// `more`'s triangles and sources after `soup`'s.
void append_sheets(SheetSoup& soup, const SheetSoup& more) {
    const Eigen::Index np = soup.points.rows(), nt = soup.triangles.rows();
    const int ns = int(soup.source_kind.size());
    soup.points.conservativeResize(np + more.points.rows(), 3);
    soup.points.bottomRows(more.points.rows()) = more.points;
    soup.triangles.conservativeResize(nt + more.triangles.rows(), 3);
    soup.triangles.bottomRows(more.triangles.rows()) = more.triangles.array() + int(np);
    soup.source.conservativeResize(nt + more.source.size());
    soup.source.tail(more.source.size()) = more.source.array() + ns;
    soup.source_kind.insert(soup.source_kind.end(), more.source_kind.begin(), more.source_kind.end());
}

// Partition, validation and conformity of the sheets in `out`. Where merging the pieces that the
// staircase cleaning cut off changed the blocks, they are made again without it and the better
// kept (on a tie, the merged ones): on 2 of the 33 part-size runs it changed, the merge lost a
// valid block (HexMe s05o and n05o at 1 x).
Validated partition_best(const TetMesh& mesh, const TetTopology& topo, const Points& singular,
                         const std::vector<int>& group, double h, const BlockOptions& options, BlockDecomposition& out) {
    BlockDecomposition plain = out;
    const double partition0 = out.seconds_partition, validation0 = out.seconds_validation;
    int merged = 0;
    Validated v = partition_and_validate(mesh, topo, singular, group, h, options, out, true, merged);
    count_conformity(v, h, options, out);
    if (merged == 0) return v;
    int unused = 0;
    Validated w = partition_and_validate(mesh, topo, singular, group, h, options, plain, false, unused);
    count_conformity(w, h, options, plain);
    // Both tries' time: each copy started from the same earlier time.
    const double seconds_partition = out.seconds_partition + plain.seconds_partition - partition0,
                 seconds_validation = out.seconds_validation + plain.seconds_validation - validation0;
    if (score(plain) > score(out)) out = std::move(plain), v = std::move(w);
    out.seconds_partition = seconds_partition, out.seconds_validation = seconds_validation;
    return v;
}

bool has_junction(const std::vector<SheetSource>& sources) {
    for (const SheetSource& s : sources)
        if (s.junction[0] >= 0 || s.junction[1] >= 0) return true;
    return false;
}

// The configured mode first; with try_junctions and a junction node in the graph, the others
// (those that zip only where a curve runs straight on through the node). Older modes come first,
// so that on a tie their blocks stay.
std::vector<BlockOptions::Junctions> junction_modes(const std::vector<SheetSource>& sources, const BlockOptions& o) {
    using J = BlockOptions::Junctions;
    std::vector<J> modes{o.junctions};
    if (!o.try_junctions || !has_junction(sources)) return modes;
    const bool straight = has_straight_junction(sources);
    for (J m : {J::Continue, J::Drop, J::DropAndClose, J::DropAndZip, J::DropCloseAndZip, J::ContinueAndClose})
        if (m != o.junctions && (straight || (m != J::DropAndZip && m != J::DropCloseAndZip))) modes.push_back(m);
    return modes;
}

const char* junction_name(BlockOptions::Junctions m) {
    switch (m) {
        case BlockOptions::Junctions::Continue: return "continue";
        case BlockOptions::Junctions::Drop: return "drop";
        case BlockOptions::Junctions::DropAndClose: return "drop+close";
        case BlockOptions::Junctions::DropAndZip: return "drop+zip";
        case BlockOptions::Junctions::DropCloseAndZip: return "drop+close+zip";
        case BlockOptions::Junctions::ContinueAndClose: return "continue+close";
    }
    return "";
}

// Sheets, partition and validation once per junction mode (junction_modes); `out` (holding what
// the tries share) becomes the best try by score, with every try listed when the graph has a
// junction node.
Validated best_junction_mode(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                             const TetLocator& locator, const std::vector<SheetSource>& sources, const Points& singular,
                             const std::vector<int>& group, double h, const BlockOptions& options,
                             BlockDecomposition& out) {
    Validated v;
    const BlockDecomposition common = out;
    const std::vector<BlockOptions::Junctions> modes = junction_modes(sources, options);
    double sheet_seconds = 0;
    std::vector<BlockDecomposition::JunctionTry> tries;
    for (size_t i = 0; i < modes.size(); ++i) {
        BlockOptions o = options;
        o.junctions = modes[i];
        BlockDecomposition tried = common;
        const auto t1 = Clock::now();
        tried.sheets = build_sheets(mesh, field, locator, sources, singular, h, o, tried.stats);
        sheet_seconds += since(t1);
        Validated w = partition_best(mesh, topo, singular, group, h, o, tried);
        tries.push_back({junction_name(modes[i]), tried.count, tried.valid, tried.pairs, tried.conforming_pairs});
        if (i == 0 || score(tried) > score(out)) out = std::move(tried), v = std::move(w), out.junction_mode = junction_name(modes[i]);
    }
    if (has_junction(sources)) out.junction_tries = std::move(tries);
    else out.junction_mode.clear();
    out.seconds_sheets = sheet_seconds;
    return v;
}

// What every partition of one build_blocks call shares.
struct BlockInputs {
    const TetMesh& mesh;
    const TetTopology& topo;
    const FeatureSet& features;
    const FrameField& field;
    const TetLocator& locator;
    const std::vector<SnappedPath>& paths;
    const std::vector<int>& group;  // surface_groups
    double h;
    const BlockOptions& options;
};

// Under-faced blocks joined or shared, prisms cut, triangles folded, each change kept when better.
void mend(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
          const BlockOptions& options, BlockDecomposition& out, Validated& v) {
    join_under_faced(mesh, topo, group, h, options, out, v);
    cut_prisms(mesh, topo, group, h, options, out, v);
    fold_triangle_prisms(mesh, topo, group, h, options, out, v);
}

// mend, and where it shared a wedge between two blocks, mend again without: a wedge shared early
// can take the place of a join or a cut that would have done better (notch_shallow at 1.5 x, 6
// of 6 blocks valid and 7 of 8 pairs conforming against 7 of 7 and 8 of 9). The better is kept,
// on a tie the one without.
void mend_best(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
               const BlockOptions& options, BlockDecomposition& out, Validated& v) {
    BlockDecomposition plain = out;
    Validated w = v;
    mend(mesh, topo, group, h, options, out, v);
    if (out.split_blocks == 0) return;
    BlockOptions no_splits = options;
    no_splits.split_wedges = false;
    mend(mesh, topo, group, h, no_splits, plain, w);
    if (!(score(out) > score(plain))) out = std::move(plain), v = std::move(w);
}

// Sheets from `sources`, partition and validation in each junction mode, rings cut where that
// helps, ambiguous edges joined: `out`, holding what the tries share, becomes the best blocks.
Validated blocks_from_sources(const BlockInputs& in, const std::vector<SheetSource>& sources, const Points& singular,
                              BlockDecomposition& out) {
    Validated v = best_junction_mode(in.mesh, in.topo, in.field, in.locator, sources, singular, in.group, in.h,
                                     in.options, out);
    // Rings (a tube): no sheet above cuts them across; meridian sheets do, then all again, kept
    // only when the blocks are better (on HexMe's n10o at 0.7 x they were not).
    TraceOptions trace;
    trace.step = in.options.step * in.h, trace.stop_distance = in.options.stop_distance * in.h;
    trace.singular_points = singular;
    const std::vector<SheetSource> rings = ring_sources(in.mesh, in.field, in.locator, out, v.surface, in.h, trace);
    if (!rings.empty()) {
        BlockDecomposition cut = out;
        const auto t3 = Clock::now();
        append_sheets(cut.sheets, build_sheets(in.mesh, in.field, in.locator, rings, singular, in.h, in.options, cut.stats));
        cut.ring_cuts = int(rings.size());
        cut.seconds_sheets += since(t3);
        Validated w = partition_best(in.mesh, in.topo, singular, in.group, in.h, in.options, cut);
        if (score(cut) > score(out)) out = std::move(cut), v = std::move(w);
    }
    join_ambiguous_edges(in.mesh, in.topo, in.features, in.paths, in.h, in.options, out, v);
    const std::vector<int> group = joined_groups(in.mesh, in.topo, in.features, in.paths, out);
    const std::vector<char> trouble = tets_in_trouble(out);
    mend_best(in.mesh, in.topo, group, in.h, in.options, out, v);
    if (out.joined_blocks + out.split_blocks + out.prism_cuts > 0) out.trouble_before_joins = trouble;
    return v;
}

// The curves glued to ambiguous edges as sheet sources too (docs/algorithms.md#sheets-from-glued-curves):
// the blocks made from `common` with them replace `out` when they score better.
void try_glued_sources(const BlockInputs& in, const SingularityGraph& graph, const std::vector<SheetSource>& sources,
                       const Points& singular, const BlockDecomposition& common, BlockDecomposition& out, Validated& v) {
    std::vector<SheetSource> more = sources;
    const std::vector<SheetSource> glued = glued_sources(in.mesh, in.field, graph, in.locator, in.h, in.options);
    more.insert(more.end(), glued.begin(), glued.end());
    SingularityGraph absorbed;
    absorbed.curves = graph.absorbed;
    const Points glued_points = singular_points(absorbed);
    Points all(singular.rows() + glued_points.rows(), 3);
    all << singular, glued_points;
    BlockDecomposition with = common;
    Validated w = blocks_from_sources(in, more, all, with);
    with.glued_sources = int(glued.size());
    if (score(with) > score(out)) out = std::move(with), v = std::move(w);
}

// Where a ring of 3 faces joined a neighbour as a lens, the blocks made again with every such ring
// left whole for the ring cuts (docs/algorithms.md#lenses), kept when they score better: HexMe's
// torus has its five rings merged into one block otherwise, and n11o at 1.5 x needs the merge.
void try_rings_kept(const BlockInputs& in, const std::vector<SheetSource>& sources, const Points& singular,
                    const BlockDecomposition& common, BlockDecomposition& out, Validated& v) {
    BlockOptions options = in.options;
    options.ring_lenses = false;
    const BlockInputs kept{in.mesh, in.topo, in.features, in.field, in.locator, in.paths, in.group, in.h, options};
    BlockDecomposition with = common;
    Validated w = blocks_from_sources(kept, sources, singular, with);
    with.rings_kept = true;
    if (score(with) > score(out)) out = std::move(with), v = std::move(w);
}

}  // namespace

// Per tet: whether its block is invalid or in a non-conforming pair.
std::vector<char> tets_in_trouble(const BlockDecomposition& out) {
    std::vector<char> block(out.count, 0), tet(out.tet_block.size(), 0);
    for (int b = 0; b < out.count; ++b) block[b] = !out.blocks[b].valid;
    for (const BlockPair& p : out.neighbour_pairs)
        if (!p.conforming) block[p.a] = block[p.b] = 1;
    for (int t = 0; t < int(tet.size()); ++t) tet[t] = block[out.tet_block[t]];
    return tet;
}

BlockDecomposition build_blocks(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const FrameField& field, const SingularityGraph& graph,
                                const std::vector<SnappedPath>& paths, const BlockOptions& options) {
    check_inputs(mesh, topo, field, graph);
    const auto t0 = Clock::now();
    BlockDecomposition out;
    const double h = mean_edge_length(mesh, topo, 1);
    out.h = h;
    const TetLocator locator(mesh, topo);

    // Sheets.
    out.boundary_wisps = boundary_wisps(graph, h);
    std::vector<SheetSource> sources = singular_sources(mesh, field, graph, locator, h, options, out.boundary_wisps);
    const std::vector<int> imprints = followed_imprints(mesh, features, field);
    for (const EdgeFeature& e : features.edges)
        if (e.valence == 2 && !ambiguous_edge(e) && !std::binary_search(imprints.begin(), imprints.end(), e.edge))
            out.ignored_imprints.push_back(e.edge);
    std::sort(out.ignored_imprints.begin(), out.ignored_imprints.end());
    const std::vector<char> convex = convex_paths(mesh, features, paths, h);
    for (int i = 0; i < int(convex.size()); ++i)
        if (convex[i]) out.convex_paths.push_back(i);
    std::vector<int> edges = imprints;  // the followed imprints and the concave curves
    for (const EdgeFeature& e : features.edges)
        if (e.valence == 3) edges.push_back(e.edge);
    const std::vector<FeatureSeeds> curves = feature_seeds(mesh, features, field, edges);
    std::vector<SheetSource> feature = feature_sources(mesh, features, field, curves, paths, convex);
    sources.insert(sources.end(), feature.begin(), feature.end());
    const Points singular = singular_points(graph);
    if (options.curtain_corners) add_curtain_corners(mesh, field, locator, curves, paths, convex, singular, h, options, sources, out);
    const std::vector<int> group = surface_groups(mesh, topo, features, out.ignored_imprints, paths);

    // Sheets, partition and validation (lenses join a neighbour and the blocks are validated
    // again), once per junction mode tried; the best blocks are kept.
    const double source_seconds = since(t0);
    const BlockDecomposition common = out;
    const BlockInputs in{mesh, topo, features, field, locator, paths, group, h, options};
    Validated v = blocks_from_sources(in, sources, singular, out);
    if (options.try_glued && !graph.absorbed.empty()) try_glued_sources(in, graph, sources, singular, common, out, v);
    if (options.ring_lenses && out.ring_lenses > 0) try_rings_kept(in, sources, singular, common, out, v);
    out.seconds_sheets += source_seconds;
    out.surfaces = block_surfaces(mesh, v.surface, v.faces);
    out.boundary = std::move(v.surface);
    out.faces = std::move(v.faces);
    out.seconds = since(t0);
    return out;
}

}  // namespace framefix
