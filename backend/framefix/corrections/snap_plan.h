#pragma once
// Which curves to snap and where their extremities go (internal to corrections;
// docs/algorithms.md#extremities, #snap-targets, #snap-plan-and-collapse-rule):
// - extremity kinds: a curve end on a boundary triangle is a boundary node; an end at a junction
//   cluster is an interior node; a "dead end" (an interior node with a single curve end) belongs to
//   the nearest interior junction within dead_end_radius_h, else it is treated like a boundary end;
// - targets: boundary end -> nearest feature-curve vertex; interior node -> nearest boundary vertex;
// - fixed point: every curve with one snapped extremity is snapped too, with the collapse rule for
//   forced curves whose boundary end is close to the target of their snapped end.
// Curve "junk" (<= 2 triangles that start and end at the same junction or are all complex) and
// closed loops are never snapped.
#include <array>
#include <vector>

#include "framefix/corrections/boundary_graph.h"
#include "framefix/corrections/snapping.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

enum class EndKind : int { Boundary = 0, Junction = 1, DeadEnd = 2 };

struct CurveEnds {
    std::vector<int> node_rep;       // #nodes: node id after merging dead ends into junctions
    std::vector<EndKind> node_kind;  // #nodes, kind of node_rep[n]
    std::vector<char> excluded;      // #curves, 1 for junk chains and closed loops (never snapped)
};

CurveEnds classify_curve_ends(const SingularityGraph& graph, double dead_end_radius);

struct SnapPlan {
    std::vector<int> curves;                  // snapped curve ids: 3-5 curves, then forced in discovery order
    std::vector<char> forced;                 // parallel to curves
    std::vector<std::array<int, 2>> targets;  // parallel to curves: target vertex of ends[0], ends[1]
    std::vector<int> node_target;             // #nodes: target vertex (via node_rep), -1 if not snapped
    int three_five_curves = 0;
    int invalid_nodes = 0;                    // invalid interior nodes sent to the boundary
    int collapsed_ends = 0;
};

// `graph.curves[i].ends` index `graph.nodes`; positions of nodes are the snap sources.
SnapPlan plan_snapping(const SingularityGraph& graph, const CurveEnds& ends, const BoundaryGraph& boundary,
                       const Points& points, const SnapOptions& options);

}  // namespace framefix
