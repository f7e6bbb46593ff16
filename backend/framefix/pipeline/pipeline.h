#pragma once
// The only module that knows the order of the stages. Every intermediate is kept in the result
// so that viewers, the report and the tests can look at it.
#include <memory>
#include <string>

#include "framefix/brep/brep_model.h"
#include "framefix/core/progress.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

struct Timings {  // seconds
    double load = 0, mesh = 0, field = 0, singularities = 0, total = 0;
};

struct AnalysisOptions {
    MeshOptions mesh;
    FeatureOptions features;
    FieldOptions field;
    SingularityOptions singularities;
    double size_factor = 1;   // multiplies the default size when mesh.size == 0
    int threads = 0;          // 0 = all cores
    ProgressSink progress;    // stages: load, mesh, field, singularities
};

struct AnalysisResult {
    std::string input_path;
    std::string input_kind;        // "step" | "brep" | "iges" | "msh" | "mesh"
    std::shared_ptr<const BrepModel> model;  // null for tet-mesh inputs
    FeatureSet features;
    TetMesh mesh;
    TetTopology topology;
    Constraints constraints;
    FrameField field;
    SingularityGraph singularities;
    bool has_field = false, has_singularities = false;
    Timings timings;
    double peak_memory_mb = 0;
};

// Kind of an input file from its extension; throws framefix::Error("load") when unknown.
std::string input_kind(const std::string& path);

// load + features + tet mesh. `path` is a CAD file or a tet mesh (.msh, .mesh).
AnalysisResult mesh_part(const std::string& path, const AnalysisOptions& options);
// The same for a model already loaded (e.g. from a FreeCAD BREP string).
AnalysisResult mesh_model(const BrepModel& model, const AnalysisOptions& options);
// Frame field and singularity graph on a meshed result (adds to it).
void analyze_mesh(AnalysisResult& result, const AnalysisOptions& options);
// The whole pipeline.
AnalysisResult analyze(const std::string& path, const AnalysisOptions& options);

}  // namespace framefix
