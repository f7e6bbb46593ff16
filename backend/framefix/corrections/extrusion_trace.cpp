#include "framefix/corrections/extrusion_trace.h"

#include <algorithm>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix::detail {
namespace {

const char* why(StopReason r) {
    switch (r) {
        case StopReason::LeftSolid: return "";
        case StopReason::ReachedSingularity: return "reached a singular curve";
        case StopReason::SharpTurn: return "turned sharply (an unlisted singularity) before the boundary";
        case StopReason::LimitCycle: return "longer than 3 x the part's diagonal: a spiral or limit cycle";
        case StopReason::MaxSteps: return "did not reach the boundary";
        case StopReason::StartOutside: return "its seed is outside the mesh";
    }
    return "";
}

// Points of the singular curves a streamline must not run into: all but the 3-5 curves (which
// the correction removes) and the short or mixed ones.
Points stop_points(const SingularityGraph& g) {
    std::vector<Eigen::Vector3d> pts;
    for (const SingularCurve& c : g.curves)
        if (c.kind != CurveKind::ThreeFive && c.kind != CurveKind::Other && c.faces.size() >= 3)
            for (Eigen::Index i = 0; i < c.points.rows(); ++i) pts.push_back(c.points.row(i).transpose());
    Points out(Eigen::Index(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) out.row(Eigen::Index(i)) = pts[i].transpose();
    return out;
}

}  // namespace

std::vector<ExtrusionStreamline> trace(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                       const std::vector<Eigen::Vector3d>& seeds, const std::vector<Eigen::Vector3d>& dirs,
                                       const TraceOptions& to, const std::string& source) {
    Points P(Eigen::Index(seeds.size()), 3), D(Eigen::Index(seeds.size()), 3);
    for (size_t i = 0; i < seeds.size(); ++i) P.row(Eigen::Index(i)) = seeds[i].transpose(), D.row(Eigen::Index(i)) = dirs[i].transpose();
    std::vector<ExtrusionStreamline> out;
    for (Streamline& s : trace_streamlines(mesh, field, locator, P, D, to)) {
        ExtrusionStreamline e{source, std::move(s), false, ""};
        e.used = e.line.reason == StopReason::LeftSolid;
        e.failure = why(e.line.reason);
        out.push_back(std::move(e));
    }
    return out;
}

Eigen::Vector3d along(const Points& p, Eigen::Index k) {
    const Eigen::Index a = std::max<Eigen::Index>(k - 1, 0), b = std::min<Eigen::Index>(k + 1, p.rows() - 1);
    const Eigen::Vector3d d = (p.row(b) - p.row(a)).transpose();
    return d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::Zero();
}

void Candidates::select(const TetMesh& mesh, double h, const ExtrusionOptions& o, ExtrusionPlan& plan) const {
    const BoundaryDistance boundary(mesh);
    Points all(Eigen::Index(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) all.row(Eigen::Index(i)) = points[i].transpose();
    const PointGrid grid(all, h);  // cell h: a 0.3 h grid over the whole part would be too big
    std::vector<char> kept(points.size(), 0);
    std::vector<int> near;
    std::vector<int> chosen;
    for (size_t i = 0; i < points.size(); ++i) {
        if (axes[i].norm() == 0 || boundary.within(points[i], o.boundary_gap_h * h)) continue;
        grid.within(points[i], o.point_gap_h * h, near);
        if (std::any_of(near.begin(), near.end(), [&](int j) { return kept[size_t(j)]; })) continue;
        kept[i] = 1, chosen.push_back(int(i));
    }
    plan.points.resize(Eigen::Index(chosen.size()), 3);
    plan.axes.resize(Eigen::Index(chosen.size()), 3);
    for (size_t k = 0; k < chosen.size(); ++k)
        plan.points.row(Eigen::Index(k)) = points[size_t(chosen[k])].transpose(),
        plan.axes.row(Eigen::Index(k)) = axes[size_t(chosen[k])].transpose();
}

TraceOptions trace_options(const SingularityGraph& graph, const ExtrusionOptions& o) {
    TraceOptions to;
    to.singular_points = stop_points(graph);
    to.append_singular_point = false;
    to.threads = o.threads;
    return to;
}

}  // namespace framefix::detail
