#pragma once
// The hex vertices of a block complex (internal to hexmesh): each corner, edge and face of the
// complex numbers its vertices once, and each block reads its boundary from them.
#include <vector>

#include <Eigen/Core>

#include "framefix/hexmesh/block_structure.h"
#include "framefix/hexmesh/hexmesh.h"

namespace framefix {

struct HexGrid {
    std::vector<Eigen::Vector3d> points;
    std::vector<std::vector<int>> edge_ids;   // per complex edge: count + 1 ids from corner a to b
    struct FaceGrid { int ns = 0, nt = 0; std::vector<int> ids; int at(int s, int t) const { return ids[t * (ns + 1) + s]; } };
    std::vector<FaceGrid> face_ids;           // per complex face: (ns + 1) x (nt + 1) ids, s fastest
    struct BlockGrid {
        std::array<int, 3> n{0, 0, 0};
        std::vector<int> ids;                 // (n0 + 1)(n1 + 1)(n2 + 1), i fastest
        int at(int i, int j, int k) const { return ids[(k * (n[1] + 1) + j) * (n[0] + 1) + i]; }
    };
    std::vector<BlockGrid> block_ids;         // per complex block
};

// Arc length of a polyline, model units.
double polyline_length(const Points& p);

// Hex counts of the complex's edges (ComplexEdge::count): opposite edges of a block are one
// class; each class gets max(1, round(mean length / size)). Returns the number of classes and
// sets `size` when it is derived from `layers`.
int assign_edge_counts(BlockComplex& cx, double& size, int layers);

// Corner, edge and face vertices (Coons patches projected onto the face's triangles and, with
// `cad`, onto the B-rep), then each block's interior by transfinite interpolation.
HexGrid hex_grid(const TetMesh& mesh, const BlockComplex& cx, const CadProjector& cad);

// Guarded Laplacian rounds on every vertex off the part's boundary (block interiors, interfaces
// and interior block edges alike): a vertex moves to the mean of its hex-edge neighbours, and
// the move is kept only when it does not lower the smallest scaled Jacobian of its hexes.
void smooth_hex_mesh(int rounds, HexMesh& mesh);

// The 8 corners of hex (i, j, k) of block grid `g`, in VTK order.
std::array<int, 8> hex_of(const HexGrid::BlockGrid& g, int i, int j, int k);

}  // namespace framefix
