#pragma once
// Block faces across ambiguous feature curves (docs/algorithms.md#block-faces-across-ambiguous-edges).
// Internal to blocks.
#include <vector>

#include "framefix/blocks/validation.h"
#include "framefix/corrections/snapping.h"
#include "framefix/mesh/features.h"

namespace framefix {

// CAD surface group of each topology face (-1 inside): connected boundary triangles, split at
// feature curves and snapped paths (a snapped path is a block edge: the hex layers meet the
// surface there at 45 degrees), joined across everything else: a cylinder's seam, and the
// B-rep edges in `joined` (sorted: imprints the field ignores, ambiguous edges folded into a face).
std::vector<int> surface_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const std::vector<int>& joined, const std::vector<SnappedPath>& paths);

// The surface groups across out's ignored imprints and joined edges.
std::vector<int> joined_groups(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                               const std::vector<SnappedPath>& paths, const BlockDecomposition& out);

// A chamfer folds into one of its two neighbouring faces, never both; the choice is per B-rep
// edge. Best first: each round joins the ambiguous edge whose join makes the blocks score best
// (ties: fewer faces, edges and corners off a hexahedron's), while that is better than no join.
// The partition stays; `out` (joined_edges, blocks) and its validation `v` are updated.
void join_ambiguous_edges(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                          const std::vector<SnappedPath>& paths, double h, const BlockOptions& options,
                          BlockDecomposition& out, Validated& v);

}  // namespace framefix
