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
