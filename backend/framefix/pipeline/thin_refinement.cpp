// The run's answer to blocks thinner than the mesh resolves (thin_blocks.h, docs/algorithms.md#thin-blocks).
#include <algorithm>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <tuple>

#include "framefix/pipeline/solve_stages.h"
#include "framefix/pipeline/thin_blocks.h"
#include "framefix/streamlines/tet_locator.h"

namespace framefix {
namespace {

bool all_good(const BlockDecomposition& b) { return b.valid == b.count && b.conforming_pairs == b.pairs; }

auto block_score(const RunResult& r) {
    const BlockDecomposition& b = *r.blocks;
    return std::make_tuple(-detail::defects(r.singularities->summary), all_good(b), 2 * b.valid - b.count,
                           2 * b.conforming_pairs - b.pairs);
}

// Why the run's blocks get no finer mesh; empty when they may (thin_blocks.h).
std::string thin_blocks_skip(const RunResult& r) {
    if (!r.model) return "a tet-mesh input has no B-rep to mesh again";
    if (all_good(*r.blocks)) return "every block is valid and every pair conforms";
    if (!r.singularities->summary.meshable) return "the graph is not hex-meshable";
    if (r.correction && r.correction->remeshed) return "the correction made a new solid or mesh";
    return "";
}

// The finer mesh may have at most this many times the tets, a run at about --size-factor 0.55:
// a cost bound. A thin cushion under a whole face needs the face's band at d / 3 (rounded_box and
// HexMe's s13o: 5.2 and 5.7 x); a few faces less (a stepped shaft: 4.1 x).
constexpr double kMaxThinTetFactor = 6;
// One more round may at most double the finer mesh's tets: a cost bound, since it runs the whole
// pipeline once more (the groove's second round: 1.2 x at 0.7 x, 1.7 x at 1 x).
constexpr double kAgainTetFactor = 2;

// Whether a point lies in an invalid block or a block with a non-conforming pair (as they were
// before under-faced blocks were joined away or prisms cut): only there do thin blocks need a finer mesh.
// Outside the mesh: no.
std::function<bool(const Eigen::Vector3d&)> in_trouble(const BlockDecomposition& b, const TetLocator& locator) {
    auto trouble = std::make_shared<std::vector<char>>(b.trouble_before_joins.empty() ? tets_in_trouble(b)
                                                                                      : b.trouble_before_joins);
    return [trouble, &locator](const Eigen::Vector3d& p) {
        const TetLocation where = locator.locate(p);
        return where.tet >= 0 && (*trouble)[size_t(where.tet)];
    };
}

// The run's blocks made again without the sheets of the curves glued to ambiguous edges
// (docs/algorithms.md#sheets-from-glued-curves).
BlockDecomposition blocks_without_glued(const RunOptions& o, const RunResult& r) {
    BlockOptions bo = o.blocks;
    bo.try_glued = false;
    if (bo.threads == 0) bo.threads = o.threads;
    static const std::vector<SnappedPath> no_paths;
    return build_blocks(r.mesh->tets, r.mesh->topology, r.mesh->features, r.field->frames, *r.singularities,
                        r.correction ? r.correction->snap.paths : no_paths, bo);
}

// A first run's thin places: curves and sheets near the walls, next to blocks in trouble.
ThinFaces first_run_places(const RunOptions& o, const RunResult& r, long base_tets, ThinRefinement& t) {
    const BlockDecomposition& b = *r.blocks;
    const TetLocator locator(r.mesh->tets, r.mesh->topology);
    ThinFaces thin = thin_block_faces(r.mesh->tets, *r.singularities, b.sheets, b.h, in_trouble(b, locator));
    if (b.glued_sources > 0 && estimate_thin_tets(r.mesh->tets, thin) > kMaxThinTetFactor * double(base_tets)) {
        // The glued curves' sheets made thinner blocks than the mesh may be refined for; those
        // without them may fit, and their finer mesh beat these blocks (the gusset at 1.5 x).
        const BlockDecomposition plain = blocks_without_glued(o, r);
        ThinFaces other = thin_block_faces(r.mesh->tets, *r.singularities, plain.sheets, plain.h, in_trouble(plain, locator));
        if (!other.face_size.empty() && estimate_thin_tets(r.mesh->tets, other) <= kMaxThinTetFactor * double(base_tets))
            thin = std::move(other), t.without_glued = true;
    }
    return thin;
}

// A kept finer run's, for one more round: its own thin places, and the under-faced blocks it still
// carves too thin (a slab between two sheets); the face sizes it was made with stay.
ThinFaces again_places(const RunResult& r, const std::map<int, double>& made_with) {
    const BlockDecomposition& b = *r.blocks;
    const TetLocator locator(r.mesh->tets, r.mesh->topology);
    ThinFaces thin = thin_block_faces(r.mesh->tets, *r.singularities, b.sheets, b.h, in_trouble(b, locator));
    add_thin_blocks(r.mesh->tets, r.mesh->topology, b, b.h, thin);
    if (!thin.face_size.empty())
        for (const auto& [face, size] : made_with) {
            auto [at, fresh] = thin.face_size.emplace(face, size);
            if (!fresh) at->second = std::min(at->second, size);
        }
    return thin;
}

// One finer run: r's thin places (a first round's when `made_with` is empty, else again_places),
// meshed finer within kMaxThinTetFactor x base_tets (and, once more, kAgainTetFactor x r's tets),
// kept in r when better.
ThinRefinement thin_round(const RunOptions& o, RunResult& r, long base_tets, const std::map<int, double>& made_with) {
    const double cap = made_with.empty() ? kMaxThinTetFactor * double(base_tets)
                                         : std::min(kMaxThinTetFactor * double(base_tets), kAgainTetFactor * r.mesh->tets.num_tets());
    ThinRefinement t;
    const BlockDecomposition& b = *r.blocks;
    t.tets_before = r.mesh->tets.num_tets();
    t.count_before = b.count, t.valid_before = b.valid, t.pairs_before = b.pairs, t.conforming_before = b.conforming_pairs;
    t.glued_before = b.glued_sources;
    t.reason = thin_blocks_skip(r);
    if (!t.reason.empty()) return t;
    ThinFaces thin = made_with.empty() ? first_run_places(o, r, base_tets, t) : again_places(r, made_with);
    t.spots = thin.places;
    t.faces = int(thin.face_size.size());
    t.thinnest = thin.thinnest;
    if (thin.face_size.empty()) {
        t.reason = "no singular curve or sheet next to an invalid block runs closer than " +
                   std::to_string(int(kResolvedThicknessH)) + " h to the boundary";
        return t;
    }
    t.min_size = std::min_element(thin.face_size.begin(), thin.face_size.end(),
                                  [](const auto& a, const auto& c) { return a.second < c.second; })->second;
    const double estimate = estimate_thin_tets(r.mesh->tets, thin);
    if (estimate > cap) {
        t.reason = "the thin blocks need about " + std::to_string(long(estimate / 1000)) + "k tets, more than " +
                   (made_with.empty() ? std::to_string(int(kMaxThinTetFactor)) + " x this mesh's"
                                      : "one more round may make (" + std::to_string(long(cap / 1000)) + "k)") +
                   "; a smaller --size-factor meshes them finer";
        return t;
    }
    const auto t0 = std::chrono::steady_clock::now();
    RunOptions fine = o;
    fine.remesh_thin = false;
    fine.hexmesh.refine_flat = false;  // compared as cut, as the first run's; the kept blocks are refined after
    fine.stop_after = Stage::blocks;
    fine.mesh.size = r.mesh->tets.size;
    fine.mesh.face_size = thin.face_size;
    fine.progress = {};
    RunResult f;
    t.tried = true;
    try {
        f = run(RunInput{r.input_path, r.model}, fine);
    } catch (const std::exception& e) {  // TetGen on the finer surface, memory: the first run stands
        t.reason = std::string("the finer mesh failed: ") + e.what();
        return t;
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.tets_after = f.mesh->tets.num_tets();
    t.count_after = f.blocks->count, t.valid_after = f.blocks->valid;
    t.pairs_after = f.blocks->pairs, t.conforming_after = f.blocks->conforming_pairs;
    t.kept = finer_run_better(f, r);
    t.reason = t.kept ? "blocks thinner than " + std::to_string(int(kResolvedThicknessH)) + " h next to " +
                            std::to_string(t.faces) + " faces"
                      : "the finer mesh's blocks are not better";
    if (t.kept) {
        t.rounds = 1, t.face_size = std::move(thin.face_size);
        r.mesh = std::move(f.mesh), r.field = std::move(f.field), r.singularities = std::move(f.singularities);
        r.correction = std::move(f.correction), r.blocks = std::move(f.blocks);
    }
    return t;
}

}  // namespace

bool finer_run_better(const RunResult& finer, const RunResult& first) { return block_score(finer) > block_score(first); }

ThinRefinement refine_thin_blocks(const RunOptions& o, RunResult& r) {
    const long first_tets = r.mesh->tets.num_tets();
    ThinRefinement t = thin_round(o, r, first_tets, {});
    // A kept round whose blocks are still not all good goes once more, from the finer run.
    for (int round = 1; t.kept && round < o.thin_rounds && !all_good(*r.blocks); ++round) {
        ThinRefinement again = thin_round(o, r, first_tets, t.face_size);
        t.seconds += again.seconds;
        if (!again.kept) break;
        t.rounds += 1, t.faces = again.faces, t.min_size = again.min_size, t.tets_after = again.tets_after;
        t.face_size = std::move(again.face_size);
        t.count_after = again.count_after, t.valid_after = again.valid_after;
        t.pairs_after = again.pairs_after, t.conforming_after = again.conforming_after;
    }
    return t;
}

}  // namespace framefix
