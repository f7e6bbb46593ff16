#include "framefix/hexmesh/hex_grid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "framefix/core/disjoint_set.h"
#include "framefix/hexmesh/hex_projection.h"

namespace framefix {

namespace {

// Rounds of 1/4-1/2-1/4 averaging: 20 spread each vertex over about 3 chain vertices each way
// (variance 20 / 2), the period of a tet-edge staircase.
constexpr int kEdgeSmoothingRounds = 20;


// n + 1 points at equal arc length along the polyline, ends included.
std::vector<Eigen::Vector3d> resample(const Points& p, int n) {
    std::vector<double> at(size_t(p.rows()), 0);
    for (Eigen::Index i = 1; i < p.rows(); ++i) at[size_t(i)] = at[size_t(i - 1)] + (p.row(i) - p.row(i - 1)).norm();
    std::vector<Eigen::Vector3d> out;
    size_t seg = 1;
    for (int k = 0; k <= n; ++k) {
        const double s = at.back() * k / n;
        while (seg + 1 < at.size() && at[seg] < s) ++seg;
        const double len = at[seg] - at[seg - 1];
        const double f = len > 0 ? std::clamp((s - at[seg - 1]) / len, 0.0, 1.0) : 0;
        out.push_back(((1 - f) * p.row(Eigen::Index(seg - 1)) + f * p.row(Eigen::Index(seg))).transpose());
    }
    out.front() = p.row(0).transpose(), out.back() = p.row(p.rows() - 1).transpose();
    return out;
}

// Laplacian rounds along a polyline, its ends fixed: an interior edge is a chain of tet-mesh
// vertices, a staircase about h/2 deep, which the hex edges must not follow.
Points smoothed(Points p, int rounds) {
    for (int r = 0; r < rounds; ++r) {
        Points next = p;
        for (Eigen::Index i = 1; i + 1 < p.rows(); ++i) next.row(i) = 0.5 * p.row(i) + 0.25 * (p.row(i - 1) + p.row(i + 1));
        p = next;
    }
    return p;
}

// Ids from corner x to corner y along the edge joining them, and the edge's count.
struct EdgeLookup {
    const BlockComplex& cx;
    const std::vector<std::vector<int>>& ids;
    std::map<std::pair<int, int>, int> by_corners;
    EdgeLookup(const BlockComplex& c, const std::vector<std::vector<int>>& i) : cx(c), ids(i) {
        for (int e = 0; e < int(cx.edges.size()); ++e) by_corners[{cx.edges[e].a, cx.edges[e].b}] = e;
    }
    std::vector<int> from_to(int x, int y) const {
        const int e = by_corners.at(std::minmax(x, y));
        std::vector<int> out = ids[e];
        if (cx.edges[e].a != x) std::reverse(out.begin(), out.end());
        return out;
    }
};

HexGrid::FaceGrid face_grid(const ComplexFace& f, const EdgeLookup& edges, HexGrid& g) {
    const auto& c = f.corners;
    const std::vector<int> bottom = edges.from_to(c[0], c[1]), top = edges.from_to(c[3], c[2]);
    const std::vector<int> left = edges.from_to(c[0], c[3]), right = edges.from_to(c[1], c[2]);
    HexGrid::FaceGrid fg;
    fg.ns = int(bottom.size()) - 1, fg.nt = int(left.size()) - 1;
    fg.ids.assign(size_t((fg.ns + 1) * (fg.nt + 1)), -1);
    auto at = [&](int s, int t) -> int& { return fg.ids[size_t(t * (fg.ns + 1) + s)]; };
    for (int s = 0; s <= fg.ns; ++s) at(s, 0) = bottom[s], at(s, fg.nt) = top[s];
    for (int t = 0; t <= fg.nt; ++t) at(0, t) = left[t], at(fg.ns, t) = right[t];
    auto P = [&](int id) { return g.points[size_t(id)]; };
    for (int t = 1; t < fg.nt; ++t)
        for (int s = 1; s < fg.ns; ++s) {
            const double u = double(s) / fg.ns, v = double(t) / fg.nt;
            const Eigen::Vector3d coons = (1 - v) * P(bottom[s]) + v * P(top[s]) + (1 - u) * P(left[t]) + u * P(right[t]) -
                                          ((1 - u) * (1 - v) * P(bottom[0]) + u * (1 - v) * P(bottom[fg.ns]) +
                                           (1 - u) * v * P(top[0]) + u * v * P(top[fg.ns]));
            at(s, t) = int(g.points.size());
            g.points.push_back(coons);
        }
    return fg;
}

// Position of block-grid vertex (i, j, k) by transfinite interpolation of the block's boundary.
Eigen::Vector3d tfi(const HexGrid& g, const HexGrid::BlockGrid& b, int i, int j, int k) {
    const int n0 = b.n[0], n1 = b.n[1], n2 = b.n[2];
    const double u = double(i) / n0, v = double(j) / n1, w = double(k) / n2;
    auto P = [&](int a, int c, int d) { return g.points[size_t(b.at(a, c, d))]; };
    const double U[2] = {1 - u, u}, V[2] = {1 - v, v}, W[2] = {1 - w, w};
    const int I[2] = {0, n0}, J[2] = {0, n1}, K[2] = {0, n2};
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int s = 0; s < 2; ++s) x += U[s] * P(I[s], j, k) + V[s] * P(i, J[s], k) + W[s] * P(i, j, K[s]);
    for (int s = 0; s < 2; ++s)
        for (int t = 0; t < 2; ++t)
            x -= U[s] * V[t] * P(I[s], J[t], k) + U[s] * W[t] * P(I[s], j, K[t]) + V[s] * W[t] * P(i, J[s], K[t]);
    for (int s = 0; s < 2; ++s)
        for (int t = 0; t < 2; ++t)
            for (int r = 0; r < 2; ++r) x += U[s] * V[t] * W[r] * P(I[s], J[t], K[r]);
    return x;
}

HexGrid::BlockGrid block_grid(const BlockComplex& cx, const ComplexBlock& blk, HexGrid& g) {
    HexGrid::BlockGrid bg;
    for (int d = 0; d < 3; ++d) bg.n[d] = cx.edges[blk.edges[4 * d]].count;
    bg.ids.assign(size_t((bg.n[0] + 1) * (bg.n[1] + 1) * (bg.n[2] + 1)), -1);
    auto cell = [&](int i, int j, int k) -> int& { return bg.ids[size_t((k * (bg.n[1] + 1) + j) * (bg.n[0] + 1) + i)]; };
    auto bits = [&](int corner) {
        for (int l = 0; l < 8; ++l)
            if (blk.corners[l] == corner) return std::array<int, 3>{l & 1, (l >> 1) & 1, (l >> 2) & 1};
        return std::array<int, 3>{-1, -1, -1};
    };
    for (int lf = 0; lf < 6; ++lf) {
        const int axis = lf / 2, side = lf % 2;
        const ComplexFace& f = cx.faces[blk.faces[lf]];
        const HexGrid::FaceGrid& fg = g.face_ids[blk.faces[lf]];
        const auto q0 = bits(f.corners[0]), q1 = bits(f.corners[1]), q3 = bits(f.corners[3]);
        int sa = 0, ta = 0;
        for (int d = 0; d < 3; ++d) {
            if (q1[d] != q0[d]) sa = d;
            if (q3[d] != q0[d]) ta = d;
        }
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int a = 0; a <= bg.n[u]; ++a)
            for (int c = 0; c <= bg.n[v]; ++c) {
                int idx[3];
                idx[axis] = side ? bg.n[axis] : 0, idx[u] = a, idx[v] = c;
                const int s = q0[sa] == 0 ? idx[sa] : bg.n[sa] - idx[sa];
                const int t = q0[ta] == 0 ? idx[ta] : bg.n[ta] - idx[ta];
                cell(idx[0], idx[1], idx[2]) = fg.at(s, t);
            }
    }
    for (int k = 1; k < bg.n[2]; ++k)
        for (int j = 1; j < bg.n[1]; ++j)
            for (int i = 1; i < bg.n[0]; ++i) {
                cell(i, j, k) = int(g.points.size());
                g.points.emplace_back(Eigen::Vector3d::Zero());
            }
    for (int k = 1; k < bg.n[2]; ++k)
        for (int j = 1; j < bg.n[1]; ++j)
            for (int i = 1; i < bg.n[0]; ++i) g.points[size_t(bg.at(i, j, k))] = tfi(g, bg, i, j, k);
    return bg;
}

}  // namespace

