#pragma once
// Singular curves that hug an ambiguous feature curve are part of the boundary
// (docs/algorithms.md#curves-along-ambiguous-edges). A chamfer's 135 degree edge, or a 45 degree
// wedge, is halfway between two hex corner types: the field settles it by laying a valence-3 or
// valence-5 curve within a mesh edge of it along its length. Glued to the edge, such a curve only
// says whether the edge is a block corner or flat there; no hex mesh needs it inside.
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

// Moves every curve whose points all lie within `radius` (model units) of a mesh edge on an
// ambiguous feature curve, or of a strip (a face within 2 radii of its own ambiguous edges: a
// narrow chamfer), but for stretches that cross a wider face from one of its ambiguous edges to
// another, from `graph.curves` to `graph.absorbed`, drops the nodes left without a curve,
// and counts the nodes and summary again. A node a moved curve ended at lies on the feature curve:
// it becomes a boundary node, unchecked like the nodes on feature curves. Returns how many curves
// moved.
int absorb_edge_curves(SingularityGraph& graph, const TetMesh& mesh, const FeatureSet& features, double radius);

}  // namespace framefix
