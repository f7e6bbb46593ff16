// Singular-node extrusion (paper section 4.2): from each end of each 3-5 curve a streamline along
// the curve's stable direction, made a singular curve by the constraints. See extrusion.h.
#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Geometry>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/corrections/extrusion.h"
#include "framefix/corrections/extrusion_trace.h"
#include "framefix/frame_field/projection.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {
namespace {

constexpr int kEndFaces = 3;             // faces averaged for a curve's stable direction at its end
constexpr double kSameDirection = 0.9;   // cosine: two starts from one node this close are one
constexpr double kMatchRadius = 1e-6;    // inserted point found at a mesh vertex, in h
constexpr double kHeadOn = 0.9;          // cosine: a streamline this close to the normal meets the boundary head-on

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

// Unit axes normal to the streamline at each of its points, carried from `reference` by
// projection (parallel transport without twist).
std::vector<Eigen::Vector3d> transported(const Points& p, const Eigen::Vector3d& reference) {
    std::vector<Eigen::Vector3d> e(size_t(p.rows()));
    Eigen::Vector3d cur = reference;
    for (Eigen::Index j = 0; j < p.rows(); ++j) {
        const Eigen::Vector3d d = detail::along(p, j);
        const Eigen::Vector3d q = cur - cur.dot(d) * d;
        cur = q.norm() > 1e-9 ? Eigen::Vector3d(q.normalized()) : cur;
        e[size_t(j)] = cur;
    }
    return e;
}

double winding_sign(int valence) { return valence == 5 ? -1.0 : 1.0; }  // index +1/4 (valence 3) or -1/4

// The frame at x of a singular curve of valence k along the streamline point (p, d, e1): the
// cross about d turned by phase + theta/4 (valence 3) or phase - theta/4 (valence 5).
Eigen::Matrix3d winding_frame(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                              const Eigen::Vector3d& e1_in, int valence, double phase) {
    const Eigen::Vector3d e1 = (e1_in - e1_in.dot(d) * d).normalized(), e2 = d.cross(e1);
    const Eigen::Vector3d r = x - p - (x - p).dot(d) * d;
    const double phi = phase + 0.25 * winding_sign(valence) * std::atan2(r.dot(e2), r.dot(e1));
    const Eigen::Vector3d a1 = std::cos(phi) * e1 + std::sin(phi) * e2;
    Eigen::Matrix3d R;
    R << a1, d.cross(a1), d;
    return R;
}

// 4 x (angle of the initial frame's cross about d at x, from e1) - s theta, as a unit complex
// number weighted by how well d is a frame axis there; zero outside the mesh.
std::complex<double> phase_sample(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                  const Eigen::Vector3d& x, const Eigen::Vector3d& d, const Eigen::Vector3d& e1,
                                  double s_theta) {
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
    const double psi = std::atan2(a.dot(d.cross(e1)), a.dot(e1));
    return std::abs(along_d.dot(d)) * std::polar(1.0, 4 * psi - s_theta);
}

// The winding phase per streamline point: fitted on a ring of radius 1 h in the initial field,
// then spread along the line (exponential smoothing both ways) so that the stretches where the
// field does not wind yet take the phase of those where it does.
std::vector<double> fit_phase(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                              const ExtrusionStreamline& l, double h) {
    constexpr int kRing = 8;
    constexpr double kKeep = 0.8;  // share of the neighbour's sum carried to the next point
    const Points& p = l.line.points;
    const std::vector<Eigen::Vector3d> e1 = transported(p, l.reference);
    const Eigen::Index n = p.rows();
    const size_t m = size_t(n);
    std::vector<std::complex<double>> z(m), fwd(m), bwd(m);
    for (Eigen::Index j = 0; j < n; ++j) {
        const Eigen::Vector3d d = detail::along(p, j), b = d.cross(e1[size_t(j)]);
        for (int r = 0; r < kRing; ++r) {
            const double t = 2 * M_PI * r / kRing;
            const Eigen::Vector3d x = p.row(j).transpose() + h * (std::cos(t) * e1[size_t(j)] + std::sin(t) * b);
            z[size_t(j)] += phase_sample(mesh, field, locator, x, d, e1[size_t(j)], winding_sign(l.valence) * t);
        }
    }
    for (Eigen::Index j = 0; j < n; ++j) fwd[size_t(j)] = z[size_t(j)] + (j ? kKeep * fwd[size_t(j - 1)] : std::complex<double>());
    for (Eigen::Index j = n - 1; j >= 0; --j) bwd[size_t(j)] = z[size_t(j)] + (j + 1 < n ? kKeep * bwd[size_t(j + 1)] : std::complex<double>());
    std::vector<double> phase(m);
    for (size_t j = 0; j < m; ++j) phase[j] = std::arg(fwd[j] + bwd[j] - z[j]) / 4;
    return phase;
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
    Points p(Eigen::Index(out.size()), 3);
    for (size_t k = 0; k < out.size(); ++k) p.row(Eigen::Index(k)) = out[k].transpose();
    return p;
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
            l.valence = s.valence;
            l.reference = s.direction.unitOrthogonal();
            if (l.used) l.phase = fit_phase(mesh, field, locator, l, h);
            if (!l.used) plan.failures.push_back({name, "the streamline " + l.failure + "; it is not used"});
            for (Eigen::Index j = 1; l.used && j < l.line.points.rows(); ++j)
                cand.points.push_back(l.line.points.row(j).transpose()), cand.axes.push_back(detail::along(l.line.points, j));
            plan.streamlines.push_back(std::move(l));
        }
    }
    cand.select(mesh, h, o, plan);
    if (getenv("FF_RING")) plan.ring_points = rings(plan, mesh, h, atof(getenv("FF_RING")));  // TEMP
    plan.seconds = detail::since(t0);
    return plan;
}

