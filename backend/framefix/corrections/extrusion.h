#pragma once
// The two extrusion corrections (paper sections 4.1 and 4.2; docs/algorithms.md#extrusions).
// Feature-curve extrusion traces the sheets that continue a concave (or imprinted) feature curve
// into the solid along the initial field; singular-node extrusion traces a streamline from each
// end of each 3-5 curve along its stable direction. Either way the streamline points are
// inserted into a new tet mesh of the same boundary and constrain the field there: tangent to
// the sheet (f has t_e x v_k as an axis) or singular about the streamline (a forced singular
// curve). This module plans: it traces, rejects what fails, and lists the points and their
// constraints; the caller remeshes (mesh/boundary_surface.h + TetGen -i) and re-solves.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/singularities/singularity_graph.h"
#include "framefix/streamlines/streamlines.h"

namespace framefix {

struct ExtrusionOptions {
    double reach_h = 3;          // a feature curve this close to a 3-5 curve causes it (mean edge lengths h)
    double boundary_gap_h = 0.5; // inserted points keep this distance from the boundary (h): no slivers
    double point_gap_h = 0.3;    // ... and from each other (h): no near-duplicates
    // Neighbouring streamlines of one sheet whose gap grows beyond split_gap_h h and split_ratio x
    // their seed spacing split the sheet (the paper's curved box): the sheet is not used.
    double split_gap_h = 3;
    double split_ratio = 4;
    // Node extrusion: free vertices within tube_radius_h h of a streamline get the frames of a
    // singular curve of its valence (the cross turns by +-theta/4 about it); a line of singular
    // frames alone is too thin to force a singularity (a line has no capacity in 3D). Vertices
    // closer than core_radius_h h get the singular frame itself.
    double tube_radius_h = 1.2;
    double core_radius_h = 0.25;
    double ring_radius_h = 0.5;  // node extrusion: radius of the refining rings (h); 0 = none
    int threads = 0;             // OpenMP threads for the tracing, 0 = all
};

struct ExtrusionStreamline {
    std::string source;          // "Edge18 sheet 1" | "node 3"
    Streamline line;             // points, stop reason, length
    bool used = false;           // its points constrain the field
    std::string failure;         // why it is not used; empty when used
    // Node extrusion: the valence forced along it (that of the 3-5 curve at its start) and the
    // frame axis normal to it at the start (the phase of the forced winding).
    int valence = 0;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    // Node extrusion, per point: the phase (radians) of the winding about the reference axis
    // carried along, fitted to the initial field where it already winds and spread from there.
    std::vector<double> phase;
};

struct ExtrusionFailure {
    std::string what;            // "Edge18 sheet 1", "node 3", "3-5 curve 2"
    std::string why;
};

struct ExtrusionPlan {
    std::vector<ExtrusionStreamline> streamlines;
    std::vector<ExtrusionFailure> failures;   // empty when everything traced reached the boundary
    Points points;               // #I x 3 points to insert, model units
    Points axes;                 // #I x 3 unit: the sheet's normal (curves) or the singular axis (nodes)
    bool singular = false;       // nodes: the points get singular frames, else tangency to the sheet
    // Nodes: rings around the streamlines, inserted to refine the mesh there (their frames
    // come from the tube constraint).
    Points ring_points;
    bool refine_boundary = false;  // nodes: TetGen may split boundary triangles (no -Y) near the forced ends
    std::vector<int> edges;      // curves: the B-rep edges extruded
    double seconds = 0;
};

// Sheets from the feature curves of valence 2, 3 or 4 within reach of a 3-5 curve.
ExtrusionPlan plan_curve_extrusion(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                   const FrameField& field, const SingularityGraph& graph,
                                   const ExtrusionOptions& options = {});

// Streamlines from both ends of every 3-5 curve along its stable direction; from an interior
// node both ways (the paper traced boundary ends only).
ExtrusionPlan plan_node_extrusion(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                                  const SingularityGraph& graph, const ExtrusionOptions& options = {});

// `constraints` (the boundary conditions of `mesh`, remeshed with plan.points inserted) plus the
// plan's internal constraint at each free vertex found at an inserted point, and for node
// extrusion the tube around its streamlines. Returns how many vertices were constrained.
int add_internal_constraints(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& constraints,
                             const ExtrusionOptions& options = {});

}  // namespace framefix
