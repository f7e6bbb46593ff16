#pragma once
// A block cut in two by tet distances, and the cut carried on as a sheet through the neighbours
// whose shared faces it splits (docs/algorithms.md#cuts-carried-through-the-neighbours). Internal
// to blocks.
#include <optional>
#include <vector>

#include "framefix/blocks/validation.h"

namespace framefix {

struct CarriedCut {
    std::vector<signed char> side;  // #T: 0 or 1 in a cut block, -1 elsewhere
    std::vector<int> blocks;        // the blocks cut, the first one first
};

// Cuts block b: each of its tets goes to the side (0 or 1) of the boundary triangles it is nearer
// to, by distances through the block's tets from the triangles with tri_side 0 and 1 (tri_side:
// per triangle of v.surface[b], -1 for no seed), whatever faces the cut splits.
CarriedCut cut_alone(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, const Validated& v,
                     int b, const std::vector<int>& tri_side);

// Cuts block b as cut_alone does, and carries the cut on: each face b shares with a neighbour
// that the cut splits carries it into that neighbour, which must be a valid hexahedron entered
// through one face: the cut runs on to the opposite face, between the two faces beside the entry
// that the cut leaves whole, and on through the faces it splits, to the part's boundary or round
// to a block it cut alike. Empty when the cut would enter a block that is no valid hexahedron,
// come round to a block cut otherwise, not split a hexahedron between two opposite faces, or cut
// more than max_blocks blocks.
std::optional<CarriedCut> carry_cut(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out,
                                    const Validated& v, int b, const std::vector<int>& tri_side, int max_blocks);

}  // namespace framefix
