#pragma once
// Block validity and conformity (docs/algorithms.md#block-faces-and-patch-cleaning, #block-validation,
// #conformity). Internal to blocks.
#include <map>
#include <tuple>
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"
#include "framefix/mesh/tet_topology.h"

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

// ---- All blocks at once (validate_all.cpp) ----

// A decomposition's validation: what validate_block and check_conformity read, per block.
struct Validated {
    std::vector<std::vector<BoundaryTriangle>> surface;  // per block: its boundary triangles
    std::vector<BlockFaces> faces;               // per block, for the conformity check
    std::vector<std::map<int, int>> shared;      // per block: neighbour -> shared triangles
};

// An earlier validation of the same mesh whose blocks' results can be reused: `old_of_new` maps
// each block to its earlier id (-1: none), `new_of_old` the other way.
struct EarlierBlocks {
    const BlockDecomposition& blocks;
    const Validated& validated;
    std::vector<int> old_of_new, new_of_old;
};

// Face f of tet t on its block's boundary, labelled with the block across (`other`) or, on the
// part's boundary (-1), its surface group (`group`); the normal points out of tet t.
BoundaryTriangle boundary_triangle(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, int f,
                                   int t, int other);
// Each block's boundary triangles (labelled by neighbour block or surface group), triangles
// shared with each neighbour, tets and volume; the rest of out.blocks is reset.
Validated collect_boundaries(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group,
                             BlockDecomposition& out);
// Each collected block validated as a hexahedron; fills out.blocks. Blocks whose boundary is
// unchanged since `earlier` keep its results.
void validate_collected(const TetMesh& mesh, double h, const BlockOptions& options, BlockDecomposition& out,
                        Validated& v, const EarlierBlocks* earlier = nullptr);
Validated validate_blocks(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                          const BlockOptions& options, BlockDecomposition& out);
// `tried`, a copy of `out` with the same partition whose boundary labels in `w` changed, validated
// again: blocks whose boundary is unchanged keep out's results (from `v`); conformity counted.
void validate_relabelled(const TetMesh& mesh, double h, const BlockOptions& options, const BlockDecomposition& out,
                         const Validated& v, BlockDecomposition& tried, Validated& w);
// out.neighbour_pairs and the counts of valid blocks, flat edges and corners, conforming pairs.
void count_conformity(const Validated& v, double h, const BlockOptions& options, BlockDecomposition& out);
// Better blocks: all valid and conforming, then valid minus invalid, then conforming minus other pairs.
std::tuple<bool, int, int> score(const BlockDecomposition& b);

}  // namespace framefix
