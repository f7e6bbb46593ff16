#pragma once
// Block validity and conformity (docs/algorithms.md#block-faces-and-patch-cleaning, #block-validation,
// #conformity). Internal to blocks.
#include <map>
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"

namespace framefix {

// Counts faces/edges/corners of one block's boundary, with `h` the unit of the options. Fills
// everything in `info` except tets, volume, neighbours and centroid. Patches labelled with a
// block of `dissolve` (neighbours whose own side cleaned the contact away as a sliver) merge
// into their longest-contact neighbour patch after cleaning.
BlockFaces validate_block(const TetMesh& mesh, const std::vector<BoundaryTriangle>& surface, double h,
                          const BlockOptions& options, BlockInfo& info, const std::vector<int>& dissolve = {});

// Pairs of blocks where one side kept a patch labelled with the other and the other side kept
// none: per block, the neighbours whose contact it must dissolve too.
std::vector<std::vector<int>> one_sided_contacts(const std::vector<BlockFaces>& faces,
                                                 const std::vector<std::map<int, int>>& shared);

// Every pair of blocks with a shared patch: exactly one patch labelled with the other block on
// each side, 4 corners on it in each block, corner sets equal within tolerance (model units).
std::vector<BlockPair> check_conformity(const std::vector<BlockFaces>& faces, double tolerance);

}  // namespace framefix
