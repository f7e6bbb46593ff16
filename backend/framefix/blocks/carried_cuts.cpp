// A block cut in two, the cut carried through the neighbours it splits
// (docs/algorithms.md#cuts-carried-through-the-neighbours).
#include "framefix/blocks/carried_cuts.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <utility>

#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

// A shared face is split when each side holds at least this fraction of the tets under it: a cut
// running along the face's rim leaves a few staircase tets on the other side.
constexpr double kSplitFraction = 0.1;
// A face beside the entry face lies on one side when this fraction of the vertices it shares
// with the entry face do; below, the cut crosses it.
constexpr double kWholeFraction = 0.8;

TriangleKey key_of(const Eigen::Vector3i& v) { return triangle_key(v[0], v[1], v[2]); }

// Per boundary triangle of a block: the block's tet under it and the tet across (-1: none).
struct Under {
    std::vector<int> tet, across;
};

Under tets_under(const TetTopology& topo, const BlockDecomposition& out, const std::vector<BoundaryTriangle>& surface,
                 int b) {
    std::map<TriangleKey, int> index;
    for (size_t i = 0; i < surface.size(); ++i) index[key_of(surface[i].verts)] = int(i);
    Under u{std::vector<int>(surface.size(), -1), std::vector<int>(surface.size(), -1)};
    for (int t : out.blocks[b].tets)
        for (int k = 0; k < 4; ++k) {
            const int f = topo.tet_faces(t, k), a = tet_across(topo, f, t);
            if (a >= 0 && out.tet_block[a] == b) continue;
            const auto it = index.find(key_of(topo.faces.row(f).transpose()));
            if (it != index.end()) u.tet[size_t(it->second)] = t, u.across[size_t(it->second)] = a;
        }
    return u;
}

using Seeds = std::vector<std::pair<int, double>>;

// Dijkstra distances through block b's tets (centroid to centroid) from the seed tets.
std::vector<double> distances_from(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, int b,
                                   const Seeds& seeds) {
    std::vector<double> d(size_t(mesh.num_tets()), 1e300);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (auto [t, d0] : seeds)
        if (d0 < d[t]) d[t] = d0, queue.push({d0, t});
    while (!queue.empty()) {
        const auto [dt, t] = queue.top();
        queue.pop();
        if (dt > d[t]) continue;
        const Eigen::Vector3d ct = tet_centroid(mesh, t);
        for (int k = 0; k < 4; ++k) {
            const int u = tet_across(topo, topo.tet_faces(t, k), t);
            if (u < 0 || out.tet_block[u] != b) continue;
            const double du = dt + (tet_centroid(mesh, u) - ct).norm();
            if (du < d[u]) d[u] = du, queue.push({du, u});
        }
    }
    return d;
}

// Block b's tets into `side`: 1 where nearer the triangles of side 1 than those of side 0.
void split_block(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, int b,
                 const std::vector<BoundaryTriangle>& surface, const Under& under, const std::vector<int>& tri_side,
                 std::vector<signed char>& side) {
    Seeds seeds[2];
    for (size_t i = 0; i < surface.size(); ++i) {
        const int t = under.tet[i];
        if (tri_side[i] < 0 || t < 0) continue;
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) c += mesh.points.row(surface[i].verts[k]).transpose() / 3;
        seeds[tri_side[i]].push_back({t, (tet_centroid(mesh, t) - c).norm()});
    }
    const std::vector<double> d0 = distances_from(mesh, topo, out, b, seeds[0]);
    const std::vector<double> d1 = distances_from(mesh, topo, out, b, seeds[1]);
    for (int t : out.blocks[b].tets) side[size_t(t)] = d1[t] < d0[t] ? 1 : 0;
}

