#pragma once
// report.json (version 1, docs/design.md#reportjson) and the files ParaView opens, from a run's result.
#include <string>
#include <vector>

#include "framefix/pipeline/pipeline.h"

namespace framefix {

// The report as JSON text. Sections of stages the run did not reach are absent. After a
// correction, "singularities" is the corrected graph and "correction" holds the before and
// after summaries and the snapped paths; after blocks, "blocks" the decomposition.
std::string report_json(const RunResult& result);

// Writes DIR/report.json and the VTK files of the stages the run reached; returns the paths
// written. Creates DIR.
std::vector<std::string> write_outputs(const RunResult& result, const std::string& dir);

// Feature curves as ordered polylines of mesh vertices, one per B-rep edge tag.
struct FeaturePolyline {
    int edge = 0;                 // B-rep edge index (1-based)
    std::vector<int> vertices;    // mesh vertex indices in order along the curve
};
std::vector<FeaturePolyline> feature_polylines(const TetMesh& mesh);

// "notch.step: 58k tets, 1 singular curve: 1 3-5 curve (not hex-meshable); 0.6 s"
std::string human_summary(const RunResult& result);

// `framefix info`: the backend's defaults and its correction methods, as JSON text.
std::string info_json();

}  // namespace framefix