int assign_edge_counts(BlockComplex& cx, double& size, int layers) {
    DisjointSet classes(int(cx.edges.size()));
    for (const ComplexBlock& b : cx.blocks)
        for (int d = 0; d < 3; ++d)
            for (int r = 1; r < 4; ++r) classes.unite(b.edges[4 * d], b.edges[4 * d + r]);
    std::map<int, std::pair<double, int>> length;  // class root -> (sum of lengths, edges)
    for (int e = 0; e < int(cx.edges.size()); ++e) {
        auto& l = length[classes.find(e)];
        l.first += polyline_length(cx.edges[e].polyline), l.second += 1;
    }
    if (layers > 0) {
        double shortest = 1e300;
        for (const auto& [root, l] : length) shortest = std::min(shortest, l.first / l.second);
        size = shortest / layers;
    }
    for (int e = 0; e < int(cx.edges.size()); ++e) {
        const auto& l = length[classes.find(e)];
        cx.edges[e].count = std::max(1, int(std::lround(l.first / l.second / size)));
    }
    return int(length.size());
}

HexGrid hex_grid(const TetMesh& mesh, const BlockComplex& cx, const CadProjector& cad) {
    HexGrid g;
    const SurfaceLocator locator(mesh);
    // The boundary faces' projectors, and for each corner and edge one boundary face it bounds.
    // An edge off the feature curves goes onto that face's own triangles, not by its chain's
    // vertices: where the patch cleaning merged interface triangles into a boundary face, the
    // chain between them runs partly inside the part, through vertices of other CAD faces.
    std::vector<std::optional<FaceProjector>> onto(cx.faces.size());
    std::map<std::pair<int, int>, int> face_of_edge;
    std::vector<int> face_of_corner(cx.corners.size(), -1);
    for (size_t f = 0; f < cx.faces.size(); ++f) {
        if (!cx.faces[f].boundary) continue;
        onto[f].emplace(mesh, cx.faces[f], locator);
        const auto& c = cx.faces[f].corners;
        for (int n = 0; n < 4; ++n) {
            face_of_edge.try_emplace(std::minmax(c[n], c[(n + 1) % 4]), int(f));
            if (face_of_corner[c[n]] < 0) face_of_corner[c[n]] = int(f);
        }
    }
    for (size_t c = 0; c < cx.corners.size(); ++c) {
        Eigen::Vector3d p = project_corner(mesh, cx.corners[c], locator, cad);
        if (p == cx.corners[c].position && face_of_corner[c] >= 0) p = onto[size_t(face_of_corner[c])]->project(p, cad);
        g.points.push_back(p);
    }
    for (const ComplexEdge& e : cx.edges) {
        const EdgeSupport support = edge_support(mesh, e, locator);
        const Points line = support.kind == EdgeSupport::curve ? e.polyline : smoothed(e.polyline, kEdgeSmoothingRounds);
        const std::vector<Eigen::Vector3d> pts = resample(line, e.count);
        const auto face = face_of_edge.find({e.a, e.b});
        std::vector<int> ids{e.a};
        for (int k = 1; k < e.count; ++k) {
            ids.push_back(int(g.points.size()));
            const Eigen::Vector3d& p = pts[size_t(k)];
            g.points.push_back(support.kind != EdgeSupport::curve && face != face_of_edge.end()
                                   ? onto[size_t(face->second)]->project(p, cad)
                                   : project_on_support(p, support, cad));
        }
        ids.push_back(e.b);
        g.edge_ids.push_back(std::move(ids));
    }
    const EdgeLookup edges(cx, g.edge_ids);
    for (size_t f = 0; f < cx.faces.size(); ++f) {
        g.face_ids.push_back(face_grid(cx.faces[f], edges, g));
        if (!onto[f]) continue;  // an interface's triangles are a tet staircase: its Coons patch is smoother
        const HexGrid::FaceGrid& fg = g.face_ids.back();
        for (int t = 1; t < fg.nt; ++t)
            for (int s = 1; s < fg.ns; ++s) g.points[size_t(fg.at(s, t))] = onto[f]->project(g.points[size_t(fg.at(s, t))], cad);
    }
    for (const ComplexBlock& b : cx.blocks) g.block_ids.push_back(block_grid(cx, b, g));
    return g;
}

std::array<int, 8> hex_of(const HexGrid::BlockGrid& g, int i, int j, int k) {
    return {g.at(i, j, k),         g.at(i + 1, j, k),         g.at(i + 1, j + 1, k),         g.at(i, j + 1, k),
            g.at(i, j, k + 1),     g.at(i + 1, j, k + 1),     g.at(i + 1, j + 1, k + 1),     g.at(i, j + 1, k + 1)};
}

}  // namespace framefix
