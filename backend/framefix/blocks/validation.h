#pragma once
// Block validity and conformity (docs/algorithms.md#block-faces-and-patch-cleaning, #block-validation,
// #conformity). Internal to blocks.
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"

namespace framefix {

// One triangle of a block's boundary surface.
struct BoundaryTriangle {
    Eigen::Vector3i verts;         // mesh vertex ids
    int label = 0;                 // neighbouring block id (>= 0) or -1 - CAD surface group
    Eigen::Vector3d normal;        // outward from the block, area-weighted (|n| = 2 area)
};

struct BlockFaces {                // the cleaned patches of one block, for the conformity check
    std::vector<int> label;        // per patch: neighbouring block id, or -1 - CAD surface group
    std::vector<std::vector<Eigen::Vector3d>> corners;  // per patch: positions of its corners
    std::vector<int> cleaned;      // per input triangle: the label of its patch after cleaning
};

// Counts faces/edges/corners of one block's boundary, with `h` the unit of the options. Fills
// everything in `info` except tets, volume, neighbours and centroid.
BlockFaces validate_block(const TetMesh& mesh, const std::vector<BoundaryTriangle>& surface, double h,
                          const BlockOptions& options, BlockInfo& info);

// Every pair of blocks with a shared patch: exactly one patch labelled with the other block on
// each side, 4 corners on it in each block, corner sets equal within tolerance (model units).
std::vector<BlockPair> check_conformity(const std::vector<BlockFaces>& faces, double tolerance);

}  // namespace framefix
