#pragma once
// Fillets on the B-rep (the paper's fillet correction, docs/algorithms.md#fillet-insertion): OCCT's
// BRepFilletAPI_MakeFillet on a copy of the solid, in a worker process (OCCT's filleting is
// modelling code that can crash). The input model is never modified.
#include <utility>
#include <string>
#include <vector>

#include "framefix/brep/brep_model.h"

namespace framefix {

struct FilletRequest {
    int edge = 0;        // B-rep edge, 1-based (Edge<i> of the input model)
    double radius = 0;   // model units
    double theta_deg = 270;  // dihedral angle inside the solid (EdgeFeature), for the volume check
};

struct FilletOutcome {
    int edge = 0;
    double radius = 0;   // the radius used (smaller than asked after a retry), or asked when not done
    bool done = false;
    std::string reason;  // why not done, empty when done
};

struct FilletOptions {
    // After a failure every radius is scaled by this and tried once more, before going edge by edge.
    double retry_scale = 0.6;
    // The volume added (concave edges) and removed (convex ones) may each be off by [1/k, k] from
    // the sum of section area x edge length (curved edges and trimmed ends make them differ; a
    // wrong-side or runaway fillet does not fit).
    double volume_factor = 3;
    double timeout_s = 120;   // worker budget for all the tries
};

struct FilletResult {
    BrepModel model;                     // the filleted solid (the input's copy when nothing was done)
    std::vector<FilletOutcome> fillets;  // one per request, in request order
    double volume_change = 0;            // filleted minus input volume, model units^3
    std::string how;                     // "all at once", "all at once, radii x 0.6", "edge by edge"
    // The fillet surfaces: (face of `model`, 1-based; radius), for meshing them finer.
    std::vector<std::pair<int, double>> fillet_faces;
};

// The fillets that OCCT can make; each edge that cannot be filleted is reported, never thrown.
// Throws framefix::Error("correct") only for bad requests (unknown edge, radius <= 0).
FilletResult fillet_edges(const BrepModel& model, const std::vector<FilletRequest>& requests,
                          const FilletOptions& options = {});

// Room for a fillet along `edge` (1-based): the distance from the edge's midpoint to the nearest
// other edge of the faces next to it, or to the nearest face that does not hold the edge (the
// local thickness), whichever is smaller; model units.
double fillet_room(const BrepModel& model, int edge);

// Cross-section area a fillet of radius r adds to an edge whose dihedral angle inside the solid is
// theta (theta > 180 deg: concave, material added) or removes (theta < 180 deg), model units^2.
double fillet_section_area(double radius, double theta_deg);

}  // namespace framefix
