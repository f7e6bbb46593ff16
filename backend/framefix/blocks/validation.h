#pragma once
// Block validity and conformity (docs/algorithms.md#block-faces-and-patch-cleaning, #block-validation,
// #conformity). Internal to blocks.
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"

namespace framefix {

// Counts faces/edges/corners of one block's boundary, with `h` the unit of the options. Fills
// everything in `info` except tets, volume, neighbours and centroid.
BlockFaces validate_block(const TetMesh& mesh, const std::vector<BoundaryTriangle>& surface, double h,
                          const BlockOptions& options, BlockInfo& info);

// Every pair of blocks with a shared patch: exactly one patch labelled with the other block on
// each side, 4 corners on it in each block, corner sets equal within tolerance (model units).
std::vector<BlockPair> check_conformity(const std::vector<BlockFaces>& faces, double tolerance);

}  // namespace framefix
