// snap_three_five_curves: plan -> paths -> path frames -> split curves -> freed vertices.
#include "framefix/corrections/snapping.h"

#include <chrono>
#include <map>
#include <set>
#include <string>

#include "framefix/core/error.h"
#include "framefix/corrections/boundary_graph.h"
#include "framefix/corrections/free_boundary.h"
#include "framefix/corrections/path_frames.h"
#include "framefix/corrections/snap_plan.h"
#include "framefix/corrections/split_curves.h"

namespace framefix {

namespace {

void check_sizes(const TetMesh& mesh, const Constraints& c, const FrameField& field) {
    const int nv = mesh.num_vertices();
    auto fail = [&](const std::string& what, long long n) {
        throw Error("snap", what + " has " + std::to_string(n) + " rows but the mesh has " + std::to_string(nv) +
                                " vertices; pass the mesh, constraints and field of one analysis");
    };
    if (int(c.kind.size()) != nv) fail("constraints.kind", (long long)c.kind.size());
    if (c.normal.rows() != nv) fail("constraints.normal", c.normal.rows());
    if (c.fixed.rows() != nv) fail("constraints.fixed", c.fixed.rows());
    if (field.coefficients.rows() != nv) fail("field.coefficients", field.coefficients.rows());
}

void set_fixed(Constraints& c, int v, const SH9& q) {
    c.kind[v] = ConstraintKind::Fixed;
    c.fixed.row(v) = q.transpose();
}

std::vector<SnappedPath> build_paths(const TetMesh& mesh, const BoundaryGraph& boundary, const SnapPlan& plan,
                                     const SnapOptions& options) {
    std::vector<SnappedPath> paths;
    for (size_t i = 0; i < plan.curves.size(); ++i) {
        const BoundaryPath bp = shortest_boundary_path(boundary, plan.targets[i][0], plan.targets[i][1]);
        if (bp.vertices.size() < 2) continue;  // both ends on one vertex: nothing to draw
        SnappedPath p;
        p.vertices = bp.vertices;
        p.source_curve = plan.curves[i];
        p.forced = plan.forced[i];
        p.crosses_features = bp.crosses_features;
        p.points.resize(int(p.vertices.size()), 3);
        p.frames.resize(int(p.vertices.size()), 9);
        const std::vector<Eigen::Matrix3d> frames = path_frames(
            mesh.points, boundary, p.vertices, options.path_frame_angle_deg, options.tangent_half_width);
        for (int k = 0; k < int(p.vertices.size()); ++k) {
            p.points.row(k) = mesh.points.row(p.vertices[k]);
            p.frames.row(k) = frame_from_rotation(frames[k]).transpose();
        }
        paths.push_back(std::move(p));
    }
    return paths;
}

// Path frames become Dirichlet conditions; returns the path frames of snapped feature vertices
// (the "S" anchors of the split curves), which are applied afterwards.
std::map<int, SH9> apply_paths(const BoundaryGraph& boundary, const std::vector<SnappedPath>& paths, SnapResult& r) {
    std::map<int, int> end_count;
    for (const SnappedPath& p : paths) ++end_count[p.vertices.front()], ++end_count[p.vertices.back()];
    std::map<int, SH9> anchors;
    for (const SnappedPath& p : paths) {
        const int n = int(p.vertices.size());
        for (int k = 0; k < n; ++k) {
            const int v = p.vertices[k];
            const SH9 q = p.frames.row(k).transpose();
            if (boundary.is_feature[v] && (k == 0 || k == n - 1)) {
                anchors.emplace(v, q);  // first path wins; all frames there are tangent to their path
                continue;
            }
            set_fixed(r.constraints, v, q);
            r.vertex_role[v] = SnapRole::Path;
        }
    }
    // Where several paths meet on a smooth face (a snapped junction) no single 45 deg frame fits
    // them all: leave the vertex free and let the solver choose.
    for (const auto& [v, count] : end_count) {
        if (count < 2 || boundary.is_feature[v]) continue;
        r.constraints.kind[v] = ConstraintKind::Free;
        r.vertex_role[v] = SnapRole::SharedEnd;
    }
    return anchors;
}

// Feature vertices onto which a whole snapped curve collapsed (both targets equal, no path).
std::set<int> collapsed_feature_points(const SnapPlan& plan, const BoundaryGraph& boundary) {
    std::set<int> points;
    for (const auto& t : plan.targets)
        if (t[0] == t[1] && boundary.is_feature[t[0]]) points.insert(t[0]);
    return points;
}

void apply_anchors(const TetMesh& mesh, const FeatureSet& features, const Constraints& original,
                   const std::map<int, SH9>& anchors, const std::set<int>& collapsed, const SnapOptions& options,
                   SnapResult& r) {
    // Without interpolation (the default) only S itself takes the path frame: that gives
    // the same singularities with a more local change. A curve collapsed onto a feature vertex
    // leaves no path frame to impose, so its feature curve is always re-interpolated between its
    // ends: that is the only change that removes it.
    const std::map<int, SH9> interpolated_anchors = options.interpolate_split_curves ? anchors : std::map<int, SH9>{};
    if (!interpolated_anchors.empty() || !collapsed.empty()) {
        const auto frames =
            interpolate_split_curves(mesh.points, feature_chains(mesh, features), original, interpolated_anchors, collapsed);
        for (const auto& [v, q] : frames) {
            set_fixed(r.constraints, v, q);
            r.vertex_role[v] = anchors.count(v) ? SnapRole::Path : SnapRole::SplitCurve;
        }
    }
    for (const auto& [v, q] : anchors) {
        if (options.interpolate_split_curves && r.vertex_role[v] == SnapRole::Path) continue;
        set_fixed(r.constraints, v, q);
        r.vertex_role[v] = SnapRole::Path;
    }
}

void free_near_paths(const TetMesh& mesh, const BoundaryGraph& boundary, const Constraints& original,
                     const SnapOptions& options, SnapResult& r) {
    std::vector<int> candidates;  // still tangency-constrained: Dirichlet vertices are never freed
    for (int v : boundary.boundary_vertices)
        if (r.constraints.kind[v] == ConstraintKind::NormalAligned) candidates.push_back(v);
    std::vector<std::vector<int>> polylines;
    for (const SnappedPath& p : r.paths) polylines.push_back(p.vertices);
    for (int v : vertices_near_paths(mesh.points, candidates, polylines, options.free_radius_hb * boundary.hb, options.threads)) {
        r.constraints.kind[v] = ConstraintKind::Free;
        r.vertex_role[v] = SnapRole::Freed;
    }
    r.freed_vertices = 0;
    for (int v : boundary.boundary_vertices)
        r.freed_vertices += original.kind[v] == ConstraintKind::NormalAligned && r.constraints.kind[v] == ConstraintKind::Free;
}

}  // namespace

SnapResult snap_three_five_curves(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                  const Constraints& constraints, const FrameField& field,
                                  const SingularityGraph& graph, const SnapOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    check_sizes(mesh, constraints, field);
    if (!(options.free_radius_hb >= 0 && options.collapse_radius_hb >= 0 && options.dead_end_radius_h >= 0))
        throw Error("snap", "radii must be >= 0 (free " + std::to_string(options.free_radius_hb) + " hb, collapse " +
                                std::to_string(options.collapse_radius_hb) + " hb, dead end " +
                                std::to_string(options.dead_end_radius_h) + " h)");
    SnapResult r;
    r.constraints = constraints;
    r.vertex_role.assign(mesh.num_vertices(), SnapRole::Untouched);

    const BoundaryGraph boundary = build_boundary_graph(mesh, topo, features, constraints);
    r.hb = boundary.hb;
    const CurveEnds ends = classify_curve_ends(graph, options.dead_end_radius_h * boundary.h_mean);
    const SnapPlan plan = plan_snapping(graph, ends, boundary, mesh.points, options);
    r.three_five_curves = plan.three_five_curves;
    r.invalid_nodes_snapped = plan.invalid_nodes;
    r.snapped_curve_ids = plan.curves;
    r.snapped_curves = int(plan.curves.size());
    r.collapsed_ends = plan.collapsed_ends;
    r.node_target.resize(graph.nodes.size());
    for (size_t n = 0; n < graph.nodes.size(); ++n) r.node_target[n] = plan.node_target[ends.node_rep[n]];

    if (!plan.curves.empty()) {
        r.paths = build_paths(mesh, boundary, plan, options);
        const std::map<int, SH9> anchors = apply_paths(boundary, r.paths, r);
        apply_anchors(mesh, features, constraints, anchors, collapsed_feature_points(plan, boundary), options, r);
        free_near_paths(mesh, boundary, constraints, options, r);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace framefix
