#pragma once
// Corrections of 3-5 curves, run on an analysed result: new boundary conditions (or, for the
// paper's other methods, a new mesh or B-rep), a re-solve and a new singularity graph.
#include <string>

#include "framefix/corrections/snapping.h"
#include "framefix/pipeline/pipeline.h"

namespace framefix {

struct CorrectionOptions {
    std::string method = "snap";  // snap | fillet | extrude-curves | extrude-nodes
    SnapOptions snap;
};

struct Correction {
    std::string method;
    SingularitySummary before;      // summary of the analysed field
    SingularityGraph graph_before;  // the graph that was corrected
    FrameField field_before;
    SnapResult snap;                // method == "snap"
    double rotated_fraction = 0;    // vertices whose frame turned by more than 10 degrees
    double seconds = 0;             // snapping + re-solve + re-extraction
};

// The names of the correction methods, and whether this build implements them.
bool correction_available(const std::string& method);
// Throws framefix::Error("correct") for an unknown or unavailable method.
void check_correction_method(const std::string& method);

// Corrects r in place: r.constraints, r.field and r.singularities become the corrected ones;
// the previous field and graph move into the returned Correction. Throws framefix::Error
// ("correct") for unknown or unavailable methods. A result without 3-5 curves is unchanged.
Correction correct(AnalysisResult& r, const CorrectionOptions& options, const AnalysisOptions& analysis);

}  // namespace framefix
