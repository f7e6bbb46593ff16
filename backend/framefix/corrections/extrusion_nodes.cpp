// Singular-node extrusion (paper section 4.2): from each end of each 3-5 curve a streamline along
// the curve's stable direction, made a singular curve by the constraints. See extrusion.h.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Geometry>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/corrections/extrusion.h"
#include "framefix/corrections/extrusion_trace.h"
#include "framefix/corrections/extrusion_winding.h"
#include "framefix/frame_field/projection.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {
namespace {

constexpr int kEndFaces = 3;             // faces averaged for a curve's stable direction at its end
constexpr double kSameDirection = 0.9;   // cosine: two starts from one node this close are one
constexpr double kAlong = 1.5;           // h: a streamline point this close to a kept curve runs along it
constexpr double kApart = 1.5;           // h: forced ends closer than this on the boundary may merge

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

// Whether most of a streamline lies within kAlong h of the curves the correction keeps: one
// traced from an interior node along a curve that leaves it adds nothing (the half-sphere's
// nodes, traced upwards, run into the sphere along their valence-3 curves).
bool follows_curve(const Points& p, const PointGrid& kept, double h) {
    if (kept.empty()) return false;
    int near = 0;
    for (Eigen::Index j = 0; j < p.rows(); ++j) near += kept.nearest(p.row(j).transpose(), kAlong * h) >= 0;
    return 2 * near >= p.rows();
}

struct Start {
    int node;
    Eigen::Vector3d point, direction;
    int valence;  // of the 3-5 curve at this end: the streamline continues it
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
                if (!seen) out.push_back({node.id, node.position + (node.boundary ? 1e-3 * h : 0.0) * d, d, c.end_valence[e]});
            }
        }
    }
    return out;
}

// The initial field's cross about d at x, as exp(4 i psi) with psi measured from e1, weighted by
// how well d is a frame axis there; zero outside the mesh.
std::complex<double> initial_cross(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                   const Eigen::Vector3d& x, const Eigen::Vector3d& d, const Eigen::Vector3d& e1) {
    const TetLocation at = locator.locate(x);
    if (at.tet < 0) return 0;
    const Eigen::Vector4d w = at.bary.cwiseMax(0.0) / std::max(at.bary.cwiseMax(0.0).sum(), 1e-300);
    SH9 q = SH9::Zero();
    for (int lv = 0; lv < 4; ++lv) q += w[lv] * field.coefficients.row(mesh.tets(at.tet, lv)).transpose();
    const ProjectedFrame f = project_frame(q);
    const Eigen::Vector3d along_d = closest_direction(d, f.rotation);
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
        if (std::abs(f.rotation.col(k).dot(along_d)) < 0.5) a = f.rotation.col(k);
    return std::abs(along_d.dot(d)) * std::polar(1.0, 4 * std::atan2(a.dot(d.cross(e1)), a.dot(e1)));
}

// The phase of each forced curve, per point: the turn c such that c + Winding::angle matches the
// initial field on rings of 2 h and 3 h about the point (away from every forced curve, where the
// forced field and the initial one should agree), spread along the curve by exponential
// smoothing both ways so that stretches with no good fit take their neighbours' phase.
void fit_phases(const TetMesh& mesh, const FrameField& field, const TetLocator& locator, double h,
                std::vector<ExtrusionStreamline>& lines) {
    constexpr int kRing = 12;
    constexpr double kKeep = 0.8;       // share of the neighbour's sum carried to the next point
    constexpr double kClear = 1.2;      // samples this close (h) to a forced curve are skipped
    const detail::Winding winding(lines, h);
    for (size_t i = 0; i < lines.size(); ++i) {
        ExtrusionStreamline& l = lines[i];
        if (!l.used || (l.valence != 3 && l.valence != 5)) continue;
        const Points& p = l.line.points;
        const size_t m = size_t(p.rows());
        std::vector<std::complex<double>> z(m), fwd(m), bwd(m);
        for (size_t j = 0; j < m; ++j) {
            const Eigen::Vector3d d = detail::along(p, Eigen::Index(j)), e1 = winding.e1(i, Eigen::Index(j)), e2 = d.cross(e1);
            for (double radius : {2.0, 3.0})
                for (int r = 0; r < kRing; ++r) {
                    const double t = 2 * M_PI * r / kRing;
                    const Eigen::Vector3d x = p.row(Eigen::Index(j)).transpose() + radius * h * (std::cos(t) * e1 + std::sin(t) * e2);
                    if (winding.nearest(x, kClear * h) >= 0) continue;
                    z[j] += initial_cross(mesh, field, locator, x, d, e1) * std::polar(1.0, -4 * winding.angle(x, d));
                }
        }
        for (size_t j = 0; j < m; ++j) fwd[j] = z[j] + (j ? kKeep * fwd[j - 1] : std::complex<double>());
        for (size_t j = m; j-- > 0;) bwd[j] = z[j] + (j + 1 < m ? kKeep * bwd[j + 1] : std::complex<double>());
        l.phase.assign(m, 0.0);
        for (size_t j = 0; j < m; ++j) l.phase[j] = std::arg(fwd[j] + bwd[j] - z[j]) / 4;
    }
}

