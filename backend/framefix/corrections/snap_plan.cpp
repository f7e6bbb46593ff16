// Snap targets and the fixed point over curves sharing snapped extremities.
#include "framefix/corrections/snap_plan.h"

#include "framefix/core/error.h"

namespace framefix {

namespace {

struct Planner {
    const SingularityGraph& graph;
    const CurveEnds& ends;
    const BoundaryGraph& boundary;
    const Points& points;
    const SnapOptions& options;
    SnapPlan plan;
    std::vector<char> in_plan;  // #curves

    Planner(const SingularityGraph& g, const CurveEnds& e, const BoundaryGraph& b, const Points& p,
            const SnapOptions& o)
        : graph(g), ends(e), boundary(b), points(p), options(o), in_plan(g.curves.size(), 0) {
        plan.node_target.assign(g.nodes.size(), -1);
    }

    int rep(int node) const { return ends.node_rep[node]; }

    // Boundary ends (and unmerged dead ends) go to the nearest feature-curve vertex, interior
    // nodes to the nearest boundary vertex (docs/algorithms.md#snap-targets).
    int target_of(int node) const {
        const Eigen::Vector3d p = graph.nodes[rep(node)].position;
        const bool interior = ends.node_kind[node] == EndKind::Junction;
        const std::vector<int>& candidates = interior || boundary.feature_vertices.empty()
                                                 ? boundary.boundary_vertices
                                                 : boundary.feature_vertices;
        const int v = nearest_vertex(points, candidates, p);
        if (v < 0) throw Error("snap", "the mesh has no boundary vertex to snap singular node " + std::to_string(node) + " to");
        return v;
    }

    // The literal rule would send a forced curve's boundary end to the nearest feature curve and
    // duplicate the path of the neighbouring 3-5 curve (half-sphere stubs): map it onto the
    // target of the curve's snapped end instead when that is close.
    void apply_collapse_rule(const SingularCurve& c) {
        for (int k = 0; k < 2; ++k) {
            const int e = c.ends[k], o = c.ends[1 - k];
            if (ends.node_kind[e] != EndKind::Boundary || plan.node_target[rep(e)] >= 0) continue;
            const int t = plan.node_target[rep(o)];
            if (t < 0) continue;
            const double d = (points.row(t).transpose() - graph.nodes[rep(e)].position).norm();
            if (d < options.collapse_radius_hb * boundary.hb) {
                plan.node_target[rep(e)] = t;
                ++plan.collapsed_ends;
            }
        }
    }

    void add(int curve, bool forced) {
        const SingularCurve& c = graph.curves[curve];
        if (forced) apply_collapse_rule(c);
        std::array<int, 2> t{};
        for (int k = 0; k < 2; ++k) {
            int& target = plan.node_target[rep(c.ends[k])];
            if (target < 0) target = target_of(c.ends[k]);
            t[k] = target;
        }
        in_plan[curve] = 1;
        plan.curves.push_back(curve);
        plan.forced.push_back(forced);
        plan.targets.push_back(t);
    }

    bool has_snapped_end(const SingularCurve& c) const {
        return plan.node_target[rep(c.ends[0])] >= 0 || plan.node_target[rep(c.ends[1])] >= 0;
    }
};

}  // namespace

SnapPlan plan_snapping(const SingularityGraph& graph, const CurveEnds& ends, const BoundaryGraph& boundary,
                       const Points& points, const SnapOptions& options) {
    FF_ASSERT(ends.excluded.size() == graph.curves.size() && ends.node_rep.size() == graph.nodes.size());
    Planner p(graph, ends, boundary, points, options);
    const int n_curves = int(graph.curves.size());
    for (int i = 0; i < n_curves; ++i) {
        if (ends.excluded[i] || graph.curves[i].kind != CurveKind::ThreeFive) continue;
        ++p.plan.three_five_curves;
        p.add(i, false);
    }
    // An invalid interior node goes to the boundary too, where a node on the boundary is valid:
    // the fixed point then snaps its curves (docs/algorithms.md#snap-plan-and-collapse-rule).
    if (options.snap_invalid_nodes)
        for (int n = 0; n < int(graph.nodes.size()); ++n) {
            const SingularNode& node = graph.nodes[n];
            if (node.valid || node.boundary || ends.node_kind[n] != EndKind::Junction || p.plan.node_target[p.rep(n)] >= 0)
                continue;
            p.plan.node_target[p.rep(n)] = p.target_of(n);
            ++p.plan.invalid_nodes;
        }
    // Each pass snaps every curve touching a snapped node; a node is snapped at most once, so this
    // ends after at most #curves passes.
    for (bool changed = p.plan.three_five_curves + p.plan.invalid_nodes > 0; changed;) {
        changed = false;
        for (int i = 0; i < n_curves; ++i) {
            if (p.in_plan[i] || ends.excluded[i] || !p.has_snapped_end(graph.curves[i])) continue;
            p.add(i, true);
            changed = true;
        }
    }
    return p.plan;
}

}  // namespace framefix
