#include "framefix/pipeline/correction.h"

#include <chrono>

#include "framefix/core/error.h"
#include "framefix/core/memory.h"

namespace framefix {

bool correction_available(const std::string& method) { return method == "snap"; }

void check_correction_method(const std::string& method) {
    const bool known = method == "snap" || method == "fillet" || method == "extrude-curves" || method == "extrude-nodes";
    if (!known) throw Error("correct", "unknown method '" + method + "'; use snap, fillet, extrude-curves or extrude-nodes");
    if (!correction_available(method))
        throw Error("correct", "method '" + method + "' is not available yet; use --method snap (the paper's recommendation)");
}

Correction correct(AnalysisResult& r, const CorrectionOptions& options, const AnalysisOptions& analysis) {
    check_correction_method(options.method);
    if (!r.has_singularities) throw InternalError("correct: analyse before correcting");

    const auto t0 = std::chrono::steady_clock::now();
    Correction c;
    c.method = options.method;
    c.before = r.singularities.summary;
    report(analysis.progress, "correct", 0.0);
    c.snap = snap_three_five_curves(r.mesh, r.topology, r.features, r.constraints, r.field, r.singularities, options.snap);
    c.graph_before = r.singularities;
    c.field_before = r.field;
    if (!c.snap.snapped_curve_ids.empty()) {
        r.constraints = c.snap.constraints;
        FieldOptions fo = analysis.field;
        if (fo.threads == 0) fo.threads = analysis.threads;
        report(analysis.progress, "correct", 0.1);
        r.field = solve_frame_field(r.mesh, r.topology, r.constraints, fo);
        report(analysis.progress, "correct", 0.9);
        SingularityOptions so = analysis.singularities;
        if (so.threads == 0) so.threads = analysis.threads;
        r.singularities = extract_singularities(r.mesh, r.topology, r.field, so);
        c.rotated_fraction = rotated_fraction(c.field_before, r.field, 10);
    }
    report(analysis.progress, "correct", 1.0);
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.timings.total += c.seconds;
    r.peak_memory_mb = peak_memory_mb();
    return c;
}

}  // namespace framefix
