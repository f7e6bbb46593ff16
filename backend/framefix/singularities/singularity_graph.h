#pragma once
// Singularity graph of a frame field (docs/algorithms.md#singularities). Definitions:
// - holonomy of a triangle: the cube rotation g_H picked up by carrying the frame around its
//   three edges (sub-sampled so consecutive frames are < 45 deg apart);
// - a singular triangle has a 90 deg holonomy; its valence is 3 (index +1/4) when the holonomy
//   axis w points along the loop normal n (w.n > 0) and 5 (index -1/4) otherwise; 120/180 deg
//   holonomies are "complex" and belong to nodes;
// - a singular curve is a chain of singular triangles linked through tets with two singular faces;
// - a 3-5 curve is an open curve whose (majority-smoothed) valence differs at its two ends: no hex
//   mesh realises it.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

enum class CurveKind : int { Valence3 = 0, Valence5 = 1, ThreeFive = 2, Other = 3 };
const char* to_string(CurveKind kind);  // "valence3" | "valence5" | "3-5" | "other"

struct SingularCurve {
    int id = 0;
    CurveKind kind = CurveKind::Valence3;
    std::vector<int> faces;              // singular triangles in chain order (topology face ids)
    std::vector<int> valences;           // per face: 3, 5 (raw label)
    Points points;                       // smoothed polyline for display, model units: end node,
                                         // triangle centroids, end node (closed: repeats point 0 last)
    Eigen::Vector3d stable_direction = Eigen::Vector3d::Zero();  // mean holonomy axis
    int ends[2] = {-1, -1};              // node ids; -1 for a closed loop
    bool closed = false;
    double length = 0;
    int transition = -1;                 // 3-5 curves: index in `points` where the valence changes
    int end_valence[2] = {0, 0};         // open curves: majority-smoothed valence at each end (3 or 5)
};

struct SingularNode {
    int id = 0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    bool boundary = false;               // curve end on the boundary
    int n3 = 0, n5 = 0;                  // valence-3 / valence-5 curves meeting here
    int n_complex = 0;                   // complex triangles absorbed
    bool valid = true;                   // interior: table of hex-meshable nodes; boundary: rule
    std::vector<int> tets;               // junction tets clustered into this node (empty on the boundary)
    bool crossing = false;               // added where a curve crosses another near the boundary
};

struct SingularitySummary {
    int curves = 0, valence3 = 0, valence5 = 0, curves_3_5 = 0, nodes = 0, invalid_nodes = 0;
    bool meshable = true;                // curves_3_5 == 0 && invalid_nodes == 0
    int singular_faces = 0;              // faces with a non-identity holonomy (complex included)
    int complex_faces = 0;               // 120/180 deg holonomies (absorbed into nodes)
    int mixed_loops = 0;                 // closed curves with mixed labels (kind Other): field defects
};

struct SingularityGraph {
    std::vector<int> face_valence;       // #faces of the topology: 0 regular, 3, 5, or -1 complex
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> face_axis;  // #faces x 3 holonomy axis w
    std::vector<SingularCurve> curves;
    std::vector<SingularNode> nodes;
    // Curves glued to an ambiguous feature curve (edge_absorption.h): not in `curves`, the nodes
    // or the summary; their ends are -1.
    std::vector<SingularCurve> absorbed;
    SingularitySummary summary;
    double seconds = 0;
    double h_mean = 0;                   // mean mesh edge length, model units
    int subsampled_edges = 0;            // edges transported through their 1/3, 2/3 samples
    int dead_ends = 0;                   // chain ends in a tet with a single singular face
    int dead_ends_attached = 0;          // of which joined to a junction within attach_distance
    int junk_chains = 0;                 // dropped loops from a node back to it (chains.h, chain_ends.h)
    int joined = 0;                      // pass-through nodes (two curve ends) removed by joining
    int crossings = 0;                   // interior nodes added where a curve crosses another near the boundary
};

// Where singular curves are read (docs/algorithms.md#per-edge-holonomy): around triangles with
// per-vertex frames (curves are chains of triangles), or around mesh edges with per-tet frames
// (curves are chains of edges; face_valence and SingularCurve::faces then index topology edges).
enum class Holonomy : int { Triangles = 0, Edges = 1 };

struct SingularityOptions {
    Holonomy holonomy = Holonomy::Triangles;
    // Triangles: an open curve ending on a boundary triangle takes that triangle's label as its
    // valence at that end (the surface singularity there fixes it).
    bool surface_end_labels = true;
    bool labels_along_curves = true;     // triangles: read labels along the curve (curve_labels.h); edges always do
    int smoothing_passes = 5;            // Laplacian passes on the display polylines
    int majority_window = 5;             // label smoothing window along a chain
    int threads = 0;                     // 0 = all
    // Edges whose end frames match within this angle skip the 1/3, 2/3 samples (degrees, 0 =
    // always sample; keep <= 25). Results were identical to full sampling in the tests.
    double direct_match_deg = 20;
    double attach_distance = 3;          // dead-end attachment radius, in mean edge lengths
    double node_core = 1.5;              // triangles this close to a junction node (mean edge
                                         // lengths) do not vote on a curve's valence
    // Curves within this many mean edge lengths of an ambiguous feature curve along their whole
    // length are glued to it (edge_absorption.h; applied by the pipeline, which knows the
    // features). 0 keeps them. 1.5: the curve the field lays along a chamfer's edge runs 0.2-1.2 h
    // off it, and blocks need about 3 h to be resolved.
    double absorb_radius = 1.5;
    // Triangles: a pure curve that passes within one edge length of another pure curve and leaves
    // through the boundary within three is split with it at a node, where that node is valid
    // (docs/algorithms.md#crossings-near-the-boundary).
    bool join_crossings = true;
};

// Counts the summary's curves, nodes and verdict again from `curves` and `nodes` (the face counts
// stay).
void count_summary(SingularityGraph& graph);

SingularityGraph extract_singularities(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                                       const SingularityOptions& options = {});

}  // namespace framefix
