#include "framefix/pipeline/fillet_plan.h"

#include <algorithm>
#include <sstream>

namespace framefix {
namespace {

constexpr double kConcaveFromDeg = 225;  // the hex valence-3 class starts here (round(theta / 90) = 3)
constexpr int kPointsPerCurve = 24;      // curve points measured against each edge

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

}  // namespace

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
