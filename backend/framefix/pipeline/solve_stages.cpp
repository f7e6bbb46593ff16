#include "framefix/pipeline/solve_stages.h"

#include "framefix/singularities/edge_absorption.h"

namespace framefix::detail {

FieldStage solve_field(const MeshStage& mesh, Constraints constraints, const RunOptions& options,
                       const ProgressSink& progress) {
    FieldOptions fo = options.field;
    if (!fo.progress) fo.progress = progress;
    if (fo.threads == 0) fo.threads = options.threads;
    FieldStage f;
    f.constraints = std::move(constraints);
    f.frames = solve_frame_field(mesh.tets, mesh.topology, f.constraints, fo);
    return f;
}

SingularityGraph find_singularities(const MeshStage& mesh, const FieldStage& field, const RunOptions& options) {
    SingularityOptions so = options.singularities;
    if (so.threads == 0) so.threads = options.threads;
    SingularityGraph g = extract_singularities(mesh.tets, mesh.topology, field.frames, so);
    absorb_edge_curves(g, mesh.tets, mesh.features, so.absorb_radius * g.h_mean);
    return g;
}

}  // namespace framefix::detail