// The neighbours across the faces of a cut block that the cut splits.
std::vector<int> split_neighbours(const BlockFaces& f, const Under& under, const std::vector<signed char>& side) {
    std::map<int, std::array<int, 2>> count;  // patch -> tets under it on side 0, 1
    for (size_t i = 0; i < f.patch.size(); ++i) {
        const int p = f.patch[i], t = under.tet[i];
        if (f.label[p] >= 0 && t >= 0) ++count[p][size_t(side[size_t(t)])];
    }
    std::vector<int> out;
    for (const auto& [p, c] : count)
        if (std::min(c[0], c[1]) >= kSplitFraction * (c[0] + c[1])) out.push_back(f.label[p]);
    return out;
}

// Per patch of a hexahedron: corners shared with patch `e`.
std::vector<int> corners_shared_with(const BlockFaces& f, int e) {
    std::vector<int> shared(f.label.size(), 0);
    for (const std::vector<int>& ps : f.corner_patches)
        if (std::find(ps.begin(), ps.end(), e) != ps.end())
            for (int q : ps)
                if (q != e) ++shared[size_t(q)];
    return shared;
}

bool share_a_corner(const BlockFaces& f, int p, int q) {
    for (const std::vector<int>& ps : f.corner_patches)
        if (std::count(ps.begin(), ps.end(), p) && std::count(ps.begin(), ps.end(), q)) return true;
    return false;
}

// Side of each face beside the entry face `e` (0, 1, or 2 where the cut crosses it), read from
// the sides of the vertices they share with it; -1 for the other faces.
std::vector<int> beside_sides(const BlockFaces& f, const std::vector<BoundaryTriangle>& surface,
                              const std::vector<int>& tri, int e) {
    std::map<int, std::array<int, 2>> vertex;  // entry-face vertex -> its triangles on side 0, 1
    for (size_t i = 0; i < surface.size(); ++i)
        if (f.patch[i] == e && tri[i] >= 0)
            for (int k = 0; k < 3; ++k) ++vertex[surface[i].verts[k]][size_t(tri[i])];
    const std::vector<int> shared = corners_shared_with(f, e);
    std::vector<std::set<int>> along(f.label.size());  // per face beside e: its vertices on e
    for (size_t i = 0; i < surface.size(); ++i)
        if (shared[size_t(f.patch[i])] == 2)
            for (int k = 0; k < 3; ++k)
                if (vertex.count(surface[i].verts[k])) along[size_t(f.patch[i])].insert(surface[i].verts[k]);
    std::vector<int> sides(f.label.size(), -1);
    for (size_t p = 0; p < along.size(); ++p) {
        if (shared[p] != 2) continue;
        int n[2] = {0, 0};
        for (int x : along[p]) ++n[vertex[x][1] > vertex[x][0]];
        const double all = std::max(1, n[0] + n[1]);
        sides[p] = n[0] >= kWholeFraction * all ? 0 : n[1] >= kWholeFraction * all ? 1 : 2;
    }
    return sides;
}

// The two opposite faces beside the entry that lie wholly on sides 0 and 1 while one of the other
// two is crossed: the cut runs between them. A face the cut crosses near its end reads whole, so
// the other pair needs only one crossed face. Empty unless exactly one pair qualifies.
std::optional<std::pair<int, int>> whole_pair(const BlockFaces& f, const std::vector<int>& sides) {
    std::vector<std::pair<int, int>> opposite;  // pairs of faces beside the entry, no shared corner
    for (int p = 0; p < int(sides.size()); ++p)
        for (int q = p + 1; q < int(sides.size()); ++q)
            if (sides[p] >= 0 && sides[q] >= 0 && !share_a_corner(f, p, q)) opposite.push_back({p, q});
    if (opposite.size() != 2) return std::nullopt;
    std::optional<std::pair<int, int>> found;
    for (int k = 0; k < 2; ++k) {
        const auto [p, q] = opposite[size_t(k)];
        const auto [r, s] = opposite[size_t(1 - k)];
        if (sides[p] + sides[q] != 1 || sides[p] == 2 || sides[q] == 2 || (sides[r] != 2 && sides[s] != 2)) continue;
        if (found) return std::nullopt;
        found = sides[p] == 0 ? std::pair{p, q} : std::pair{q, p};
    }
    return found;
}

