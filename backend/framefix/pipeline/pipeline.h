#pragma once
// The only module that knows the order of the stages: load, mesh, field, singularities,
// correction, blocks, hexmesh. A run returns every stage's output it reached, so that viewers, the
// report and the tests can look at each.
#include <memory>
#include <optional>
#include <string>

#include "framefix/blocks/blocks.h"
#include "framefix/brep/brep_model.h"
#include "framefix/hexmesh/hexmesh.h"
#include "framefix/pipeline/run_options.h"
#include "framefix/pipeline/stages.h"

namespace framefix {

// A CAD file or tet mesh (.msh, .mesh) by path, or a model already loaded (a FreeCAD shape).
struct RunInput {
    std::string path;
    std::shared_ptr<const BrepModel> model;

    static RunInput file(std::string path);
    static RunInput shape(const BrepModel& model);
};

struct RunResult {
    std::string input_path;
    std::string input_kind;                   // "step" | "brep" | "iges" | "msh" | "mesh"
    std::shared_ptr<const BrepModel> model;   // null for tet-mesh inputs
    std::optional<MeshStage> mesh;
    std::optional<FieldStage> field;          // the corrected field after a correction
    std::optional<SingularityGraph> singularities;  // the corrected graph after a correction
    std::optional<Correction> correction;     // absent when the run had none
    std::optional<BlockDecomposition> blocks;
    std::optional<ThinRefinement> thin;       // blocks runs on a B-rep whose blocks were not all valid
    std::optional<BlockRefinement> flat;      // flat corners refined: the blocks before, and whether refined ones replaced them
    std::optional<HexMesh> hexmesh;          // done = false with the reason when the blocks cannot be meshed
    Timings timings;
    double peak_memory_mb = 0;
};

// Kind of an input file from its extension; throws framefix::Error("load") when unknown.
std::string input_kind(const std::string& path);

// "tetgen" or "hxt" (--mesher); anything else is an options error naming both.
Mesher mesher_named(const std::string& name);

// Runs the stages up to options.stop_after. Options are checked before any work: an unknown
// or unavailable correction method throws framefix::Error("correct") at once. A tet-mesh input
// has no B-rep: load reads it, mesh finds its crease features.
RunResult run(const RunInput& input, const RunOptions& options);

}  // namespace framefix
