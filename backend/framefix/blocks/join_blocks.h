#pragma once
// Under-faced blocks joined to a neighbour (docs/algorithms.md#under-faced-blocks). Internal to blocks.
#include <vector>

#include "framefix/blocks/validation.h"

namespace framefix {

// Each invalid block of fewer than 6 faces (a wedge a sheet cut off) joins the neighbour it
// makes a hexahedron with, where the blocks then score better; greedy, one join per round, at
// most options.join_rounds. `group`: the surface group of every topology face. Updates `out`
// (joined_blocks) and its validation `v`.
void join_under_faced(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                      const BlockOptions& options, BlockDecomposition& out, Validated& v);

}  // namespace framefix
