#pragma once
// A conforming hexahedral mesh from a valid block decomposition (docs/algorithms.md#hex-mesh):
// every block edge gets a hex count (equal on opposite edges of a block, shared between
// blocks), edges are split by arc length, faces are Coons patches projected onto the block
// interfaces and the CAD surfaces, block interiors are transfinite interpolations of their six
// faces, then smoothed with the topology fixed. Vertices on a shared edge or face exist once,
// so the mesh has no hanging node by construction.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/blocks/blocks.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct HexMeshOptions {
    // Blocks with a flat edge are split in three first (docs/algorithms.md#flat-edge-refinement).
    bool refine_flat = true;
    double flat_deg = 35;    // a corner whose block edges leave more than 180 - this apart is flat (reported)
    double size = 0;         // target hex edge length, model units; 0 = kDefaultHexSizeInH x tet h
    int layers = 0;          // > 0: the shortest edge class gets this many hexes (overrides size)
    int smoothing_rounds = 30;  // guarded Laplacian rounds on the vertices off the part's boundary
    int order = 1;           // 1: 8-node hexes, 2: also the 12 edge midpoints (20-node)
};

// Two tet edges per hex edge by default: the tet boundary the faces are projected onto then
// resolves each hex face with a few triangles.
constexpr double kDefaultHexSizeInH = 2.0;

// Where boundary vertices go: the closest point on B-rep face `face` / edge `edge` (1-based
// tags). Empty functions keep them on the tet mesh's boundary triangles.
struct CadProjector {
    std::function<Eigen::Vector3d(int face, const Eigen::Vector3d&)> to_face;
    std::function<Eigen::Vector3d(int edge, const Eigen::Vector3d&)> to_edge;
};

struct HexBlockStats {
    std::array<int, 3> counts{0, 0, 0};  // hexes along the block's three directions
    int hexes = 0;
    double min_scaled_jacobian = 0;
};

struct HexQuality {
    double min_scaled_jacobian = 0, mean_scaled_jacobian = 0;
    double share_sj_ge_0_5 = 0;   // fraction of hexes whose minimum scaled Jacobian is >= 0.5
    int inverted = 0;             // hexes with a corner scaled Jacobian <= 0
    double volume = 0;            // sum of the hexes' (trilinear) volumes, model units^3
};

// What the flat-edge refinement did to the block complex (counts over (block, edge) and
// (block, corner) pairs).
struct HexRefinement {
    bool applied = false;          // the refinement was tried (HexMeshOptions::refine_flat)
    bool kept = false;             // the refined complex gave the better hexes and was meshed
    double plain_min_scaled_jacobian = 0, refined_min_scaled_jacobian = 0;  // when tried
    int blocks_before = 0, blocks = 0;
    int pairs_before = 0, pairs = 0;   // faces shared by two blocks (each one whole face)
    int flat_edges_before = 0, flat_corners_before = 0, flat_edges = 0, flat_corners = 0;
    int refined = 0;               // blocks split into three (in the kept mesh only when `kept`)
    std::vector<std::string> skipped;  // flat edges left, with the reason
    std::vector<Eigen::Vector3d> flat_corner_positions;  // of the meshed complex, model units
};

struct HexMesh {
    bool done = false;
    std::string reason;            // why not, when !done
    Points points;                 // #V x 3, model units
    std::vector<std::array<int, 8>> hexes;  // VTK_HEXAHEDRON / C3D8 node order
    std::vector<std::array<int, 12>> midpoints;  // order 2: edge midpoints in C3D20 order, else empty
    std::vector<int> hex_block;    // #hexes
    std::vector<double> scaled_jacobian;  // #hexes: minimum over the 8 corners
    std::vector<std::array<int, 4>> boundary_quads;  // outward quads on the part's boundary
    std::vector<int> quad_face;    // #boundary_quads: B-rep face tag (1-based; 0 unknown)
    std::vector<HexBlockStats> blocks;
    HexQuality quality;
    double size = 0;               // hex edge length aimed at, model units
    double part_volume = 0;        // the solid's volume (the tets' for a mesh input), model units^3
    int edge_classes = 0;          // groups of block edges that share one count
    // Neighbour pairs whose shared face matched by its corners although they lay further apart
    // than the blocks' conformity tolerance. Such a mesh is kept only without inverted hexes.
    int off_tolerance_pairs = 0;
    HexRefinement refinement;
    double seconds = 0;
};

// Never throws for a decomposition it cannot mesh: done = false and the reason (an invalid
// block, a non-conforming pair, faces that do not close into a cube).
HexMesh build_hexmesh(const TetMesh& mesh, const BlockDecomposition& blocks, const HexMeshOptions& options,
                      const CadProjector& cad = {});

// Each tet's block after the flat-edge refinement of `hm` (made from the blocks `tet_block`
// labels): a tet of a block the refinement cut goes to the part whose hex centre is nearest; the
// parts' ids are hm's (a cut block's first part keeps its id). tet_block itself when nothing was cut.
Eigen::VectorXi refined_tet_blocks(const TetMesh& mesh, const TetTopology& topo, const Eigen::VectorXi& tet_block,
                                   const HexMesh& hm);

// The 12 edges of a hex as pairs of its VTK corners, in C3D20's (and VTK_QUADRATIC_HEXAHEDRON's)
// order of edge midpoints.
constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// Minimum scaled Jacobian over the 8 corners of a hex in VTK order (1 for a cube, <= 0 inverted).
double hex_scaled_jacobian(const std::array<Eigen::Vector3d, 8>& p);
// Volume of the trilinear hex (2-point Gauss, exact for the trilinear map).
double hex_volume(const std::array<Eigen::Vector3d, 8>& p);

}  // namespace framefix
