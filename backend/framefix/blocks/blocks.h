#pragma once
// Block decomposition of a (corrected) frame field (docs/algorithms.md#blocks):
// separatrix sheets are traced from the singular curves (valence k: k sheets), from the concave
// feature curves (2 inward sheets), from the imprinted curves the field follows (1 sheet) and from the snapped paths of the boundary snapping (2 inward
// sheets); the mesh edges the sheets cut split the vertices into components, the tets take their
// vertices' majority label, and the labelling is cleaned until every block boundary is a closed
// manifold. Each block is then checked to be a topological hexahedron (6 disk faces, 12 edges, 8
// corners of degree 3) and each pair of neighbouring blocks to share one whole face, corner to
// corner. Flat block edges/corners (zero-Jacobian after snapping) are found with the normal-angle
// proxy and reported; hexmesh/ meshes valid blocks with hexes and refines flat edges there.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/corrections/snapping.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

struct BlockOptions {
    double step = 0.4;             // streamline RK4 step, in mean edge lengths h
    double seed_spacing = 1;       // seeds along singular curves, in h
    double seed_radius = 0.5;      // radius of the circle on which separatrix directions are found, in h
                                   // (1 h fails when a curve is 1-2 h from the wall)
    double stop_distance = 1.5;    // streamlines stop this close to a singular curve, in h
    double match_deg = 40;         // consecutive seeds' directions pair into a ribbon below this angle
    double overshoot = 1;          // lateral widening of feature/snapped-path ribbons, in h (rule 6)
    double tube_radius = 1;        // mesh edges this close to a singular curve are cut, in h
    int min_component_vertices = 8;   // smaller vertex components adopt a neighbour's label
    double min_piece_fraction = 0.005;  // face-connected pieces below this fraction of the tets merge
    // Rounds of "a block with at most 3 faces (a lens between two sheets that should be one)
    // joins the neighbour it shares the most boundary with" (0 = off).
    int lens_rounds = 10;
    // Rings of 3 faces (boundary Euler characteristic 0) count as lenses; where one did, the blocks
    // are also made with them left whole for the ring cuts, and the better kept (build_blocks).
    bool ring_lenses = true;
    // Rounds of "an invalid block of fewer than 6 faces joins a neighbour when the two together
    // are a hexahedron and the blocks score better" (0 = off; docs/algorithms.md#under-faced-blocks).
    int join_rounds = 10;
    // Within those rounds: "where no single neighbour makes one, the block is shared between two
    // of its largest contacts, each tet to the nearer" (docs/algorithms.md#under-faced-blocks).
    bool split_wedges = true;
    // Cuts of "an invalid block that is a pentagonal to octagonal prism is cut into hexahedra
    // where the blocks then have more valid blocks and no more non-conforming pairs" (0 = off;
    // docs/algorithms.md#prism-cuts).
    int prism_rounds = 20;
    double patch_merge_area = 2;   // block-face patches below this area merge, in h^2
    // Patches touching <= 3 other patches merge below this area, in h^2: a face of a hexahedron has
    // 4 neighbouring faces, so such a patch is a sliver where four blocks meet along a line.
    double sliver_area = 6;
    // Patches with w = 2 area / perimeter below this merge (staircase strips), in h. 0.75 suits
    // gmsh meshes; TetGen meshes leave ~0.8 h strips where 4 blocks meet, and a real face of
    // a block >= 3 h thick has w >= 1.5 h.
    double thin_width = 1.0;
    double bevel_width = 2.5;      // strip-like patches below this width between two ~90 deg flanks split, in h
    double conform_tolerance = 2.5;  // corner positions of a shared face must match within this, in h
    // Corner lines of concave-curve curtains emit sheets (docs/algorithms.md#curtain-corners).
    bool curtain_corners = true;
    // Sheets at interior nodes where three or more singular curves meet
    // (docs/algorithms.md#junction-nodes). Continue: cross-extend every sheet past the node.
    // Drop: not the continuations that another curve's sheet at the node already is.
    // DropAndClose: those dropped, and every sheet carried to the node and 0.5 h past it.
    // ...AndZip: also, where one curve runs straight on through the node into another, their end
    // streamlines are zipped across it, as one curve's would be.
    // ContinueAndClose: every sheet continued, and also carried to the node and 0.5 h past it.
    enum class Junctions { Continue, Drop, DropAndClose, DropAndZip, DropCloseAndZip, ContinueAndClose };
    Junctions junctions = Junctions::Continue;
    // Also partition with the other Junctions modes where the graph has such a node (the zip
    // modes only where a curve runs straight on through one), and keep the best blocks
    // (build_blocks' score).
    bool try_junctions = true;
    // Also partition with the curves glued to ambiguous edges as sheet sources, where the graph has
    // any, and keep the better blocks (docs/algorithms.md#sheets-from-glued-curves).
    bool try_glued = true;
    double flat_deg = 35;          // a block edge whose two face normals are closer than this is flat
    int threads = 0;               // OpenMP threads, 0 = all
};