// The sides of a valid hexahedron's triangles when the cut enters it through the face it shares
// with block `from`: that face's triangles take the sides of from's tets across, and the faces of
// whole_pair seed their sides. Empty without such a pair.
std::optional<std::vector<int>> entry_sides(const BlockFaces& f, const std::vector<BoundaryTriangle>& surface,
                                            const Under& under, int from, const std::vector<signed char>& side) {
    const auto e = std::find(f.label.begin(), f.label.end(), from);
    if (e == f.label.end() || std::count(f.label.begin(), f.label.end(), from) != 1) return std::nullopt;
    const int entry = int(e - f.label.begin());
    std::vector<int> tri(surface.size(), -1);
    for (size_t i = 0; i < surface.size(); ++i)
        if (f.patch[i] == entry && under.across[i] >= 0 && side[size_t(under.across[i])] >= 0)
            tri[i] = side[size_t(under.across[i])];
    const std::vector<int> sides = beside_sides(f, surface, tri, entry);
    const std::optional<std::pair<int, int>> whole = whole_pair(f, sides);
    if (!whole) return std::nullopt;
    for (size_t i = 0; i < surface.size(); ++i)
        if (f.patch[i] == whole->first || f.patch[i] == whole->second) tri[i] = sides[size_t(f.patch[i])];
    return tri;
}

// Whether the tets on both sides of the face block n shares with block `from`, both cut, lie on
// the same side of the cut: all but a staircase's share of them.
bool same_sides_across(const BlockFaces& f, const Under& under, int from, const std::vector<signed char>& side) {
    int same = 0, all = 0;
    for (size_t i = 0; i < f.patch.size(); ++i) {
        const int t = under.tet[i], a = under.across[i];
        if (f.label[f.patch[i]] != from || t < 0 || a < 0 || side[size_t(t)] < 0 || side[size_t(a)] < 0) continue;
        ++all, same += side[size_t(t)] == side[size_t(a)];
    }
    return all > 0 && same >= (1 - kSplitFraction) * all;
}

}  // namespace

CarriedCut cut_alone(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, const Validated& v,
                     int b, const std::vector<int>& tri_side) {
    CarriedCut cut{std::vector<signed char>(size_t(mesh.num_tets()), -1), {b}};
    split_block(mesh, topo, out, b, v.surface[b], tets_under(topo, out, v.surface[b], b), tri_side, cut.side);
    return cut;
}

std::optional<CarriedCut> carry_cut(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out,
                                    const Validated& v, int b, const std::vector<int>& tri_side, int max_blocks) {
    CarriedCut cut = cut_alone(mesh, topo, out, v, b, tri_side);
    std::vector<char> in(size_t(out.count), 0);
    in[size_t(b)] = 1;
    std::queue<std::pair<int, int>> todo;  // (block, the cut block it is entered from)
    for (int n : split_neighbours(v.faces[b], tets_under(topo, out, v.surface[b], b), cut.side)) todo.push({n, b});
    while (!todo.empty()) {
        const auto [n, from] = todo.front();
        todo.pop();
        const Under u = tets_under(topo, out, v.surface[n], n);
        if (in[size_t(n)]) {  // the sheet closes round: both blocks cut alike along their face
            if (!same_sides_across(v.faces[n], u, from, cut.side)) return std::nullopt;
            continue;
        }
        if (!out.blocks[n].valid || int(cut.blocks.size()) >= max_blocks) return std::nullopt;
        const std::optional<std::vector<int>> sides = entry_sides(v.faces[n], v.surface[n], u, from, cut.side);
        if (!sides) return std::nullopt;
        split_block(mesh, topo, out, n, v.surface[n], u, *sides, cut.side);
        in[size_t(n)] = 1;
        cut.blocks.push_back(n);
        for (int m : split_neighbours(v.faces[n], u, cut.side))
            if (m != from) todo.push({m, n});
    }
    return cut;
}

}  // namespace framefix