// Rings on the boundary about where each forced curve ends, on the boundary triangles (TetGen
// splits them, no -Y): the surface singularities there get room of their own.
void surface_rings(const ExtrusionPlan& plan, const BoundaryDistance& boundary, double h, double r,
                   std::vector<Eigen::Vector3d>& out) {
    constexpr int kRingPoints = 6;
    for (const ExtrusionStreamline& l : plan.streamlines) {
        if (!l.used || l.line.points.rows() < 2) continue;
        const Eigen::Vector3d end = l.line.points.bottomRows<1>().transpose();
        const Eigen::Vector3d d = detail::along(l.line.points, l.line.points.rows() - 1), e1 = d.unitOrthogonal(), e2 = d.cross(e1);
        for (double radius : {r, 2 * r})
            for (int k = 0; k < kRingPoints; ++k) {
                const double t = 2 * M_PI * k / kRingPoints;
                out.push_back(boundary.closest(end + radius * h * (std::cos(t) * e1 + std::sin(t) * e2), h));
            }
    }
}

// kRingPoints points on a circle of radius r h about each inserted point, normal to its axis,
// kept away from the boundary: the mesh is refined around the forced curves.
Points rings(const ExtrusionPlan& plan, const TetMesh& mesh, double h, double r) {
    constexpr int kRingPoints = 6;
    const BoundaryDistance boundary(mesh);
    std::vector<Eigen::Vector3d> out;
    for (Eigen::Index i = 0; i < plan.points.rows(); ++i) {
        const Eigen::Vector3d d = plan.axes.row(i).transpose(), e1 = d.unitOrthogonal(), e2 = d.cross(e1);
        for (int k = 0; k < kRingPoints; ++k) {
            const double t = 2 * M_PI * (k + 0.5 * (i % 2)) / kRingPoints;
            const Eigen::Vector3d x = plan.points.row(i).transpose() + r * h * (std::cos(t) * e1 + std::sin(t) * e2);
            if (!boundary.within(x, 0.5 * r * h)) out.push_back(x);
        }
    }
    surface_rings(plan, boundary, h, r, out);
    Points p(Eigen::Index(out.size()), 3);
    for (size_t k = 0; k < out.size(); ++k) p.row(Eigen::Index(k)) = out[k].transpose();
    return p;
}

// Forced curves of opposite valence whose boundary ends are closer than kApart h read as one
// node there (the mesh cannot keep them apart): said in the failures, with what helps.
void note_close_ends(ExtrusionPlan& plan, double h) {
    const auto& l = plan.streamlines;
    for (size_t i = 0; i < l.size(); ++i)
        for (size_t j = i + 1; j < l.size(); ++j) {
            if (!l[i].used || !l[j].used || l[i].valence == l[j].valence) continue;
            const double d = (l[i].line.points.bottomRows<1>() - l[j].line.points.bottomRows<1>()).norm();
            if (d >= kApart * h) continue;
            char what[160];
            std::snprintf(what, sizeof what, "the streamlines from %s and %s end %.1f h apart on the boundary; a finer --size "
                          "keeps their curves apart", l[i].source.c_str(), l[j].source.c_str(), d / h);
            plan.failures.push_back({l[i].source, what});
        }
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
    const PointGrid kept(to.singular_points, h);
    for (const Start& s : starts(graph, locator, boundary, h, plan.failures)) {
        const std::string name = "node " + std::to_string(s.node);
        for (ExtrusionStreamline& l : detail::trace(mesh, field, locator, {s.point}, {s.direction}, to, name)) {
            l.valence = s.valence;
            l.reference = s.direction.unitOrthogonal();
            if (l.used && follows_curve(l.line.points, kept, h)) l.used = false, l.failure = "follows an existing singular curve";
            if (!l.used) plan.failures.push_back({name, "the streamline " + l.failure + "; it is not used"});
            for (Eigen::Index j = 1; l.used && j < l.line.points.rows(); ++j)
                cand.points.push_back(l.line.points.row(j).transpose()), cand.axes.push_back(detail::along(l.line.points, j));
            plan.streamlines.push_back(std::move(l));
        }
    }
    note_close_ends(plan, h);
    fit_phases(mesh, field, locator, h, plan.streamlines);
    cand.select(mesh, h, o, plan);
    if (o.ring_radius_h > 0) plan.ring_points = rings(plan, mesh, h, o.ring_radius_h);
    plan.refine_boundary = true;
    plan.seconds = detail::since(t0);
    return plan;
}

}  // namespace framefix
