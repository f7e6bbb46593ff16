#include "framefix/pipeline/fillet_map.h"

namespace framefix {
namespace {

constexpr double kNodeReach = 1.5;  // radii: a node this close to the edge lay on its fillet (or within h of it)
constexpr double kPointReach = 1;   // radii: the fillet's material ends at r from the edge (right angle)

// The filleted edge nearest to p within reach x its radius, or -1; its closest point in `q`.
int onto_edge(const BrepModel& original, const std::vector<FilletOutcome>& fillets, const Eigen::Vector3d& p,
              double reach, Eigen::Vector3d* q) {
    int best = -1;
    double best_d = 0;
    for (size_t i = 0; i < fillets.size(); ++i) {
        if (!fillets[i].done) continue;
        const double d = distance_to_edge(original, fillets[i].edge, p);
        if (d <= reach * fillets[i].radius && (best < 0 || d < best_d)) best = int(i), best_d = d;
    }
    if (best >= 0) *q = closest_point_on_edge(original, fillets[size_t(best)].edge, p);
    return best;
}

}  // namespace

MappedGraph map_back(const BrepModel& original, const std::vector<FilletOutcome>& fillets,
                     const SingularityGraph& filleted) {
    MappedGraph m;
    m.graph = filleted;
    for (SingularCurve& c : m.graph.curves) {
        std::vector<int>& edge = m.point_edge.emplace_back(size_t(c.points.rows()), 0);
        for (int i = 0; i < c.points.rows(); ++i) {
            Eigen::Vector3d q;
            const int f = onto_edge(original, fillets, c.points.row(i).transpose(), kPointReach, &q);
            if (f < 0) continue;
            c.points.row(i) = q.transpose();
            edge[size_t(i)] = fillets[size_t(f)].edge;
            ++m.moved_points;
        }
    }
    SingularitySummary& s = m.graph.summary;
    for (SingularNode& n : m.graph.nodes) {
        Eigen::Vector3d q;
        if (onto_edge(original, fillets, n.position, kNodeReach, &q) < 0) continue;
        n.position = q;
        n.boundary = true;  // on the concave edge: a boundary node on a feature curve
        s.invalid_nodes -= !n.valid;
        n.valid = true;
        ++m.moved_nodes;
    }
    s.meshable = s.curves_3_5 == 0 && s.invalid_nodes == 0;
    return m;
}

std::vector<EdgeRun> valence5_runs(const MappedGraph& mapped) {
    std::vector<EdgeRun> runs;
    for (size_t c = 0; c < mapped.graph.curves.size(); ++c) {
        const SingularCurve& curve = mapped.graph.curves[c];
        if (curve.kind != CurveKind::Valence5) continue;
        const std::vector<int>& edge = mapped.point_edge[c];
        for (size_t i = 0; i < edge.size();) {
            size_t j = i;
            while (j < edge.size() && edge[j] == edge[i]) ++j;
            if (edge[i] > 0 && j - i >= 2) runs.push_back({edge[i], curve.points.middleRows(Eigen::Index(i), Eigen::Index(j - i))});
            i = j;
        }
    }
    return runs;
}

}  // namespace framefix
