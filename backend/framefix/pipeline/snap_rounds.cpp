// Snap rounds (docs/algorithms.md#snap-rounds): snapping again on the re-solved graph while it helps.
#include <optional>

#include "framefix/pipeline/solve_stages.h"

namespace framefix::detail {
namespace {

// Rounds per run, the first included: bounds the cost at 4 field solves (n01o still gained in
// its fourth, the samples never need a third).
constexpr int kMaxSnapRounds = 4;

struct SnapRound {
    SnapResult snap;
    FieldStage field;
    SingularityGraph graph;
};

// One more snapping of the graph's 3-5 curves, and with `invalid` of its invalid interior nodes,
// then the re-solve; nothing when there is nothing to snap.
std::optional<SnapRound> snap_round(const MeshStage& mesh, const FieldStage& field, const SingularityGraph& graph,
                                    const RunOptions& options, bool invalid) {
    SnapOptions so = options.snap;
    so.snap_invalid_nodes = invalid;
    SnapResult s = snap_three_five_curves(mesh.tets, mesh.topology, mesh.features, field.constraints, field.frames, graph, so);
    if (s.snapped_curve_ids.empty()) return std::nullopt;
    FieldStage f = solve_field(mesh, s.constraints, options, {});
    SingularityGraph g = find_singularities(mesh, f, options);
    return SnapRound{std::move(s), std::move(f), std::move(g)};
}

// Snapping again on the re-solved graph while each round lowers the 3-5 curves plus invalid nodes:
// a re-solve can leave or create 3-5 curves next to the snapped ones. Where the graph has invalid
// interior nodes a round is tried with and without snapping them, and the better one counts. A
// round that does not lower them is undone and ends the rounds; each round's summary is kept.
}  // namespace

void more_snap_rounds(Correction& c, const MeshStage& mesh, FieldStage& field, SingularityGraph& graph,
                      const RunOptions& options) {
    c.snap_rounds.push_back(graph.summary);
    for (int round = 1; round < kMaxSnapRounds && !graph.summary.meshable; ++round) {
        std::optional<SnapRound> best;
        for (bool invalid : {false, true}) {
            if (invalid && graph.summary.invalid_nodes == 0) continue;
            std::optional<SnapRound> r = snap_round(mesh, field, graph, options, invalid);
            if (r && (!best || defects(r->graph.summary) < defects(best->graph.summary))) best = std::move(r);
        }
        if (!best) break;
        c.snap_rounds.push_back(best->graph.summary);
        if (defects(best->graph.summary) >= defects(graph.summary)) break;
        SnapResult& s = best->snap;
        for (SnappedPath& p : s.paths) c.snap.paths.push_back(std::move(p));
        c.snap.snapped_curve_ids.insert(c.snap.snapped_curve_ids.end(), s.snapped_curve_ids.begin(), s.snapped_curve_ids.end());
        c.snap.snapped_curves += s.snapped_curves;
        c.snap.freed_vertices += s.freed_vertices;
        c.snap.invalid_nodes_snapped += s.invalid_nodes_snapped;
        c.snap.constraints = std::move(s.constraints);
        field = std::move(best->field);
        graph = std::move(best->graph);
    }
}

}  // namespace framefix::detail
