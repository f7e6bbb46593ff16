#pragma once
// From sheets to a tet labelling (docs/algorithms.md#cut-edges, #partition, #staircase-cleaning). Internal to blocks.
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"

namespace framefix {

// #Ed flags (topology edge space): the mesh edge crosses or touches a sheet triangle.
std::vector<char> cut_by_sheets(const TetMesh& mesh, const TetTopology& topo, const SheetSoup& sheets, int threads);

// Sets the flag of every edge passing within `radius` of a polyline point set (#S x 3): the k
// sheets of a singular curve meet on a noisy polyline, the tube closes them.
void cut_near_polylines(const TetMesh& mesh, const TetTopology& topo, const Points& polyline_points,
                        double radius, std::vector<char>& cut);

// Vertex components over uncut edges -> small ones adopt neighbours -> tets by majority ->
// face-connected pieces -> small pieces merge -> spike smoothing. Returns #T labels 0..n-1.
Eigen::VectorXi partition_tets(const TetMesh& mesh, const TetTopology& topo, const std::vector<char>& cut,
                               const BlockOptions& options);

// Splits each label into face-connected pieces; pieces below `threshold` tets merge into the
// neighbour with the most shared faces (only into a larger piece, so no two swap). Returns the
// number of pieces merged. Also run after the staircase cleaning, which can cut a few tets of a
// block off from the rest (notch_filleted at 0.6 x: two tets left on the boundary, a second
// boundary sphere of the block).
int merge_small_pieces(const TetTopology& topo, Eigen::VectorXi& labels, int threshold);

// Pieces below this many tets merge: min_piece_fraction of the tets, at least 10.
int small_piece_tets(int num_tets, const BlockOptions& options);

// Rule 7: moves the minority side at non-manifold block-boundary edges and pinched vertices until
// every block boundary is a manifold (<= 10 passes each). Returns relabelled, compacted labels.
// With `only` (#labels flags), only the flagged blocks' boundaries are mended: a block just
// joined to another, and its neighbours.
Eigen::VectorXi clean_staircase(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi labels,
                                const std::vector<char>& only = {});

// Relabels to 0..n-1 in order of first appearance; returns n.
int compact_labels(Eigen::VectorXi& labels);

}  // namespace framefix
