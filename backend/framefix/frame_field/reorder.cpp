#include "framefix/frame_field/reorder.h"

#include <algorithm>
#include <utility>

namespace framefix {
namespace {

int degree(const P1System& s, int v) { return s.row_start[v + 1] - s.row_start[v]; }

// Breadth-first from `start` over vertices whose mark != stamp (marks them); neighbours are
// visited by increasing (degree, index). Appends the visit order to `out`; returns the index in
// `out` where the last level begins.
size_t bfs(const P1System& s, int start, std::vector<int>& mark, int stamp, std::vector<int>& out) {
    const size_t first = out.size();
    out.push_back(start);
    mark[start] = stamp;
    size_t level_begin = first, level_end = out.size(), last_level = first;
    std::vector<std::pair<int, int>> next;
    while (level_begin < level_end) {
        last_level = level_begin;
        for (size_t q = level_begin; q < level_end; ++q) {
            const int v = out[q];
            next.clear();
            for (int k = s.row_start[v]; k < s.row_start[v + 1]; ++k) {
                const int u = s.col[k];
                if (mark[u] == stamp) continue;
                mark[u] = stamp;
                next.emplace_back(degree(s, u), u);
            }
            std::sort(next.begin(), next.end());
            for (const auto& e : next) out.push_back(e.second);
        }
        level_begin = level_end;
        level_end = out.size();
    }
    return last_level;
}

}  // namespace

std::vector<int> rcm_order(const P1System& s) {
    const int nv = s.rows();
    std::vector<int> order, scratch;
    order.reserve(nv);
    std::vector<int> done(nv, 0), mark(nv, 0);
    int stamp = 0;
    for (int seed = 0; seed < nv; ++seed) {
        if (done[seed]) continue;
        // Pseudo-peripheral start: two sweeps, each restarting from the lowest-degree vertex of
        // the previous sweep's last level (George-Liu, shortened).
        int start = seed;
        for (int sweep = 0; sweep < 2; ++sweep) {
            scratch.clear();
            const size_t last = bfs(s, start, mark, ++stamp, scratch);
            for (size_t q = last; q < scratch.size(); ++q)
                if (degree(s, scratch[q]) < degree(s, start) || q == last) start = scratch[q];
        }
        const size_t begin = order.size();
        bfs(s, start, mark, ++stamp, order);
        for (size_t q = begin; q < order.size(); ++q) done[order[q]] = 1;
    }
    std::reverse(order.begin(), order.end());
    return order;
}

P1System permute(const P1System& s, const std::vector<int>& order) {
    const int nv = s.rows();
    std::vector<int> rank(nv);
    for (int r = 0; r < nv; ++r) rank[order[r]] = r;
    P1System p;
    p.mean_edge = s.mean_edge;
    p.diameter = s.diameter;
    p.row_start.assign(nv + 1, 0);
    for (int r = 0; r < nv; ++r) p.row_start[r + 1] = p.row_start[r] + degree(s, order[r]);
    p.col.resize(s.col.size());
    p.K.resize(s.K.size());
    p.diag.resize(nv);
    p.mass.resize(nv);
    std::vector<std::pair<int, double>> row;
    for (int r = 0; r < nv; ++r) {
        const int o = order[r];
        row.clear();
        for (int k = s.row_start[o]; k < s.row_start[o + 1]; ++k) row.emplace_back(rank[s.col[k]], s.K[k]);
        std::sort(row.begin(), row.end());
        for (size_t e = 0; e < row.size(); ++e) {
            const int k = p.row_start[r] + int(e);
            p.col[k] = row[e].first;
            p.K[k] = row[e].second;
            if (row[e].first == r) p.diag[r] = k;
        }
        p.mass(r) = s.mass(o);
    }
    return p;
}

ConstrainedSpace permute(const ConstrainedSpace& s, const std::vector<int>& order) {
    const int nv = s.vertices();
    ConstrainedSpace p;
    p.families = s.families;  // indexed through `family`, which moves with its vertex
    p.kind.resize(nv);
    p.c.resize(nv, 9);
    p.family.resize(nv);
    p.fixed_rotation.resize(nv);
    for (int r = 0; r < nv; ++r) {
        const int o = order[r];
        p.kind[r] = s.kind[o];
        p.c.row(r) = s.c.row(o);
        p.family[r] = s.family[o];
        p.fixed_rotation[r] = s.fixed_rotation[o];
    }
    return p;
}

}  // namespace framefix
