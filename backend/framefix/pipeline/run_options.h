#pragma once
// What a run does: where it stops, which correction it applies, and each stage's options.
#include <string>

#include "framefix/blocks/blocks.h"
#include "framefix/brep/brep_model.h"
#include "framefix/core/progress.h"
#include "framefix/hexmesh/hexmesh.h"
#include "framefix/corrections/snapping.h"
#include "framefix/pipeline/fillet_plan.h"
#include "framefix/pipeline/stages.h"

namespace framefix {

constexpr const char* kNoCorrection = "none";  // RunOptions::correction that skips the stage

struct RunOptions {
    Stage stop_after = Stage::singularities;
    std::string correction = "auto";  // a registered method (correction_methods.h) or kNoCorrection
    // Method auto: time budget for its tries, seconds; 0 = kAutoBudgetSeconds per kDefaultTargetTets tets.
    double budget_s = 0;
    MeshOptions mesh;
    FeatureOptions features;
    FieldOptions field;
    SingularityOptions singularities;
    SnapOptions snap;
    FilletPlanOptions fillet;
    BlockOptions blocks;
    // Mesh again finer next to blocks thinner than 3 h when the blocks are not all valid (thin_blocks.h).
    bool remesh_thin = true;
    // Finer runs in a row at most: a kept finer run whose blocks are still not all valid meshes
    // again finer, with its own face sizes and those of its thin blocks (docs/algorithms.md#thin-blocks).
    int thin_rounds = 2;
    HexMeshOptions hexmesh;
    double size_factor = 1;  // multiplies the default size when mesh.size == 0
    int threads = 0;         // OpenMP threads of this run's parallel loops, 0 = all cores
    ProgressSink progress;   // fractions per stage, stages in run order
};

}  // namespace framefix
