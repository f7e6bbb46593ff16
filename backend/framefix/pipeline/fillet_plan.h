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
    // Also fillet each chosen edge's rims: the convex edges across a strip face from it (a
    // groove's or notch's top edges), so the whole feature turns smooth, as in the paper's Fig. 5b;
    // fillets narrower than h are then meshed finer (correction_methods.cpp).
    bool rims = false;
};

struct FilletPlan {
    std::vector<FilletRequest> requests;  // sorted by edge
    std::vector<std::string> notes;       // 3-5 curves no concave edge explains, radii cut by the room
};

// Concave feature edges (valence 3, or varying through 225 deg) within `reach` of a 3-5 curve of
// `graph`; h is the mesh's mean edge length. Imprinted (valence-2) curves are never filleted.
// With options.rims, their rims too (rims_of).
FilletPlan plan_fillets(const BrepModel& model, const FeatureSet& features, const SingularityGraph& graph, double h,
                        const FilletPlanOptions& options = {});

// The convex (valence-1) edges across a strip face from concave edge `edge`: they share a face
// with it and no vertex, and stay at one distance from it (within kStripTolerance of that distance).
std::vector<int> rims_of(const BrepModel& model, const FeatureSet& features, int edge);

}  // namespace framefix
