// Singular-node extrusion (paper section 4.2): from each end of each 3-5 curve a streamline along
// the curve's stable direction, made a singular curve by the constraints. See extrusion.h.
#include <algorithm>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/corrections/extrusion.h"
#include "framefix/corrections/extrusion_trace.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {
namespace {

constexpr int kEndFaces = 3;             // faces averaged for a curve's stable direction at its end
constexpr double kSameDirection = 0.9;   // cosine: two starts from one node this close are one
constexpr double kMatchRadius = 1e-6;    // inserted point found at a mesh vertex, in h

// The holonomy axis w at end e of curve c: the mean over its last kEndFaces faces, sign-aligned.
Eigen::Vector3d end_axis(const SingularityGraph& g, const SingularCurve& c, int e) {
    const int n = int(c.faces.size());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), first = Eigen::Vector3d::Zero();
    for (int i = 0; i < std::min(kEndFaces, n); ++i) {
        const Eigen::Vector3d w = g.face_axis.row(c.faces[size_t(e == 0 ? i : n - 1 - i)]).transpose();
        if (first.norm() == 0) first = w;
        sum += w.dot(first) < 0 ? Eigen::Vector3d(-w) : w;
    }
    return sum.norm() > 0 ? Eigen::Vector3d(sum.normalized()) : Eigen::Vector3d(c.stable_direction);
}

struct Start {
    int node;
    Eigen::Vector3d point, direction;
};

// A boundary node goes into the solid: the sign whose point one h away is inside and farther from
// the boundary. An interior node goes both ways.
std::vector<Eigen::Vector3d> start_directions(const SingularNode& node, const Eigen::Vector3d& w, const TetLocator& locator,
                                              const BoundaryDistance& boundary, double h) {
    if (!node.boundary) return {w, -w};
    for (double f : {1.0, 0.5, 0.25})
        for (const Eigen::Vector3d& d : {w, Eigen::Vector3d(-w)}) {
            const Eigen::Vector3d p = node.position + f * h * d;
            if (locator.locate(p).tet >= 0 && !boundary.within(p, 0.5 * f * h)) return {d};
        }
    return {};
}

std::vector<Start> starts(const SingularityGraph& g, const TetLocator& locator, const BoundaryDistance& boundary,
                          double h, std::vector<ExtrusionFailure>& failures) {
    std::vector<Start> out;
    for (const SingularCurve& c : g.curves) {
        if (c.kind != CurveKind::ThreeFive) continue;
        for (int e = 0; e < 2; ++e) {
            if (c.ends[e] < 0) continue;
            const SingularNode& node = g.nodes[size_t(c.ends[e])];
            const std::vector<Eigen::Vector3d> dirs = start_directions(node, end_axis(g, c, e), locator, boundary, h);
            if (dirs.empty())
                failures.push_back({"node " + std::to_string(node.id), "its stable direction does not point into the solid"});
            for (const Eigen::Vector3d& d : dirs) {
                const bool seen = std::any_of(out.begin(), out.end(), [&](const Start& s) {
                    return s.node == node.id && s.direction.dot(d) > kSameDirection;
                });
                // A seed on the boundary is moved in a little so that it is located.
                if (!seen) out.push_back({node.id, node.position + (node.boundary ? 1e-3 * h : 0.0) * d, d});
            }
        }
    }
    return out;
}

}  // namespace

ExtrusionPlan plan_node_extrusion(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                                  const SingularityGraph& graph, const ExtrusionOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    ExtrusionPlan plan;
    plan.singular = true;
    const double h = graph.h_mean;
    const TetLocator locator(mesh, topo);
    const BoundaryDistance boundary(mesh);
    const TraceOptions to = detail::trace_options(graph, o);
    detail::Candidates cand;
    for (const Start& s : starts(graph, locator, boundary, h, plan.failures)) {
        const std::string name = "node " + std::to_string(s.node);
        for (ExtrusionStreamline& l : detail::trace(mesh, field, locator, {s.point}, {s.direction}, to, name)) {
            if (!l.used) plan.failures.push_back({name, "the streamline " + l.failure + "; it is not used"});
            for (Eigen::Index j = 1; l.used && j < l.line.points.rows(); ++j)
                cand.points.push_back(l.line.points.row(j).transpose()), cand.axes.push_back(detail::along(l.line.points, j));
            plan.streamlines.push_back(std::move(l));
        }
    }
    cand.select(mesh, h, o, plan);
    plan.seconds = detail::since(t0);
    return plan;
}

int add_internal_constraints(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& cons) {
    if (plan.points.rows() == 0) return 0;
    const double r = kMatchRadius * std::max(mesh.size, 1e-12);
    const PointGrid grid(mesh.points, std::max(mesh.size, 1e-12));
    int n = 0;
    for (Eigen::Index i = 0; i < plan.points.rows(); ++i) {
        const int v = grid.nearest(plan.points.row(i).transpose(), r);
        if (v < 0 || cons.kind[size_t(v)] != ConstraintKind::Free) continue;
        const Eigen::Vector3d axis = plan.axes.row(i).transpose();
        if (plan.singular) {
            set_singular(cons, v, axis);
        } else {
            cons.kind[size_t(v)] = ConstraintKind::NormalAligned;
            cons.normal.row(v) = axis.transpose();
        }
        ++n;
    }
    return n;
}

}  // namespace framefix
