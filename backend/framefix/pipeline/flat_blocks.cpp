#include "framefix/pipeline/flat_blocks.h"

#include <chrono>
#include <memory>
#include <string>

#include "framefix/brep/brep_model.h"

namespace framefix {
namespace {

using Clock = std::chrono::steady_clock;

bool all_good(const BlockDecomposition& b) { return b.valid == b.count && b.conforming_pairs == b.pairs; }

// "8 of 9 valid (block 8: faces 5), 12 of 12 pairs conforming": the first failure says where.
std::string figures(const BlockDecomposition& b) {
    std::string first;
    for (int k = 0; k < b.count && first.empty(); ++k)
        if (!b.blocks[size_t(k)].valid) first = " (block " + std::to_string(k) + ": " + b.blocks[size_t(k)].reason + ")";
    for (const BlockPair& p : b.neighbour_pairs)
        if (first.empty() && !p.conforming)
            first = " (blocks " + std::to_string(p.a) + " and " + std::to_string(p.b) + ": " + p.reason + ")";
    return std::to_string(b.valid) + " of " + std::to_string(b.count) + " valid, " + std::to_string(b.conforming_pairs) +
           " of " + std::to_string(b.pairs) + " pairs conforming" + first;
}

// Why the blocks are not refined before any hex is made; empty when they may be.
std::string flat_skip(const RunOptions& o, const BlockDecomposition& b) {
    if (!o.hexmesh.refine_flat) return "turned off (--no-refine)";
    if (!all_good(b)) return "not every block is valid and conforming";
    return "";
}

}  // namespace

HexMesh mesh_hexes(const RunResult& r, const RunOptions& o) {
    const BrepModel* model = r.correction && r.correction->filleted ? r.correction->filleted.get() : r.model.get();
    CadProjector cad;
    if (model) {
        cad.to_face = [model](int face, const Eigen::Vector3d& p) { return closest_point_on_face(*model, face, p); };
        cad.to_edge = [model](int edge, const Eigen::Vector3d& p) { return closest_point_on_edge(*model, edge, p); };
    }
    HexMesh h = build_hexmesh(r.mesh->tets, *r.blocks, o.hexmesh, cad);
    if (model) h.part_volume = model->volume;
    else for (int t = 0; t < r.mesh->tets.num_tets(); ++t) h.part_volume += tet_volume(r.mesh->tets, t);
    return h;
}

BlockRefinement refine_flat_blocks(const RunOptions& o, RunResult& r) {
    const auto t0 = Clock::now();
    BlockRefinement out;
    const BlockDecomposition& b = *r.blocks;
    out.count_before = b.count, out.valid_before = b.valid, out.pairs_before = b.pairs;
    out.conforming_before = b.conforming_pairs, out.flat_corners_before = b.flat_corners, out.flat_edges_before = b.flat_edges;
    out.reason = flat_skip(o, b);
    if (!out.reason.empty()) return out;
    auto hexes = std::make_shared<HexMesh>(mesh_hexes(r, o));
    out.tried = true;
    const HexRefinement& f = hexes->refinement;
    if (!hexes->done) out.reason = "the blocks give no hex mesh: " + hexes->reason;
    else if (!f.kept) out.reason = f.flat_edges_before == 0 && f.skipped.empty() ? "no flat block edge" : "no refinement gave better hexes";
    else {
        static const std::vector<SnappedPath> no_paths;
        const auto& paths = r.correction ? r.correction->snap.paths : no_paths;
        const MeshStage& m = *r.mesh;
        BlockOptions bo = o.blocks;
        if (bo.threads == 0) bo.threads = o.threads;
        BlockDecomposition refined = relabelled_blocks(m.tets, m.topology, m.features, paths, b,
                                                       refined_tet_blocks(m.tets, m.topology, b.tet_block, *hexes), bo);
        if (all_good(refined) && refined.count == int(hexes->blocks.size())) {
            out.kept = true, out.refined = f.refined;
            r.blocks = std::move(refined);
        } else {
            out.reason = "the refined blocks' tets validate as " + figures(refined) + "; the blocks stay as cut";
        }
    }
    out.hexes = std::move(hexes);
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return out;
}

}  // namespace framefix
