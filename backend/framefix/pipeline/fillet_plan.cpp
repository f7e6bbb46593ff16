#include "framefix/pipeline/fillet_plan.h"

#include <algorithm>
#include <sstream>

namespace framefix {
namespace {

constexpr double kConcaveFromDeg = 225;  // the hex valence-3 class starts here (round(theta / 90) = 3)
constexpr int kPointsPerCurve = 24;      // curve points measured against each edge
constexpr int kRimSamples = 9;           // points of a candidate rim measured against the concave edge
constexpr double kStripTolerance = 0.1;  // a strip's width varies by less than this share along it

bool concave(const EdgeFeature& e) {
    return e.valence == 3 || (e.valence_varies && e.angle_max_deg >= kConcaveFromDeg && e.valence != 2);
}

double distance_to_curve(const BrepModel& model, int edge, const SingularCurve& c) {
    const int n = int(c.points.rows());
    const int step = std::max(1, n / kPointsPerCurve);
    double d = 1e300;
    for (int i = 0; i < n; i += step) d = std::min(d, distance_to_edge(model, edge, c.points.row(i).transpose()));
    return std::min(d, distance_to_edge(model, edge, c.points.row(n - 1).transpose()));
}

bool shares(const std::vector<int>& a, const std::vector<int>& b) {
    return std::any_of(a.begin(), a.end(), [&](int x) { return std::find(b.begin(), b.end(), x) != b.end(); });
}

// Edge `rim` stays at one distance from `edge`, as the far side of a strip face does.
bool parallel(const BrepModel& model, int edge, int rim) {
    const Points p = edge_points(model, rim, kRimSamples);
    double lo = 1e300, hi = 0;
    for (int i = 0; i < p.rows(); ++i) {
        const double d = distance_to_edge(model, edge, p.row(i).transpose());
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    return lo > 0 && hi - lo <= kStripTolerance * hi;
}

}  // namespace

std::vector<int> rims_of(const BrepModel& model, const FeatureSet& features, int edge) {
    const EdgeFeature& c = features.edges[size_t(edge - 1)];
    std::vector<int> rims;
    for (const EdgeFeature& e : features.edges)
        if (e.valence == 1 && !e.valence_varies && shares(e.faces, c.faces) && !shares(e.vertices, c.vertices) &&
            parallel(model, edge, e.edge))
            rims.push_back(e.edge);
    return rims;
}

FilletPlan plan_fillets(const BrepModel& model, const FeatureSet& features, const SingularityGraph& graph, double h,
                        const FilletPlanOptions& o) {
    FilletPlan plan;
    std::vector<int> chosen;
    for (const SingularCurve& c : graph.curves) {
        if (c.kind != CurveKind::ThreeFive || c.points.rows() == 0) continue;
        bool explained = false;
        for (const EdgeFeature& e : features.edges)
            if (concave(e) && distance_to_curve(model, e.edge, c) <= o.reach * h) {
                chosen.push_back(e.edge);
                explained = true;
            }
        if (!explained)
            plan.notes.push_back("3-5 curve " + std::to_string(c.id) + " has no concave feature curve within " +
                                 std::to_string(int(o.reach)) + " h: a fillet cannot remove it");
    }
    if (o.rims)
        for (size_t i = 0, n = chosen.size(); i < n; ++i)
            for (int rim : rims_of(model, features, chosen[i])) chosen.push_back(rim);
    std::sort(chosen.begin(), chosen.end());
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    for (int edge : chosen) {
        const EdgeFeature& e = features.edges[size_t(edge - 1)];
        const double limit = o.room_share * fillet_room(model, edge);
        double r = o.radius * h;
        if (limit < r) {
            std::ostringstream m;
            m << "Edge" << edge << ": radius " << limit << ", " << o.room_share << " of the room next to the edge ("
              << limit / o.room_share << "), below " << o.radius << " h = " << r;
            plan.notes.push_back(m.str());
            r = limit;
        }
        plan.requests.push_back({edge, r, (e.angle_min_deg + e.angle_max_deg) / 2});
    }
    return plan;
}

}  // namespace framefix
