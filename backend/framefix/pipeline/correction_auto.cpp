// Method auto (docs/algorithms.md#auto): the methods that keep the part's geometry first,
// cheapest first, then the fillet, which changes the B-rep; the first hex-meshable result ends
// the search. When none is, snapping is tried on top of the best result ("M+snap"): it snaps
// the 3-5 curves the first method left, one region fixed by each. The best result is kept;
// when nothing helps, the input's graph is.
#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>

#include "framefix/pipeline/solve_stages.h"

namespace framefix::detail {
namespace {

// The budget for a part of kDefaultTargetTets tets, scaled by its tets (the figure).
constexpr double kAutoBudgetSeconds = 120;
constexpr const char* kAutoOrder[] = {"snap", "extrude-nodes", "extrude-curves", "fillet"};

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string seconds_text(double s) {
    std::ostringstream o;
    o.precision(3);
    o << s << " s";
    return o.str();
}

struct State {  // a try's copy of the run: what correct() changes in place
    MeshStage mesh;
    FieldStage field;
    SingularityGraph graph;
    Correction record;
};

// a ranks strictly above b: hex-meshable first, then fewer 3-5 curves plus invalid nodes, then a
// result on the input's mesh (its turned frames are measured) before a remeshed one, then fewer
// frames turned by more than 10 degrees.
bool better(const CorrectionTry& a, const CorrectionTry& b) {
    if (a.after.meshable != b.after.meshable) return a.after.meshable;
    if (defects(a.after) != defects(b.after)) return defects(a.after) < defects(b.after);
    if (a.remeshed != b.remeshed) return !a.remeshed;
    return a.rotated_fraction < b.rotated_fraction;
}

CorrectionTry run_try(const std::string& method, State& s, const RunOptions& options, const BrepModel* model) {
    const auto t0 = Clock::now();
    RunOptions o = options;
    o.correction = method;
    o.progress = {};
    s.record = correct(s.mesh, s.field, s.graph, o, model);
    const Correction& r = s.record;
    CorrectionTry t{method, true, r.changed && !r.worse_dropped, s.graph.summary, r.rotated_fraction, r.remeshed,
                    since(t0), ""};
    if (!r.changed) t.reason = r.notes.empty() ? "nothing to change" : r.notes.front();
    if (r.worse_dropped) t.reason = "worse than the input: dropped";
    if (method == "extrude-nodes" || method == "extrude-curves")
        if (!r.changed && !r.extrusion.failures.empty()) t.reason = r.extrusion.failures.front().why;
    return t;
}

CorrectionTry skipped(const std::string& method, const SingularitySummary& before, std::string why) {
    CorrectionTry t;
    t.method = method;
    t.after = before;
    t.reason = std::move(why);
    return t;
}

// The best state's record with the snap done on top of it.
void merge_snap(State& best, State& snapped) {
    Correction merged = std::move(best.record);
    merged.snap = std::move(snapped.record.snap);
    merged.snap_rounds = std::move(snapped.record.snap_rounds);
    for (std::string& n : snapped.record.notes) merged.notes.push_back(std::move(n));
    best.mesh = std::move(snapped.mesh);
    best.field = std::move(snapped.field);
    best.graph = std::move(snapped.graph);
    best.record = std::move(merged);
}

}  // namespace

Correction correct_auto(MeshStage& mesh, FieldStage& field, SingularityGraph& graph, const RunOptions& options,
                        const BrepModel* model) {
    const auto t0 = Clock::now();
    Correction c;
    c.method = "auto";
    c.before = graph.summary;
    c.graph_before = graph;
    c.field_before = field.frames;
    c.budget_s = options.budget_s > 0 ? options.budget_s
                                      : kAutoBudgetSeconds * std::max(1.0, double(mesh.tets.num_tets()) / kDefaultTargetTets);
    report(options.progress, "correct", 0.0);
    if (graph.summary.meshable) {
        c.notes.push_back("already hex-meshable: nothing to correct");
        return c;
    }
    std::optional<State> best;
    CorrectionTry best_try = skipped("input", c.before, "");
    // A try costs at least one field solve: the input's is the first estimate.
    double longest = field.frames.seconds_init + field.frames.seconds_smooth;
    const auto over_budget = [&] { return since(t0) + longest > c.budget_s; };
    const auto budget_note = [&] {
        return "budget: " + seconds_text(since(t0)) + " of " + seconds_text(c.budget_s) + " spent, a try takes about " +
               seconds_text(longest);
    };
    for (const char* name : kAutoOrder) {
        report(options.progress, "correct", double(c.tries.size()) / std::size(kAutoOrder));
        if (std::string(name) == "fillet" && !model) {
            c.tries.push_back(skipped(name, c.before, "the input is a tet mesh: no B-rep to fillet"));
            continue;
        }
        if (over_budget()) {
            c.tries.push_back(skipped(name, c.before, budget_note()));
            continue;
        }
        State s{mesh, field, graph, {}};
        const CorrectionTry t = run_try(name, s, options, model);
        longest = std::max(longest, t.seconds);
        c.tries.push_back(t);
        if (t.kept && better(t, best_try)) best = std::move(s), best_try = t;
        if (best_try.after.meshable) break;
    }
    if (best && !best_try.after.meshable && best_try.method != "snap") {
        const std::string combined = best_try.method + "+snap";
        if (over_budget()) {
            c.tries.push_back(skipped(combined, best_try.after, budget_note()));
        } else {
            State s{best->mesh, best->field, best->graph, {}};
            CorrectionTry t = run_try("snap", s, options, model);
            t.method = combined;
            t.remeshed = best_try.remeshed;
            c.tries.push_back(t);
            if (t.kept && better(t, best_try)) merge_snap(*best, s), best_try = t;
        }
    }
    report(options.progress, "correct", 1.0);
    if (!best) {
        const bool ran = std::any_of(c.tries.begin(), c.tries.end(), [](const CorrectionTry& t) { return t.ran; });
        c.notes.push_back(ran ? "nothing helped: no method lowered the 3-5 curves plus invalid nodes (" +
                                    std::to_string(defects(c.before)) + "); the input's graph is kept"
                              : "no method fits the budget of " + seconds_text(c.budget_s) +
                                    ": the input's graph is kept; raise --budget-s");
        c.seconds = since(t0);
        return c;
    }
    Correction r = std::move(best->record);
    mesh = std::move(best->mesh);
    field = std::move(best->field);
    graph = std::move(best->graph);
    r.method = "auto";
    r.chosen = best_try.method;
    r.before = c.before;
    r.graph_before = std::move(c.graph_before);
    r.field_before = std::move(c.field_before);
    r.tries = std::move(c.tries);
    r.budget_s = c.budget_s;
    r.changed = true;
    r.seconds = since(t0);
    return r;
}

}  // namespace framefix::detail
