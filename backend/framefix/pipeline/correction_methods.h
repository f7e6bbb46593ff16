#pragma once
// The registry of correction methods: the one list the CLI, Python and the workbench read.
// A method changes the part's set-up (boundary conditions today; the mesh for a method that
// changes the B-rep or extrudes); the pipeline then re-solves the field and the graph.
#include <string>
#include <vector>

#include "framefix/pipeline/run_options.h"
#include "framefix/pipeline/stages.h"

namespace framefix {

struct CorrectionContext {
    const RunOptions& options;
    const BrepModel* model;          // the B-rep the mesh came from; null for a tet-mesh input
    MeshStage& mesh;                 // a method that remeshes replaces it
    FieldStage& field;               // constraints to change; frames: the field being corrected
    const SingularityGraph& graph;   // the graph being corrected
    Correction& record;              // what the method did, for the report
};

struct CorrectionMethod {
    std::string name;
    std::string description;  // one line, shown by `framefix info` and the workbench
    bool available = false;   // implemented in this build
    // Returns true when it changed the set-up (the pipeline then re-solves); null for auto, which
    // runs the others (correction_auto.cpp).
    bool (*apply)(CorrectionContext&) = nullptr;
    // The result is dropped, and the input's mesh, field and graph kept, when it has more 3-5
    // curves plus invalid nodes than the input (the reason goes to the failures).
    bool never_worse = false;
};

// auto, then every method the paper describes, in the order the user sees them; the first is the default.
const std::vector<CorrectionMethod>& correction_methods();

// The method called `name`; throws framefix::Error("correct") when unknown or not available.
const CorrectionMethod& find_correction_method(const std::string& name);

}  // namespace framefix
