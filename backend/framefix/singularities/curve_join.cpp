#include "framefix/singularities/chain_ends.h"

#include <algorithm>
#include <utility>

#include "framefix/core/error.h"

namespace framefix::detail {
namespace {

void reverse_curve(ChainCurve& c) {
    const int np = int(c.points.size());
    std::reverse(c.faces.begin(), c.faces.end());
    std::reverse(c.points.begin(), c.points.end());
    std::reverse(c.face_point.begin(), c.face_point.end());
    for (int& p : c.face_point) p = np - 1 - p;
    std::swap(c.ends[0], c.ends[1]);
}

// (curve, end) pairs meeting at each node; curves emptied by a join are skipped.
std::vector<std::vector<std::pair<int, int>>> end_refs(const ChainGraph& g) {
    std::vector<std::vector<std::pair<int, int>>> refs(g.nodes.size());
    for (int i = 0; i < int(g.curves.size()); ++i) {
        const ChainCurve& c = g.curves[i];
        if (c.faces.empty() || c.closed) continue;
        for (int k = 0; k < 2; ++k) refs[c.ends[k]].emplace_back(i, k);
    }
    return refs;
}

// A loop at a junction that stays within this many mean edge lengths of the junction's tets
// encloses no room for a hex layer (HexMe n08o at 0.6 x: a loop 4.6 h long under the apex, at
// most 1.6 h from the junction's tets).
constexpr double kJunctionReach = 2.0;

bool near_tets(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& centroids, double reach) {
    return std::any_of(centroids.begin(), centroids.end(), [&](const Eigen::Vector3d& x) { return (p - x).norm() <= reach; });
}

// Empties every curve from a junction back to the same junction whose triangles (edges) all lie within
// kJunctionReach edge lengths of one of the junction's tets; returns how many.
int drop_junction_loops(ChainGraph& g, const TetMesh& mesh) {
    int dropped = 0;
    for (ChainCurve& c : g.curves) {
        if (c.faces.empty() || c.closed || c.ends[0] != c.ends[1]) continue;
        const ChainNode& n = g.nodes[size_t(c.ends[0])];
        if (n.boundary || n.tets.empty()) continue;
        std::vector<Eigen::Vector3d> centroids;
        for (int t : n.tets) centroids.push_back(tet_centroid(mesh, t));
        const double reach = kJunctionReach * g.h_mean;
        if (!std::all_of(c.face_point.begin(), c.face_point.end(),
                         [&](int i) { return near_tets(c.points[size_t(i)], centroids, reach); }))
            continue;
        c = ChainCurve{};  // emptied: removed by renumber
        ++dropped;
    }
    return dropped;
}

}  // namespace

int join_and_drop_loops(ChainGraph& g, const TetMesh& mesh) {
    int joined = 0;
    for (;;) {
        g.junk_chains += drop_junction_loops(g, mesh);
        const int j = join_pass_through(g);
        if (j == 0) return joined;
        joined += j;
    }
}

int join_pass_through(ChainGraph& g) {
    int joined = 0;
    for (;;) {
        const auto refs = end_refs(g);
        int node = -1;
        for (int n = 0; n < int(g.nodes.size()) && node < 0; ++n)
            if (!g.nodes[n].boundary && refs[n].size() == 2) node = n;
        if (node < 0) return joined;
        ++joined;
        const auto [a, ea] = refs[node][0];
        const auto [b, eb] = refs[node][1];
        ChainCurve& A = g.curves[a];
        // Interior node points are always in the raw polyline (assemble), so the node's point is
        // the first/last point and appears once in the joined curve.
        if (a == b) {
            A.points.pop_back();
            A.closed = true;
            A.ends[0] = A.ends[1] = -1;
            continue;
        }
        ChainCurve B = std::move(g.curves[b]);
        g.curves[b] = ChainCurve{};  // emptied: removed by renumber
        if (ea == 0) reverse_curve(A);
        if (eb == 1) reverse_curve(B);
        FF_ASSERT(A.ends[1] == node && B.ends[0] == node);
        const int offset = int(A.points.size()) - 1;
        A.faces.insert(A.faces.end(), B.faces.begin(), B.faces.end());
        for (int p : B.face_point) A.face_point.push_back(p + offset);
        A.points.insert(A.points.end(), B.points.begin() + 1, B.points.end());
        A.ends[1] = B.ends[1];
    }
}

void renumber(ChainGraph& g) {
    std::vector<ChainCurve> curves;
    for (ChainCurve& c : g.curves)
        if (!c.faces.empty()) curves.push_back(std::move(c));
    std::vector<int> id(g.nodes.size(), -1);
    std::vector<ChainNode> nodes;
    for (ChainCurve& c : curves) {
        if (c.closed) continue;
        for (int& e : c.ends) {
            if (id[e] < 0) {
                id[e] = int(nodes.size());
                nodes.push_back(std::move(g.nodes[e]));
            }
            e = id[e];
        }
    }
    g.curves = std::move(curves);
    g.nodes = std::move(nodes);
}

}  // namespace framefix::detail
