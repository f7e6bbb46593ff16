#pragma once
// The corrected graph of a filleted part mapped back onto the original part
// (docs/algorithms.md#map-back), beyond the paper, which left it undone.
#include <vector>

#include "framefix/brep/fillet.h"
#include "framefix/corrections/flat_corners.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

struct MappedGraph {
    SingularityGraph graph;  // points and nodes on the original part; kinds as on the filleted one
    int moved_points = 0;    // curve points pulled onto a filleted edge
    int moved_nodes = 0;     // nodes on a fillet, now on the concave edge it replaced
    // Per curve, per point: the original part's edge (1-based) the point was moved onto, 0 if none.
    std::vector<std::vector<int>> point_edge;
};

// Curve points within one radius of a filleted edge (original part's Edge<i>) go to their closest
// point on it, and so do nodes within 1.5 radii: those lay on the fillet or within a tet of it.
// A node on the edge is a boundary node on a feature curve, hence valid
// (docs/algorithms.md#node-validity).
MappedGraph map_back(const BrepModel& original, const std::vector<FilletOutcome>& fillets,
                     const SingularityGraph& filleted);

// The stretches of the mapped valence-5 curves that lie on a filleted edge: there the original
// part gets flat corners (corrections/flat_corners.h).
std::vector<EdgeRun> valence5_runs(const MappedGraph& mapped);

}  // namespace framefix
