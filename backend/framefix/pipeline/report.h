#pragma once
// report.json (version 1, docs/design.md#reportjson) and the files ParaView opens, from an AnalysisResult.
#include <string>
#include <vector>

#include "framefix/pipeline/block_stage.h"
#include "framefix/pipeline/correction.h"
#include "framefix/pipeline/pipeline.h"

namespace framefix {

// The report as JSON text. Sections a result does not have (no field yet, ...) are absent.
// With a correction, "singularities" is the corrected graph and "correction" holds the before
// and after summaries and the snapped paths.
// With blocks, the "blocks" section holds the decomposition and its validation.
std::string report_json(const AnalysisResult& result, const Correction* correction = nullptr,
                        const BlockDecomposition* blocks = nullptr);

// Writes DIR/report.json and the VTK files; returns the paths written. Creates DIR.
std::vector<std::string> write_outputs(const AnalysisResult& result, const std::string& dir,
                                       const Correction* correction = nullptr,
                                       const BlockDecomposition* blocks = nullptr);

// Feature curves as ordered polylines of mesh vertices, one per B-rep edge tag.
struct FeaturePolyline {
    int edge = 0;                 // B-rep edge index (1-based)
    std::vector<int> vertices;    // mesh vertex indices in order along the curve
};
std::vector<FeaturePolyline> feature_polylines(const TetMesh& mesh);

// "notch.step: 58k tets, 1 singular curve: 1 3-5 curve (not hex-meshable); 0.6 s"
std::string human_summary(const AnalysisResult& result, const Correction* correction = nullptr,
                          const BlockDecomposition* blocks = nullptr);

}  // namespace framefix