struct BlockInfo {
    std::vector<int> tets;         // tet ids of the block, ascending
    double volume = 0;             // model units^3
    bool valid = false;            // topological hexahedron with a manifold sphere boundary
    int faces = 0, edges = 0, corners = 0;  // counts on the block's boundary after patch cleaning
    int face_corners_off = 0;      // sum over the faces of |corners on the face - 4|
    int euler = 0;                 // Euler characteristic of the boundary surface (2 for a sphere)
    bool manifold = false;         // every boundary edge in exactly two boundary triangles
    // Flat-edge proxy (docs/algorithms.md#flat-edges-and-corners): outward mean normals of the two faces, within 2 h of their common
    // chain, closer than flat_deg (about 90 deg at a proper edge). Counted per pair of adjacent faces.
    int flat_edges = 0;
    int flat_corners = 0;          // corners where two incident faces' mean normals (within 2 h) are < flat_deg apart
    std::vector<int> neighbours;   // neighbouring block ids, ascending
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // mean of the block's vertices, model units
    std::string reason;            // empty if valid, else the first failed test ("faces 5", ...)
};

struct BlockPair {                 // two blocks that share boundary
    int a = -1, b = -1;            // block ids, a < b
    bool conforming = false;       // exactly one shared face on each side, corners matching
    bool one_face = false;         // one shared face with 4 corners on each side (conforming but for
                                   // the corner positions, which may be further apart than the tolerance)
    std::string reason;            // why not
};

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
    std::vector<int> patch;        // per input triangle: its patch (index into label)
    std::vector<std::vector<int>> corner_vertices;  // per corner: the mesh vertices of its cluster
    std::vector<std::vector<int>> corner_patches;   // per corner: its patches, ascending
    std::vector<Eigen::Vector3d> corner_position;   // per corner: mean of its cluster, model units
};

struct BlockSurfaces {            // smoothed for display (docs/algorithms.md#block-surfaces)
    Points points;                 // smoothed positions, model units
    Triangles triangles;           // each block's boundary triangles, outward; an interface twice
    Eigen::VectorXi block;         // #triangles: the block it bounds
    Eigen::VectorXi neighbour;     // #triangles: the block across, -1 on the part's boundary
    std::vector<Points> edges;     // each block's edges: polylines between its corners, smoothed
    std::vector<int> edge_block;   // #edges: the block of each polyline
};

struct SheetSoup {                 // the separatrix sheets, for display (VTK)
    Points points;                 // #P x 3, model units
    Triangles triangles;           // #S x 3 indices into points
    Eigen::VectorXi source;        // #S: source id of each triangle (index into `source_kind`)
    std::vector<std::string> source_kind;  // per source: "singular:<curve id>", "concave:<B-rep edge>",
                                           // "snapped:<path index>", "ring:<block>"
};

struct SheetStats {
    int sources = 0, streamlines = 0, ribbons = 0, cross_ribbons = 0;
    int left_solid = 0, reached_singularity = 0, sharp_turn = 0, limit_cycle = 0, max_steps = 0, start_outside = 0;
    int cut_edges = 0;             // mesh edges cut by sheets or the singular-curve tubes
};

