#include "framefix/singularities/chain_ends.h"

#include <algorithm>
#include <utility>

namespace framefix::detail {
namespace {

// In mean edge lengths (docs/algorithms.md#crossings-near-the-boundary). A curve that runs past
// another one within kCrossRadius and then leaves through the boundary within kCrossReach has
// passed a node the chains missed: on the groove with filleted rims the rising curves pass the
// rims' valence-3 curves 0.3-0.7 h apart, 1-2 triangles before the top face, at every size.
constexpr double kCrossRadius = 1.0;
constexpr double kCrossReach = 3.0;  // as the dead-end attachment: the "one tet short" scale
// The curve passed must run on for this long on both sides of the crossing, and the crossing
// curve must come from at least this far, so that curves meeting at a node they share anyway
// and short stubs are not cut.
constexpr double kCrossMargin = 2.0;

struct Crossing {
    int b = -1, b_face = -1;  // the curve reaching the boundary and its face index at the crossing
    int a = -1, a_face = -1;  // the curve passed and its face index
    double distance = 0;
};

const Eigen::Vector3d& face_point(const ChainCurve& c, int i) { return c.points[size_t(c.face_point[size_t(i)])]; }

// Whether face i of `a` lies farther than `margin` from both of a's end nodes.
bool inside(const ChainGraph& g, const ChainCurve& a, int i, double margin) {
    if (a.closed) return true;
    for (int e : a.ends)
        if ((face_point(a, i) - g.nodes[size_t(e)].position).norm() <= margin) return false;
    return true;
}

// The closest crossing of curve b (open, ending on the boundary at `end`) with another curve.
Crossing find_crossing(const ChainGraph& g, int b, int end) {
    const double h = g.h_mean;
    const ChainCurve& B = g.curves[size_t(b)];
    const Eigen::Vector3d& exit = g.nodes[size_t(B.ends[end])].position;
    const Eigen::Vector3d& start = g.nodes[size_t(B.ends[1 - end])].position;
    const int n = int(B.faces.size());
    Crossing best;
    best.distance = kCrossRadius * h;
    for (int s = 1; s < n; ++s) {  // s: faces from the boundary end; the boundary face itself is the tail
        const int i = end == 1 ? n - 1 - s : s;
        if (i < 1 || i > n - 2) break;  // the curve keeps a face on each side of the crossing
        const Eigen::Vector3d& p = face_point(B, i);
        if ((p - exit).norm() > kCrossReach * h) break;
        if ((p - start).norm() <= kCrossMargin * h) break;
        for (int a = 0; a < int(g.curves.size()); ++a) {
            const ChainCurve& A = g.curves[size_t(a)];
            if (a == b || A.faces.empty()) continue;
            const int last = A.closed ? int(A.faces.size()) - 1 : int(A.faces.size()) - 2;
            for (int j = 0; j <= last; ++j) {
                const double d = (face_point(A, j) - p).norm();
                if (d < best.distance && inside(g, A, j, kCrossMargin * h)) best = {b, i, a, j, d};
            }
        }
    }
    return best;
}

ChainCurve piece(const ChainCurve& c, int first, int last, int end0, int end1, const ChainGraph& g) {
    ChainCurve out;
    out.ends[0] = end0;
    out.ends[1] = end1;
    auto add_node = [&](int id) { out.points.push_back(g.nodes[size_t(id)].position); };
    if (!g.nodes[size_t(end0)].boundary || c.face_point[size_t(first)] > 0) add_node(end0);
    const int nf = int(c.faces.size());
    for (int k = first;; k = (k + 1) % nf) {
        out.faces.push_back(c.faces[size_t(k)]);
        out.face_point.push_back(int(out.points.size()));
        out.points.push_back(face_point(c, k));
        if (k == last) break;
    }
    const bool last_point = c.face_point[size_t(last)] == int(c.points.size()) - 1;
    if (!g.nodes[size_t(end1)].boundary || !last_point) add_node(end1);
    return out;
}

// Splits curve `i` after face index `at` through the new node `node`.
void split(ChainGraph& g, int i, int at, int node) {
    const ChainCurve c = g.curves[size_t(i)];
    const int n = int(c.faces.size());
    if (c.closed) {  // opened at the crossing: a loop from the node back to it
        g.curves[size_t(i)] = piece(c, (at + 1) % n, at, node, node, g);
        return;
    }
    g.curves[size_t(i)] = piece(c, 0, at, c.ends[0], node, g);
    g.curves.push_back(piece(c, at + 1, n - 1, node, c.ends[1], g));
}

ChainNode crossing_node(const ChainGraph& g, const TetTopology& topo, const Crossing& x) {
    ChainNode n;
    n.crossing = true;
    const int fa = g.curves[size_t(x.a)].faces[size_t(x.a_face)], fb = g.curves[size_t(x.b)].faces[size_t(x.b_face)];
    n.position = (face_point(g.curves[size_t(x.a)], x.a_face) + face_point(g.curves[size_t(x.b)], x.b_face)) / 2;
    for (int f : {fa, fb})
        for (int k = 0; k < 2; ++k)
            if (topo.face_tets(f, k) >= 0) n.tets.push_back(topo.face_tets(f, k));
    std::sort(n.tets.begin(), n.tets.end());
    n.tets.erase(std::unique(n.tets.begin(), n.tets.end()), n.tets.end());
    return n;
}

}  // namespace

int join_crossings(ChainGraph& g, const TetTopology& topo, const CrossingCheck& accept) {
    const int original = int(g.curves.size());  // pieces cut off are not searched again
    int joined = 0;
    for (int b = 0; b < original; ++b) {
        for (int end : {1, 0}) {  // after a split at end 1, b still holds end 0
            const ChainCurve& B = g.curves[size_t(b)];
            if (B.faces.empty() || B.closed || !g.nodes[size_t(B.ends[end])].boundary) continue;
            const Crossing x = find_crossing(g, b, end);
            if (x.a < 0) continue;
            ChainGraph trial = g;
            const int node = int(trial.nodes.size());
            trial.nodes.push_back(crossing_node(g, topo, x));
            // b is split at the face before its tail (end 1) or after it (end 0): the tail
            // from the crossing to the boundary keeps the crossing face.
            split(trial, x.b, end == 1 ? x.b_face - 1 : x.b_face, node);
            split(trial, x.a, x.a_face, node);
            if (!accept(g, trial, x.a, x.b, node)) continue;
            g = std::move(trial);
            ++joined;
        }
    }
    return joined;
}

}  // namespace framefix::detail