namespace {

// Node extrusion: free vertices near a used streamline get its winding frames (or, on its core,
// the singular frame). Returns how many.
int constrain_tubes(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& cons, const ExtrusionOptions& o) {
    struct At { size_t line; Eigen::Index j; };
    std::vector<At> at;
    std::vector<std::vector<Eigen::Vector3d>> e1(plan.streamlines.size());
    std::vector<Eigen::Vector3d> pts;
    for (size_t i = 0; i < plan.streamlines.size(); ++i) {
        const ExtrusionStreamline& l = plan.streamlines[i];
        if (!l.used || (l.valence != 3 && l.valence != 5)) continue;
        e1[i] = transported(l.line.points, l.reference);
        for (Eigen::Index j = 0; j < l.line.points.rows(); ++j) at.push_back({i, j}), pts.push_back(l.line.points.row(j).transpose());
    }
    if (pts.empty()) return 0;
    Points all(Eigen::Index(pts.size()), 3);
    for (size_t k = 0; k < pts.size(); ++k) all.row(Eigen::Index(k)) = pts[k].transpose();
    const double h = std::max(mesh.size, 1e-12);
    const PointGrid grid(all, h);
    int n = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const ConstraintKind kind = cons.kind[size_t(v)];
        if (kind == ConstraintKind::Fixed) continue;
        const Eigen::Vector3d x = mesh.points.row(v).transpose();
        const int k = grid.nearest(x, o.tube_radius_h * h);
        if (k < 0) continue;
        const ExtrusionStreamline& l = plan.streamlines[at[size_t(k)].line];
        const Eigen::Index j = at[size_t(k)].j;
        Eigen::Vector3d d = detail::along(l.line.points, j);
        // Where the streamline meets the boundary head-on, the surface singularity is forced too.
        if (kind == ConstraintKind::NormalAligned) {
            const Eigen::Vector3d n = cons.normal.row(v).transpose();
            if (std::abs(n.dot(d)) < kHeadOn) continue;
            d = n.dot(d) > 0 ? n : Eigen::Vector3d(-n);
        }
        {  // TEMP experiment: skip near the ends
            double skip = getenv("FF_SKIP") ? atof(getenv("FF_SKIP")) : 0;
            double s0 = 0, s1 = 0;
            for (Eigen::Index q = 1; q <= j; ++q) s0 += (l.line.points.row(q) - l.line.points.row(q - 1)).norm();
            s1 = l.line.length - s0;
            if (std::min(s0, s1) < skip * h) continue;
        }
        const Eigen::Vector3d p = pts[size_t(k)];
        const Eigen::Vector3d r = x - p - (x - p).dot(d) * d;
        if (r.norm() < o.core_radius_h * h) {
            set_singular(cons, v, d);
        } else {
            cons.kind[size_t(v)] = ConstraintKind::Fixed;
            cons.fixed.row(v) = frame_from_rotation(winding_frame(x, p, d, e1[at[size_t(k)].line][size_t(j)], l.valence, l.phase[size_t(j)])).transpose();
        }
        ++n;
        if (getenv("FF_DEBUG")) fprintf(stderr, "tube line %zu z %.3f kind %d r %.3f\n", at[size_t(k)].line, x.z(), int(kind), r.norm() / h);
    }
    return n;
}

}  // namespace

int add_internal_constraints(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& cons, const ExtrusionOptions& o) {
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
    return n + (plan.singular ? constrain_tubes(mesh, plan, cons, o) : 0);
}

}  // namespace framefix
