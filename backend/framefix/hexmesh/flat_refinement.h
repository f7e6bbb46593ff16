#pragma once
// Flat block edges and their refinement (internal to hexmesh; docs/algorithms.md#flat-edge-refinement).
// After snapping, a block can have an edge where its two faces meet at about 180 degrees (the
// paper's flat corner): every hex along it has a zero Jacobian there. Seen across the edge, such a
// block is a triangle with a corner on one side; the template cuts that triangle into three
// quads around a new interior point, extruded along the edge, so the block becomes three blocks
// with proper corners.
#include <functional>
#include <string>
#include <vector>

#include "framefix/hexmesh/block_structure.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct FlatCount {
    int edges = 0;                 // (block, edge) pairs whose two other faces meet flat along the whole edge
    int corners = 0;               // (block, corner) pairs where two of the corner's edges leave flat
    std::vector<Eigen::Vector3d> where;  // the flat corners' positions, model units
};

// A corner is flat when two of its three block edges leave it more than 180 - flat_deg degrees
// apart (directions taken `reach` model units along each edge, at most 40 % of it); an edge is
// flat when the two other edges are, at both its ends.
FlatCount count_flat(const BlockComplex& cx, double reach, double flat_deg);

struct FlatRefinement {
    FlatCount before, after;
    int blocks_before = 0, blocks_after = 0;
    int refined = 0;                    // blocks split into three by the template
    std::vector<std::string> skipped;   // flat edges left as they are, each with the reason
};

// Splits every block with a flat edge into three blocks by the template, with the blocks the
// flat edge runs on into face to face (its ends must lie on the part's boundary); a neighbour
// across a face the template splits is split by a sheet through its neighbours to the boundary.
// One block at a time, on a copy that replaces `cx` only when keep(copy) says its hexes are
// better. An edge counts as flat here when its two other edges leave one end more than
// 180 - flat_deg and the other end more than 180 - end_deg degrees apart. Blocks left as they
// are are listed in `skipped` with the reason; `before` and `after` count with these thresholds.
FlatRefinement refine_flat_edges(const TetMesh& mesh, double reach, double flat_deg, double end_deg, BlockComplex& cx,
                                 const std::function<bool(const BlockComplex&)>& keep);

}  // namespace framefix
