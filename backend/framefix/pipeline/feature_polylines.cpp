#include <algorithm>
#include <map>
#include <set>

#include "framefix/pipeline/report.h"

namespace framefix {

std::vector<FeaturePolyline> feature_polylines(const TetMesh& mesh) {
    std::map<int, std::vector<std::pair<int, int>>> by_tag;
    for (int s = 0; s < mesh.feature_edges.rows(); ++s)
        by_tag[mesh.edge_tags(s)].push_back({mesh.feature_edges(s, 0), mesh.feature_edges(s, 1)});
    std::vector<FeaturePolyline> out;
    for (auto& [tag, segs] : by_tag) {
        // Walk the segment chain from an end vertex (degree 1) or anywhere on a closed curve.
        std::map<int, std::vector<int>> adj;
        for (auto [a, b] : segs) {
            adj[a].push_back(b);
            adj[b].push_back(a);
        }
        int start = adj.begin()->first;
        for (auto& [v, nb] : adj)
            if (nb.size() == 1) {
                start = v;
                break;
            }
        FeaturePolyline pl;
        pl.edge = tag;
        std::set<std::pair<int, int>> used;
        for (int cur = start;;) {
            pl.vertices.push_back(cur);
            int next = -1;
            for (int nb : adj[cur])
                if (!used.count({std::min(cur, nb), std::max(cur, nb)})) {
                    next = nb;
                    break;
                }
            if (next < 0) break;
            used.insert({std::min(cur, next), std::max(cur, next)});
            cur = next;
        }
        out.push_back(std::move(pl));
    }
    return out;
}

}  // namespace framefix
