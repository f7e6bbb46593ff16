#pragma once
// Smooth display of a block decomposition (internal to blocks) (docs/algorithms.md#block-surfaces): each block's
// boundary triangles with their vertices smoothed, so that interfaces read as surfaces and not as
// tet-face staircases, and the block edges as polylines. Display only: validation and the tet
// labels never see the moved vertices.
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/validation.h"

namespace framefix {

// `surface`: each block's boundary triangles; `faces`: their cleaned labels (BlockFaces::cleaned),
// so that the staircase slivers the validation merged do not show as edges. `iterations` rounds of Laplacian smoothing: vertices inside an interface move to the mean of
// their interface neighbours, vertices on a block edge to the mean of their two edge neighbours
// (on the part's boundary: within the tangent plane); corners and CAD feature curves stay.
BlockSurfaces block_surfaces(const TetMesh& mesh, const std::vector<std::vector<BoundaryTriangle>>& surface,
                             const std::vector<BlockFaces>& faces, int iterations = 40);

}  // namespace framefix
