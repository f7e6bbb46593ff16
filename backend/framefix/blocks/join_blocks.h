#pragma once
// Under-faced blocks joined to a neighbour (docs/algorithms.md#under-faced-blocks). Internal to blocks.
#include <optional>
#include <utility>
#include <vector>

#include "framefix/blocks/validation.h"

namespace framefix {

// Each invalid block of fewer than 6 faces (a wedge a sheet cut off) joins the neighbour it
// makes a hexahedron with, or else is shared between two of its three largest contacts that are
// valid hexahedra, where the blocks then score better; greedy, one change per round, at most
// options.join_rounds. `group`: the surface group of every topology face. Updates `out`
// (joined_blocks, split_blocks) and its validation `v`.
void join_under_faced(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                      const BlockOptions& options, BlockDecomposition& out, Validated& v);

// `out` with block `from` shared between its neighbours a and b, each tet to the one whose shared
// face is nearer through the block, cleaned and validated again; none when a or b is then no
// hexahedron. Tried by join_under_faced, between two valid hexahedra, where no single neighbour
// takes a block.
std::optional<std::pair<BlockDecomposition, Validated>> split_between(const TetMesh& mesh, const TetTopology& topo,
                                                                      const std::vector<int>& group, double h,
                                                                      const BlockOptions& options,
                                                                      const BlockDecomposition& out, const Validated& v,
                                                                      int from, int a, int b);

}  // namespace framefix
