#pragma once
// Editing a block complex (internal to hexmesh; docs/algorithms.md#flat-edge-refinement): the
// flat-edge template and the sheets it sends through the neighbours.
#include <string>

#include "framefix/hexmesh/block_structure.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// Splits block bi of cx along its flat local edge e into three blocks by the template, with the
// blocks the flat edge runs on into face to face (its two ends must lie on the part's boundary);
// each neighbour across a face the template splits is split in two by a sheet on through its
// neighbours to the boundary. Returns why it cannot (cx then unchanged in its blocks; it may
// hold unused corners), or "" when done (cx compacted).
std::string refine_flat_block(const TetMesh& mesh, BlockComplex& cx, int bi, int e);

// Drops the edges and faces no block uses any more, and renumbers the rest.
void compact(BlockComplex& cx);

}  // namespace framefix
