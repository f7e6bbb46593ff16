#include "framefix/hexmesh/flat_refinement.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "framefix/hexmesh/complex_splitter.h"
#include "framefix/hexmesh/hex_grid.h"

namespace framefix {

namespace {

// Share of an edge's length over which its leaving direction is read at most: further on, a
// curved edge (the notch's arc) turns away from its tangent.
constexpr double kMaxReachShare = 0.4;

Eigen::Vector3d row(const Points& p, Eigen::Index i) { return p.row(i).transpose(); }

// Unit direction in which edge `e` leaves `corner`.
Eigen::Vector3d leaving(const ComplexEdge& e, int corner, double reach) {
    const Points& p = e.polyline;
    const bool forward = e.a == corner;
    const Eigen::Index n = p.rows(), start = forward ? 0 : n - 1, step = forward ? 1 : -1;
    const double target = std::min(reach, kMaxReachShare * polyline_length(p));
    double s = 0;
    for (Eigen::Index i = start + step; i >= 0 && i < n; i += step) {
        s += (p.row(i) - p.row(i - step)).norm();
        if (s >= target) return (row(p, i) - row(p, start)).normalized();
    }
    return (row(p, n - 1 - start) - row(p, start)).normalized();
}
struct FlatTest {
    const BlockComplex& cx;
    double reach;
    double cos_flat, cos_end;  // an edge is flat when one end passes cos_flat and the other cos_end
    // The block's edges along axes a1 and a2 leave local corner l more than acos(cos) apart.
    bool apart(const ComplexBlock& b, int l, int a1, int a2, double cos) const {
        const int c = b.corners[l];
        return leaving(cx.edges[b.edges[edge_at(l, a1)]], c, reach).dot(leaving(cx.edges[b.edges[edge_at(l, a2)]], c, reach)) < cos;
    }
    bool flat_edge(const ComplexBlock& b, int e) const {
        const int d = e / 4, d1 = (d + 1) % 3, d2 = (d + 2) % 3;
        const auto l = edge_local_corners(e);
        return (apart(b, l[0], d1, d2, cos_flat) && apart(b, l[1], d1, d2, cos_end)) ||
               (apart(b, l[1], d1, d2, cos_flat) && apart(b, l[0], d1, d2, cos_end));
    }
    // Sum over the edge's two ends of the cosines between the two other edges (lower: flatter).
    double flatness(const ComplexBlock& b, int e) const {
        const int d = e / 4, d1 = (d + 1) % 3, d2 = (d + 2) % 3;
        double sum = 0;
        for (int l : edge_local_corners(e)) {
            const int c = b.corners[l];
            sum += leaving(cx.edges[b.edges[edge_at(l, d1)]], c, reach).dot(leaving(cx.edges[b.edges[edge_at(l, d2)]], c, reach));
        }
        return sum;
    }
    bool flat_corner(const ComplexBlock& b, int l) const {
        return apart(b, l, 0, 1, cos_flat) || apart(b, l, 1, 2, cos_flat) || apart(b, l, 0, 2, cos_flat);
    }
};

double cos_of(double flat_deg) { return std::cos((180.0 - flat_deg) * M_PI / 180.0); }

FlatTest flat_test(const BlockComplex& cx, double reach, double flat_deg, double end_deg) {
    return {cx, reach, cos_of(flat_deg), cos_of(end_deg)};
}

}  // namespace

FlatCount count_flat(const BlockComplex& cx, double reach, double flat_deg) {
    const FlatTest test = flat_test(cx, reach, flat_deg, flat_deg);
    FlatCount n;
    for (const ComplexBlock& b : cx.blocks) {
        for (int e = 0; e < 12; ++e) n.edges += test.flat_edge(b, e);
        for (int l = 0; l < 8; ++l)
            if (test.flat_corner(b, l)) n.corners += 1, n.where.push_back(cx.corners[b.corners[l]].position);
    }
    return n;
}

namespace {

// Block bi refined along its flattest flat edge the template can take, on a copy of cx; nullopt
// with `why` when none can or the block has none.
std::optional<BlockComplex> refined_copy(const TetMesh& mesh, const BlockComplex& cx, int bi, double reach, double flat_deg,
                                         double end_deg, std::string& why) {
    std::vector<std::pair<double, int>> flat;  // candidates, flattest first
    const FlatTest test = flat_test(cx, reach, flat_deg, end_deg);
    for (int e = 0; e < 12; ++e)
        if (test.flat_edge(cx.blocks[size_t(bi)], e)) flat.push_back({test.flatness(cx.blocks[size_t(bi)], e), e});
    std::sort(flat.begin(), flat.end());
    why.clear();
    for (const auto& [score, e] : flat) {
        BlockComplex tried = cx;
        if (!(why = refine_flat_block(mesh, tried, bi, e)).empty()) continue;
        return tried;
    }
    return std::nullopt;
}

}  // namespace

FlatRefinement refine_flat_edges(const TetMesh& mesh, double reach, double flat_deg, double end_deg, BlockComplex& cx,
                                 const std::function<bool(const BlockComplex&)>& keep) {
    FlatRefinement out;
    out.before = count_flat(cx, reach, flat_deg);
    out.blocks_before = int(cx.blocks.size());
    // Best first: each round refines, of the blocks with a flat edge, the one whose hexes then are
    // best. keep() accepts a complex only when its hexes beat every one it accepted before, so the
    // round's last accepted complex is its best.
    std::map<int, std::string> pending;  // block index -> why it is not refined (yet)
    for (int bi = 0; bi < int(cx.blocks.size()); ++bi) {
        std::string why;
        if (refined_copy(mesh, cx, bi, reach, flat_deg, end_deg, why) || !why.empty()) pending[bi] = why;
    }
    for (bool progress = true; progress && !pending.empty();) {
        progress = false;
        std::optional<BlockComplex> best;
        int chosen = -1;
        for (auto& [bi, why] : pending) {
            std::optional<BlockComplex> tried = refined_copy(mesh, cx, bi, reach, flat_deg, end_deg, why);
            if (!tried) continue;
            if (!keep(*tried)) {
                why = "its refined hexes are not better";
                continue;
            }
            best = std::move(tried), chosen = bi;
        }
        if (!best) break;
        cx = std::move(*best);
        pending.erase(chosen);
        out.refined += 1, progress = true;
    }
    for (const auto& [bi, why] : pending)
        if (!why.empty()) out.skipped.push_back("block " + std::to_string(cx.blocks[size_t(bi)].id) + ": " + why);
    out.after = count_flat(cx, reach, flat_deg);
    out.blocks_after = int(cx.blocks.size());
    return out;
}

}  // namespace framefix