struct BlockDecomposition {
    Eigen::VectorXi tet_block;     // #T block id of each tet, 0..count-1
    int count = 0;                 // number of blocks
    std::vector<BlockInfo> blocks; // #count
    int valid = 0;                 // blocks that are topological hexahedra
    std::vector<BlockPair> neighbour_pairs;  // every pair of blocks sharing boundary triangles
    int conforming_pairs = 0, pairs = 0;
    int flat_corners = 0, flat_edges = 0;    // summed over blocks (a shared edge counts in each block)
    SheetSoup sheets;
    BlockSurfaces surfaces;        // smoothed block boundaries and edges, for display
    // Per block: its boundary triangles and their cleaned faces and corners (what the hex mesh
    // is built from).
    std::vector<std::vector<BoundaryTriangle>> boundary;
    std::vector<BlockFaces> faces;
    SheetStats stats;
    // Imprinted curves (B-rep edge ids, ascending) the field does not follow: they emit no sheet
    // and block faces run across them (the hex mesh will not follow them either).
    std::vector<int> ignored_imprints;
    // Singular curves (ids) that emit no sheet: boundary to boundary, under 1 h (sheet_sources.h).
    std::vector<int> boundary_wisps;
    // Ambiguous feature curves (a chamfer's 135 degree edges; B-rep edge ids, ascending) that the
    // block faces run across, chosen so that the blocks are hexahedra
    // (docs/algorithms.md#block-faces-across-ambiguous-edges).
    std::vector<int> joined_edges;
    // Curves glued to ambiguous feature curves (SingularityGraph::absorbed) that emit sheets: the
    // blocks are made with and without them and the better kept; 0 when without.
    int glued_sources = 0;
    // Snapped paths (indices into the paths given) on a convex surface: they emit no sheet, and the
    // curtain below each end on a curved concave curve has a corner line that does
    // (docs/algorithms.md#curtain-corners). `curtain_corners` counts those lines.
    std::vector<int> convex_paths;
    int curtain_corners = 0;
    // Meridian sheets across rings (blocks that were solid tori: a tube), docs/algorithms.md#ring-cuts.
    int ring_cuts = 0;
    // Rings of 3 faces that joined a neighbour as lenses while these blocks were made; rings_kept:
    // these blocks were made with such rings left whole, as they scored better (docs/algorithms.md#lenses).
    int ring_lenses = 0;
    bool rings_kept = false;
    // Under-faced blocks joined to a neighbour (docs/algorithms.md#under-faced-blocks).
    int joined_blocks = 0;
    // Under-faced blocks shared between two neighbours (docs/algorithms.md#under-faced-blocks).
    int split_blocks = 0;
    // Prism blocks cut into hexahedra (docs/algorithms.md#prism-cuts).
    int prism_cuts = 0;
    // Of those, the cuts carried on through the neighbours whose faces they split
    // (docs/algorithms.md#cuts-carried-through-the-neighbours).
    int carried_cuts = 0;
    // Triangular prism blocks made hexahedra by splitting a boundary side face in two
    // (docs/algorithms.md#triangular-prisms).
    int triangle_folds = 0;
    // Per tet: whether it lay in an invalid block or a block of a non-conforming pair before any
    // under-faced block was joined or prism cut; empty when none was. The thin-block refinement
    // reads its thin places there: a wedge joined away is still where the mesh was too coarse.
    std::vector<char> trouble_before_joins;
    // Junction nodes (docs/algorithms.md#junction-nodes): each mode tried, in order, with its
    // blocks, and the one kept; empty when the graph has no such node.
    struct JunctionTry {
        std::string mode;          // "continue", "drop", "drop+close", "drop+zip", "drop+close+zip", "continue+close"
        int count = 0, valid = 0, pairs = 0, conforming_pairs = 0;
    };
    std::vector<JunctionTry> junction_tries;
    std::string junction_mode;
    double h = 0;                  // mean mesh edge length used as the unit of the options
    double seconds = 0;            // total wall clock
    double seconds_sheets = 0, seconds_partition = 0, seconds_validation = 0;
};

// Per tet: whether its block is invalid or in a non-conforming pair.
std::vector<char> tets_in_trouble(const BlockDecomposition& blocks);

// Throws framefix::Error("blocks") when the field or graph does not belong to the mesh.
BlockDecomposition build_blocks(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                const FrameField& field, const SingularityGraph& graph,
                                const std::vector<SnappedPath>& paths, const BlockOptions& options = {});

// `before` with its tets' blocks replaced by `tet_block` (ids 0..n-1: the parts the flat-edge
// refinement cut, docs/algorithms.md#flat-corner-refinement-in-the-blocks) and validated again;
// the sheets and what was done to make the blocks stay before's.
BlockDecomposition relabelled_blocks(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                     const std::vector<SnappedPath>& paths, const BlockDecomposition& before,
                                     Eigen::VectorXi tet_block, const BlockOptions& options = {});

}  // namespace framefix
