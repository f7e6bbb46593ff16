// The correction stage: a registered method changes the set-up, then field and graph are
// solved again on it. Progress: correct 0 -> 0.1 method, 0.1 -> 0.9 re-solve, then the graph.
#include <chrono>
#include <optional>

#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/fillet_map.h"
#include "framefix/pipeline/solve_stages.h"

namespace framefix::detail {
namespace {

constexpr double kRotationThresholdDeg = 10;  // "frames turned" in the report counts above this
constexpr int kMaxSnapRounds = 4;  // snap rounds per run; measured: a third round rarely helps

int defects(const SingularitySummary& s) { return s.curves_3_5 + s.invalid_nodes; }

// A never_worse method's result with more 3-5 curves plus invalid nodes than its input is
// dropped: the input's mesh, field and graph come back, and the notes (and an extrusion's
// failures) say why. A result not worse but still not hex-meshable is said too.
void keep_only_if_not_worse(Correction& c, MeshStage& mesh_before, Constraints& constraints_before, MeshStage& mesh,
                            FieldStage& field, SingularityGraph& graph) {
    const int before = defects(c.before), after = defects(graph.summary);
    std::string why;
    if (after > before) {
        why = "it has " + std::to_string(after) + " 3-5 curves plus invalid nodes, the input " + std::to_string(before) +
              ": the input's graph is kept";
        c.worse_dropped = true;
        mesh = std::move(mesh_before);
        field = FieldStage{std::move(constraints_before), c.field_before};
        graph = c.graph_before;
        c.remeshed = false;
        c.filleted.reset();
    } else if (!graph.summary.meshable) {
        why = "not hex-meshable yet: " + std::to_string(graph.summary.curves_3_5) + " 3-5 curves, " +
              std::to_string(graph.summary.invalid_nodes) + " invalid nodes (the input: " + std::to_string(before) + " in all)";
    }
    if (why.empty()) return;
    c.notes.push_back("result: " + why);
    if (c.method.rfind("extrude", 0) == 0) c.extrusion.failures.push_back({"result", why});
}

// The mapped graph as a correction of the original part: flat corners where its valence-5 curves
// lie on a filleted edge, then a re-solve on the original mesh.
FlatCornerSolve solve_flat_corners(const MeshStage& original, const Constraints& constraints, const MappedGraph& mapped,
                                   const RunOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    FlatCornerSolve s;
    const std::vector<EdgeRun> runs = valence5_runs(mapped);
    s.runs = int(runs.size());
    FlatCorners f = flat_corner_constraints(original.tets, original.features, constraints, runs);
    s.turned_vertices = f.turned_vertices;
    if (s.turned_vertices > 0) {
        const FieldStage field = solve_field(original, std::move(f.constraints), options, {});
        s.graph = find_singularities(original, field, options);
        s.solved = true;
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

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

}  // namespace

Correction correct(MeshStage& mesh, FieldStage& field, SingularityGraph& graph, const RunOptions& options,
                   const BrepModel* model) {
    const CorrectionMethod& method = find_correction_method(options.correction);
    if (!method.apply) return correct_auto(mesh, field, graph, options, model);
    const auto t0 = std::chrono::steady_clock::now();
    Correction c;
    c.method = method.name;
    c.before = graph.summary;
    report(options.progress, "correct", 0.0);
    std::optional<MeshStage> mesh_before;  // never_worse: what to go back to
    std::optional<Constraints> constraints_before;
    if (method.never_worse) mesh_before = mesh, constraints_before = field.constraints;
    CorrectionContext context{options, model, mesh, field, graph, c};
    c.changed = method.apply(context);
    c.graph_before = graph;
    c.field_before = field.frames;
    if (c.changed) {
        report(options.progress, "correct", 0.1);
        const ProgressSink& sink = options.progress;
        const ProgressSink inner = [&sink](const std::string&, double f) { report(sink, "correct", 0.1 + 0.8 * f); };
        field = solve_field(mesh, std::move(field.constraints), options, sink ? inner : ProgressSink{});
        report(options.progress, "correct", 0.9);
        graph = find_singularities(mesh, field, options);
        if (method.name == "snap") more_snap_rounds(c, mesh, field, graph, options);
        if (!c.remeshed)  // frames of another mesh cannot be compared vertex by vertex
            c.rotated_fraction = rotated_fraction(c.field_before, field.frames, kRotationThresholdDeg, options.threads);
        if (mesh_before) keep_only_if_not_worse(c, *mesh_before, *constraints_before, mesh, field, graph);
        if (c.filleted && model) {
            MappedGraph m = map_back(*model, c.fillets, graph);
            c.flat_corners = solve_flat_corners(*mesh_before, *constraints_before, m, options);
            c.mapped = std::move(m.graph);
            c.mapped_points = m.moved_points;
            c.mapped_nodes = m.moved_nodes;
        }
    }
    report(options.progress, "correct", 1.0);
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return c;
}

}  // namespace framefix::detail
