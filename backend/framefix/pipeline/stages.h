#pragma once
// The stages of a run, in the order they run, and what each one produces.
#include <string>

#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "framefix/brep/fillet.h"
#include "framefix/corrections/extrusion.h"
#include "framefix/corrections/snapping.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/hexmesh/hexmesh.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/pipeline/mesh_attempts.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

// In run order; a run stops after the stage RunOptions::stop_after names.
enum class Stage { load, mesh, field, singularities, correction, blocks, hexmesh };

// The stage's name in progress lines and errors: load, mesh, field, singularities, correct, blocks, hexmesh.
const char* stage_name(Stage stage);

struct MeshStage {              // feature curves and the tet mesh that carries them
    FeatureSet features;
    TetMesh tets;
    TetTopology topology;
    std::vector<MeshAttempt> attempts;  // how the tets were made from a B-rep; empty for a mesh file
    int narrow_faces = 0;       // B-rep faces meshed finer than the size (MeshOptions::keep_narrow_faces)
    std::string mesher;         // "tetgen" or "hxt", the one that made the tets; empty for a mesh file
};

struct FieldStage {             // boundary conditions and the frame field solved under them
    Constraints constraints;
    FrameField frames;
};

// Fillet: the original part's field solved again with flat corners under the mapped valence-5
// curves (corrections/flat_corners.h), on the original mesh.
struct FlatCornerSolve {
    bool solved = false;        // false when no mapped valence-5 curve lies on a filleted edge
    int runs = 0;               // stretches of mapped valence-5 curves on filleted edges
    int turned_vertices = 0;    // edge vertices whose Dirichlet frame turned by 45 deg
    SingularityGraph graph;     // the original part's graph after the re-solve
    double seconds = 0;
};

// Method auto: one method (or a combination, "fillet+snap") tried on the input.
struct CorrectionTry {
    std::string method;
    bool ran = false;            // false: skipped (the reason says why: budget, not applicable)
    bool kept = false;           // it changed the part and its result was not dropped as worse
    SingularitySummary after;    // the input's summary when it did not run or was dropped
    double rotated_fraction = 0; // same-mesh methods only (snap), else 0
    bool remeshed = false;
    double seconds = 0;
    std::string reason;
};

// What a correction did. The run's field and singularities are the corrected ones; the field
// and graph that were corrected are kept here.
struct Correction {
    std::string method;
    SingularitySummary before;      // summary of the graph that was corrected
    SingularityGraph graph_before;
    FrameField field_before;
    SnapResult snap;                // filled by method "snap"
    // Filled by method "fillet": one outcome per edge it tried, what it could not do, how OCCT
    // made the fillets, and the filleted solid (the run's mesh, field and graph are then its own).
    std::vector<FilletOutcome> fillets;
    std::vector<std::string> notes;
    std::string fillet_how;
    std::shared_ptr<const BrepModel> filleted;
    // Filled by methods "extrude-curves" and "extrude-nodes": the streamlines, what failed, and the
    // points inserted into the new mesh (constrained_points of them carry the internal constraint).
    ExtrusionPlan extrusion;
    int constrained_points = 0;
    double extrusion_seconds = 0;   // tracing and choosing the points (the remesh is remesh_seconds)
    bool remeshed = false;          // the mesh was replaced (field_before lives on the old one)
    std::optional<SingularityGraph> mapped;  // fillet: the corrected graph on the original part
    int mapped_points = 0, mapped_nodes = 0;  // fillet: curve points and nodes moved onto the concave edges
    std::optional<FlatCornerSolve> flat_corners;  // fillet: the mapped graph offered to the original part
    double fillet_seconds = 0;      // choosing the edges and filleting (OCCT), before the remesh
    int fine_fillet_faces = 0;      // with rims: fillet surfaces meshed finer than h (radius below h)
    double remesh_seconds = 0;      // features and tets of the filleted solid; extrusions: TetGen with the points
    // Method snap: the summary after each round (the re-solve of one snapping; a round that does
    // not lower the 3-5 curves plus invalid nodes is not kept and ends the rounds).
    std::vector<SingularitySummary> snap_rounds;
    // Method auto: the method or combination kept ("" when nothing helped), every try, the budget.
    std::string chosen;
    std::vector<CorrectionTry> tries;
    double budget_s = 0;
    bool changed = false;           // the method changed the set-up; field and graph were re-solved
    bool worse_dropped = false;     // its result was worse than the input and was dropped (never_worse)
    double rotated_fraction = 0;    // vertices whose frame turned by more than 10 degrees
    double seconds = 0;             // method + re-solve + re-extraction
};

// Blocks thinner than the mesh resolves (thin_blocks.h): the run meshed again, finer on the faces
// next to them. The figures of both decompositions, whichever was kept.
struct ThinRefinement {
    bool tried = false;          // false: the reason says why not
    bool kept = false;           // the finer run's mesh, field, graph and blocks are the run's
    std::string reason;
    int spots = 0;               // thin places counted (curve points, sheet triangles parallel to a wall)
    int faces = 0;               // B-rep faces meshed finer
    double min_size = 0;         // their finest edge length, model units
    double thinnest = 0;         // the smallest singular-curve-to-boundary distance, model units
    // The thin places were read from the blocks made without the glued curves' sheets: with them
    // the finer mesh would pass its cap (docs/algorithms.md#sheets-from-glued-curves).
    bool without_glued = false;
    long tets_before = 0, tets_after = 0;
    int count_before = 0, valid_before = 0, pairs_before = 0, conforming_before = 0;
    int glued_before = 0;        // glued curves whose sheets the first blocks used (BlockDecomposition::glued_sources)
    int count_after = 0, valid_after = 0, pairs_after = 0, conforming_after = 0;
    double seconds = 0;          // the finer run, from meshing to its blocks
    int rounds = 0;              // finer runs kept in a row (RunOptions::thin_rounds)
    std::map<int, double> face_size;  // B-rep face -> edge length the kept mesh was made with
};

// Flat corners refined in the blocks (flat_blocks.h, docs/algorithms.md#flat-corner-refinement-in-the-blocks):
// the figures of the blocks as the sheets cut them, and whether the refined blocks replaced them.
struct BlockRefinement {
    bool tried = false;          // a hex mesh judged the refinement; false: the reason says why not
    bool kept = false;           // the run's blocks are the refined ones
    std::string reason;          // why not kept (empty when kept)
    int refined = 0;             // blocks the template split in three (when kept)
    int count_before = 0, valid_before = 0, pairs_before = 0, conforming_before = 0;
    int flat_corners_before = 0, flat_edges_before = 0;
    double seconds = 0;
    // The hex mesh made to judge it (its blocks are the refined ones when a template was kept),
    // which the hexmesh stage reuses: it would make the same one.
    std::shared_ptr<const HexMesh> hexes;
};

struct Timings {  // seconds
    double load = 0, mesh = 0, field = 0, singularities = 0, correct = 0, blocks = 0, hexmesh = 0, total = 0;
};

}  // namespace framefix
