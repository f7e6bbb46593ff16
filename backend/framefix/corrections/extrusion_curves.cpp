// Feature-curve extrusion (paper section 4.1): the sheets that continue the feature curves next
// to the 3-5 curves into the solid. See extrusion.h.
#include "framefix/corrections/extrusion.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "framefix/corrections/extrusion_trace.h"
#include "framefix/streamlines/feature_seeds.h"

namespace framefix {
namespace {

using detail::Candidates;
using detail::along;

constexpr double kConcaveFromDeg = 225; // valence-3 class starts here (round(theta / 90 deg) = 3)
constexpr double kOffSheet = 0.5;       // |cos| between a gap and the sheet normal: the gap leaves the sheet
constexpr double kSameNormal = 0.87;    // |cos| of 30 deg: sheet normals further apart are another sheet

bool extrudable(const EdgeFeature& e) {
    return e.valence == 2 || e.valence == 3 || e.valence == 4 || (e.valence_varies && e.angle_max_deg >= kConcaveFromDeg);
}

// Feature curves (valence 2..4) with a vertex within `reach` of a 3-5 curve; 3-5 curves with none
// are failures.
std::vector<int> edges_near_three_five(const TetMesh& mesh, const FeatureSet& features, const SingularityGraph& g,
                                       double reach, std::vector<ExtrusionFailure>& failures) {
    std::map<int, std::vector<int>> verts;  // B-rep edge -> mesh vertices
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e)
        if (extrudable(features.edges.at(size_t(mesh.edge_tags[e] - 1))))
            for (int k = 0; k < 2; ++k) verts[mesh.edge_tags[e]].push_back(mesh.feature_edges(e, k));
    std::vector<int> out;
    for (const SingularCurve& c : g.curves) {
        if (c.kind != CurveKind::ThreeFive) continue;
        bool found = false;
        for (const auto& [edge, vs] : verts) {
            bool near = false;
            for (Eigen::Index i = 0; i < c.points.rows() && !near; ++i)
                for (int v : vs) near |= (mesh.points.row(v) - c.points.row(i)).norm() <= reach;
            if (near) out.push_back(edge), found = true;
        }
        if (!found)
            failures.push_back({"3-5 curve " + std::to_string(c.id), "no concave or imprinted feature curve within " +
                                    std::to_string(int(reach / g.h_mean + 0.5)) + " h: nothing to extrude"});
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// Whether streamline b leaves the sheet of streamline a: a point of a whose nearest point of b
// is further than `limit` and off a's sheet plane (normal t x v), or whose sheet normals differ.
// Streamlines that drift apart within one plane (the notch's floor, sheared at a diagonal) do
// not split the sheet: the paper's "parts that stay inside a future valid sheet".
bool leaves_sheet(const Points& a, const Eigen::Vector3d& ta, const Points& b, const Eigen::Vector3d& tb, double limit) {
    for (Eigen::Index i = 1; i < a.rows(); ++i) {
        Eigen::Index best = 0;
        for (Eigen::Index j = 1; j < b.rows(); ++j)
            if ((a.row(i) - b.row(j)).squaredNorm() < (a.row(i) - b.row(best)).squaredNorm()) best = j;
        const Eigen::Vector3d sep = (b.row(best) - a.row(i)).transpose();
        if (sep.norm() <= limit) continue;
        const Eigen::Vector3d na = ta.cross(along(a, i)).normalized(), nb = tb.cross(along(b, best)).normalized();
        if (std::abs(sep.normalized().dot(na)) > kOffSheet || std::abs(na.dot(nb)) < kSameNormal) return true;
    }
    return false;
}

// Streamlines of one sheet in seed order: the first pair of neighbours that split it, or -1.
int split_at(const std::vector<ExtrusionStreamline>& lines, const std::vector<Eigen::Vector3d>& seeds,
             const std::vector<Eigen::Vector3d>& tangents, double h, const ExtrusionOptions& o) {
    for (size_t i = 0; i + 1 < lines.size(); ++i) {
        if (!lines[i].used || !lines[i + 1].used) continue;
        const double limit = std::max(o.split_gap_h * h, o.split_ratio * (seeds[i + 1] - seeds[i]).norm());
        const Points &a = lines[i].line.points, &b = lines[i + 1].line.points;
        if (leaves_sheet(a, tangents[i], b, tangents[i + 1], limit) || leaves_sheet(b, tangents[i + 1], a, tangents[i], limit))
            return int(i);
    }
    return -1;
}

// "12 of 40 streamlines reached a singular curve; 2 of 40 did not reach the boundary".
std::string failure_counts(const std::vector<ExtrusionStreamline>& lines) {
    std::map<std::string, int> n;
    for (const auto& l : lines)
        if (!l.used) n[l.failure] += 1;
    std::ostringstream s;
    for (const auto& [text, count] : n) s << (s.tellp() ? "; " : "") << count << " of " << lines.size() << " streamlines " << text;
    return s.str();
}

// One sheet of a feature curve: trace, reject a split sheet, add the tangency points.
void extrude_sheet(const TetMesh& mesh, const FrameField& field, const TetLocator& locator, const FeatureSeeds& curve,
                   size_t k, const TraceOptions& to, double h, const ExtrusionOptions& o, ExtrusionPlan& plan,
                   Candidates& cand) {
    std::vector<Eigen::Vector3d> seeds, dirs, tangents;
    for (size_t i = 1; i + 1 < curve.seeds.size(); ++i)  // the two ends are corners: no sheet direction there
        if (curve.seeds[i].directions.size() > k)
            seeds.push_back(curve.seeds[i].point), dirs.push_back(curve.seeds[i].directions[k]),
                tangents.push_back(curve.seeds[i].tangent);
    if (seeds.empty()) return;
    const std::string name = "Edge" + std::to_string(curve.edge) + " sheet " + std::to_string(k + 1);
    std::vector<ExtrusionStreamline> lines = detail::trace(mesh, field, locator, seeds, dirs, to, name);
    const int split = split_at(lines, seeds, tangents, h, o);
    if (split >= 0) {
        for (auto& l : lines) l.used = false, l.failure = "belongs to a split sheet";
        plan.failures.push_back({name, "neighbouring streamlines " + std::to_string(split) + " and " + std::to_string(split + 1) +
                                           " drift apart out of the sheet: another singularity splits it, so it is not used"});
    } else if (std::any_of(lines.begin(), lines.end(), [](const auto& l) { return !l.used; })) {
        plan.failures.push_back({name, failure_counts(lines) + "; those are not used"});
    }
    for (size_t i = 0; i < lines.size(); ++i) {
        if (!lines[i].used) continue;
        const Points& p = lines[i].line.points;
        for (Eigen::Index j = 1; j < p.rows(); ++j) {
            const Eigen::Vector3d n = tangents[i].cross(along(p, j));
            cand.points.push_back(p.row(j).transpose());
            cand.axes.push_back(n.norm() > 1e-6 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
        }
    }
    for (auto& l : lines) plan.streamlines.push_back(std::move(l));
}

}  // namespace

ExtrusionPlan plan_curve_extrusion(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                   const FrameField& field, const SingularityGraph& graph, const ExtrusionOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    ExtrusionPlan plan;
    const double h = graph.h_mean;
    plan.edges = edges_near_three_five(mesh, features, graph, o.reach_h * h, plan.failures);
    if (plan.edges.empty()) return plan.seconds = detail::since(t0), plan;
    const TetLocator locator(mesh, topo);
    const TraceOptions to = detail::trace_options(graph, o);
    Candidates cand;
    for (const FeatureSeeds& curve : feature_seeds(mesh, features, field, plan.edges))
        for (size_t k = 0; k + 1 < size_t(curve.valence); ++k) extrude_sheet(mesh, field, locator, curve, k, to, h, o, plan, cand);
    cand.select(mesh, h, o, plan);
    plan.seconds = detail::since(t0);
    return plan;
}

}  // namespace framefix
