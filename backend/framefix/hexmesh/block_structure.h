#pragma once
// The block decomposition as a cell complex (internal to hexmesh): corners, edges and faces
// shared between blocks, each once, and each block as a cube over them.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct ComplexCorner {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    std::vector<int> vertices;     // mesh vertices of the corner's clusters in every block
};

struct ComplexEdge {
    int a = -1, b = -1;            // corners, a < b
    Points polyline;               // from corner a to corner b: a, the chain's mesh vertices, b
    std::vector<int> chain;        // the mesh vertices between, in order
    int count = 1;                 // hexes along it
};

struct ComplexFace {
    std::array<int, 4> corners{};  // cyclic; s runs corners[0] -> [1], t runs [0] -> [3]
    std::vector<Eigen::Vector3i> triangles;  // the tet-mesh triangles it was cut from, outward from its first block
    bool boundary = false;         // on the part's boundary (else between two blocks)
};

struct ComplexBlock {
    int id = -1;                   // block id in the decomposition
    std::array<int, 8> corners{};  // local corner (i, j, k) in {0,1}^3 at index i + 2 j + 4 k, right-handed
    std::array<int, 6> faces{};    // i = 0, i = 1, j = 0, j = 1, k = 0, k = 1
    std::array<int, 12> edges{};   // along i at (j, k): (j + 2 k); along j at (i, k): 4 + (i + 2 k); along k: 8 + (i + 2 j)
};

struct BlockComplex {
    std::vector<ComplexCorner> corners;
    std::vector<ComplexEdge> edges;
    std::vector<ComplexFace> faces;
    std::vector<ComplexBlock> blocks;
    std::string failure;           // empty when the decomposition forms a complex of cubes
    int off_tolerance_pairs = 0;   // pairs meshed although their corners were off the blocks' tolerance
};

BlockComplex block_complex(const TetMesh& mesh, const BlockDecomposition& blocks);

// Local corner index of (i, j, k).
constexpr int local_corner(int i, int j, int k) { return i + 2 * j + 4 * k; }
// Local corners of local face `lf` (i = 0, i = 1, j = 0, ...) in cyclic order.
std::array<int, 4> face_local_corners(int lf);
// Local corners at the start and end of local edge `e` (ComplexBlock::edges' numbering).
std::array<int, 2> edge_local_corners(int e);
// Local edge along `axis` through local corner `l`.
int edge_at(int l, int axis);

}  // namespace framefix
