#pragma once
// Field and singularity stages, shared by the first solve and the re-solve of a correction.
// Internal to the pipeline module: callers outside it use run().
#include "framefix/pipeline/run_options.h"
#include "framefix/pipeline/stages.h"

namespace framefix::detail {

// 3-5 curves plus invalid nodes: what "never worse" compares and what auto ranks by.
inline int defects(const SingularitySummary& s) { return s.curves_3_5 + s.invalid_nodes; }

// Solves the field under `constraints`; the solver's progress goes to `progress`.
FieldStage solve_field(const MeshStage& mesh, Constraints constraints, const RunOptions& options,
                       const ProgressSink& progress);

SingularityGraph find_singularities(const MeshStage& mesh, const FieldStage& field, const RunOptions& options);

// The correction stage: applies `options.correction` and, when it changed the set-up,
// re-solves `field` and re-extracts `graph` in place.
// model: the B-rep the mesh was made from, null for a tet-mesh input (methods that change the
// B-rep refuse those).
Correction correct(MeshStage& mesh, FieldStage& field, SingularityGraph& graph, const RunOptions& options,
                   const BrepModel* model);

// Method snap: more rounds on the re-solved graph while they lower its 3-5 curves plus invalid
// nodes (snap_rounds.cpp); `c.snap` and `c.snap_rounds` gather them.
void more_snap_rounds(Correction& c, const MeshStage& mesh, FieldStage& field, SingularityGraph& graph,
                      const RunOptions& options);

// Method auto (correction_auto.cpp): tries the other methods on copies and keeps the best.
Correction correct_auto(MeshStage& mesh, FieldStage& field, SingularityGraph& graph, const RunOptions& options,
                        const BrepModel* model);

}  // namespace framefix::detail
