#pragma once
// Which concave edges the fillet correction fillets, and with which radius
// (docs/algorithms.md#edges-and-radii).
#include <string>
#include <vector>

#include "framefix/brep/fillet.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

struct FilletPlanOptions {
    double reach = 3;         // a concave edge this close to a 3-5 curve (mean edge lengths) causes it
    double radius = 3;        // wanted radius, in mean edge lengths: the mesh resolves the fillet
    double room_share = 0.25; // the radius stays below this share of the edge's room (fillet_room)
};

struct FilletPlan {
    std::vector<FilletRequest> requests;  // sorted by edge
    std::vector<std::string> notes;       // 3-5 curves no concave edge explains, radii cut by the room
};

// Concave feature edges (valence 3, or varying through 225 deg) within `reach` of a 3-5 curve of
// `graph`; h is the mesh's mean edge length. Imprinted (valence-2) curves are never filleted.
FilletPlan plan_fillets(const BrepModel& model, const FeatureSet& features, const SingularityGraph& graph, double h,
                        const FilletPlanOptions& options = {});

}  // namespace framefix
