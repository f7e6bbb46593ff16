#pragma once
// Boundary snapping of 3-5 curves (the paper's recommended correction; docs/algorithms.md#boundary-snapping).
// A 3-5 curve (valence 3 at one end, 5 at the other) cannot be realised by a hex mesh. Snapping
// moves it onto the boundary: both extremities go to the boundary (a boundary end to the nearest
// feature-curve vertex, an internal node to the nearest boundary vertex), curves left with one
// snapped extremity are snapped too (fixed point), each snapped curve becomes a shortest path on
// the boundary edges with Dirichlet frames turned 45 deg about the path, and the tangency
// constraint is dropped near the paths. A curve whose two ends land on one feature vertex (the
// paper's box with an imprinted arc) gets no path: its feature curve is re-interpolated between
// its ends instead. This module only builds the new boundary conditions: the caller re-solves the
// field (same mesh) and re-extracts the singularities; the snapped curves are invisible to
// holonomy afterwards, so SnapResult::paths must be kept as extra feature curves (blocks/).
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

struct SnapOptions {
    // Tangency-constrained boundary vertices within this Euclidean distance of a snapped path are
    // freed (9 dof). In units of hb = mean boundary edge length; 1..6 work, 0 fails.
    double free_radius_hb = 2.5;
    // Collapse rule: a forced curve's boundary end closer than this to the snap target of its other
    // (already snapped) end is mapped onto that target and gets no path. Units of hb.
    double collapse_radius_hb = 3;
    // A curve end in a tet with a single singular face ("dead end") belongs to the nearest interior
    // node within this distance. Units of h_mean = mean tet edge length.
    double dead_end_radius_h = 3;
    // Angle of the two non-tangent path-frame axes from the surface normal, degrees. 45 is the
    // paper's value and the only one that works (0 and 22.5 leave curves).
    double path_frame_angle_deg = 45;
    // Half-width (in path vertices) of the chord used for path tangents: t_k = x_{k+w} - x_{k-w}.
    // Dijkstra paths zig-zag by up to 45 deg; w = 2 smooths that out.
    int tangent_half_width = 2;
    // Invalid interior nodes are snapped too: the node to the nearest boundary vertex, its curves
    // along with it (the fixed point). Off by default: it helps some parts and not others, so the
    // pipeline's snap rounds try both (docs/algorithms.md#snap-rounds).
    bool snap_invalid_nodes = false;
    // Re-interpolate the Dirichlet frames of feature curves that received a snapped end point
    // between their anchors (paper). Off by default: same singularities, more local change.
    bool interpolate_split_curves = false;
    int threads = 0;  // OpenMP threads, 0 = all
};

// Roles of vertices after snapping (SnapResult::vertex_role).
enum class SnapRole : char {
    Untouched = 0,
    Path = 1,          // on a snapped path: Dirichlet 45 deg frame
    Freed = 2,         // tangency constraint removed (9 dof)
    SharedEnd = 3,     // >= 2 paths end here on a smooth face: left free
    SplitCurve = 4,    // feature-curve vertex whose Dirichlet frame was re-interpolated
};

struct SnappedPath {
    std::vector<int> vertices;      // boundary mesh vertices in path order, >= 2
    Points points;                  // #vertices x 3 positions, model units
    Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> frames;  // #vertices x 9 path frames (SH)
    int source_curve = -1;          // SingularityGraph curve id
    bool forced = false;            // snapped by the fixed point, not itself a 3-5 curve
    bool crosses_features = false;  // no feature-free path existed; feature vertices were allowed
};

struct SnapResult {
    Constraints constraints;        // the new boundary conditions (same vertex space as the input)
    std::vector<SnappedPath> paths; // one per snapped curve whose two targets differ
    int snapped_curves = 0;         // 3-5 curves + curves forced by the fixed point
    std::vector<int> snapped_curve_ids;  // #snapped_curves graph curve ids: the 3-5 curves first, then forced ones
    std::vector<int> node_target;   // #nodes of the graph: snap target vertex of each node, -1 if none
    std::vector<SnapRole> vertex_role;   // #V
    int three_five_curves = 0;      // 3-5 curves found in the graph
    int invalid_nodes_snapped = 0;  // invalid interior nodes sent to the boundary (snap_invalid_nodes)
    int freed_vertices = 0;         // tangency vertices made free (Freed + SharedEnd)
    int collapsed_ends = 0;         // curve ends mapped by the collapse rule
    double hb = 0;                  // mean boundary edge length, model units
    double seconds = 0;
};

// New constraints for the re-solve. `constraints` must be the ones `field` was solved with;
// `field` is only checked for size. Returns the input constraints unchanged (and no path) when
// the graph has no 3-5 curve. Throws framefix::Error("snap") on inconsistent sizes.
SnapResult snap_three_five_curves(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                  const Constraints& constraints, const FrameField& field,
                                  const SingularityGraph& graph, const SnapOptions& options = {});

// Locality of a correction: per-vertex angle (degrees, 0..~63) between the frames of two fields on
// the same mesh, modulo the cube group (the smallest rotation taking one frame to the other).
Eigen::VectorXd frame_rotation_degrees(const FrameField& before, const FrameField& after, int threads = 0);
// Fraction of the vertices whose frame turned by more than `threshold_deg`.
double rotated_fraction(const FrameField& before, const FrameField& after, double threshold_deg = 10, int threads = 0);

}  // namespace framefix
