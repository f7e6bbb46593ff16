// Prism blocks cut into hexahedra (docs/algorithms.md#prism-cuts).
#include "framefix/blocks/prism_cuts.h"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <tuple>
#include <utility>

#include "framefix/blocks/partition.h"
#include "framefix/core/segment_distance.h"

namespace framefix {
namespace {

constexpr int kMaxSides = 8;

std::vector<int> shared_corners(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> s;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(s));
    return s;
}

// The laterals in cyclic order (each shares two corners with the next), or empty.
std::vector<int> lateral_cycle(const std::vector<int>& lats, const std::vector<std::vector<int>>& corners) {
    std::vector<int> cycle{lats[0]};
    std::set<int> left(lats.begin() + 1, lats.end());
    while (!left.empty()) {
        auto next = std::find_if(left.begin(), left.end(),
                                 [&](int l) { return shared_corners(corners[cycle.back()], corners[l]).size() == 2; });
        if (next == left.end()) return {};
        cycle.push_back(*next);
        left.erase(next);
    }
    if (shared_corners(corners[cycle.back()], corners[cycle.front()]).size() != 2) return {};
    return cycle;
}

}  // namespace

std::optional<Prism> prism_of(const BlockFaces& f, const BlockInfo& info, int min_n) {
    const int np = int(f.label.size()), nc = int(f.corner_patches.size());
    const int n = nc / 2;
    if (!info.manifold || info.euler != 2 || nc % 2 != 0 || n < min_n || n > kMaxSides || np != n + 2 ||
        info.edges != 3 * n)
        return std::nullopt;
    std::vector<std::vector<int>> corners(np);
    for (int c = 0; c < nc; ++c) {
        if (f.corner_patches[c].size() != 3) return std::nullopt;
        for (int p : f.corner_patches[c]) corners[p].push_back(c);
    }
    std::vector<int> caps, lats;
    for (int p = 0; p < np; ++p) (corners[p].size() == 4 ? lats : caps).push_back(p);
    if (caps.size() != 2 || int(lats.size()) != n || !shared_corners(corners[caps[0]], corners[caps[1]]).empty())
        return std::nullopt;
    Prism prism;
    prism.n = n;
    prism.caps[0] = caps[0], prism.caps[1] = caps[1];
    prism.laterals = lateral_cycle(lats, corners);
    if (prism.laterals.empty()) return std::nullopt;
    for (int i = 0; i < n; ++i) {
        const std::vector<int> s = shared_corners(corners[prism.laterals[(i + n - 1) % n]], corners[prism.laterals[i]]);
        prism.edge.push_back({s[0], s[1]});
    }
    return prism;
}

std::vector<std::vector<int>> prism_cut_sides(const Prism& prism, const std::vector<int>& face_label) {
    const int n = prism.n;
    std::set<std::vector<int>> cuts;
    for (int s = 0; s < n; ++s) {
        std::vector<int> side(n, 1);
        for (int k = 0; k < 3; ++k) side[(s + k) % n] = 0;  // three faces and the cut: a quad
        if (n % 2 == 1) {
            // Odd: two faces, then the middle of the third; that face must be the part's boundary,
            // or its neighbour would see two faces.
            if (face_label[prism.laterals[(s + 2) % n]] >= 0) continue;
            side[(s + 2) % n] = 2;
        }
        if (side[0] == 1) for (int& x : side) x = x == 2 ? 2 : 1 - x;  // one name per cut
        cuts.insert(side);
    }
    return {cuts.begin(), cuts.end()};
}

namespace {

// The side of each boundary triangle of the block (-1: a cap's, no seed).
std::vector<int> triangle_sides(const Prism& prism, const BlockFaces& f, const std::vector<BoundaryTriangle>& surface,
                                const std::vector<int>& side, const TetMesh& mesh) {
    std::map<int, int> lateral;  // patch -> index in the cycle
    for (int i = 0; i < prism.n; ++i) lateral[prism.laterals[i]] = i;
    std::vector<int> out(surface.size(), -1);
    for (size_t i = 0; i < surface.size(); ++i) {
        const auto it = lateral.find(f.patch[i]);
        if (it == lateral.end()) continue;
        const int li = it->second;
        if (side[li] != 2) {
            out[i] = side[li];
            continue;
        }
        // The face cut across its middle: each triangle goes with the nearer of its two edges.
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) c += mesh.points.row(surface[i].verts[k]).transpose() / 3;
        auto dist = [&](int e) {
            return point_segment_distance(c, f.corner_position[prism.edge[e][0]], f.corner_position[prism.edge[e][1]]);
        };
        const int n = prism.n, before = side[(li + n - 1) % n];  // edge li lies on that face's side
        out[i] = dist(li) <= dist((li + 1) % n) ? before : 1 - before;
    }
    return out;
}

// Tet distances (through the block's tets) from the seeds: tets under a triangle of that side.
std::vector<double> distances_from(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, int b,
                                   const std::vector<std::pair<int, double>>& seeds) {
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

// The block's tets labelled 0 / 1 by the nearer side of the cut (ties to 0).
Eigen::VectorXi cut_labels(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& out, int b,
                           const std::vector<BoundaryTriangle>& surface, const std::vector<int>& tri_side) {
    std::map<std::array<int, 3>, int> index;
    for (size_t i = 0; i < surface.size(); ++i) {
        std::array<int, 3> key{surface[i].verts[0], surface[i].verts[1], surface[i].verts[2]};
        std::sort(key.begin(), key.end());
        index[key] = int(i);
    }
    std::vector<std::pair<int, double>> seeds[2];
    for (int t : out.blocks[b].tets)
        for (int k = 0; k < 4; ++k) {
            const int f = topo.tet_faces(t, k), u = tet_across(topo, f, t);
            if (u >= 0 && out.tet_block[u] == b) continue;
            std::array<int, 3> key{topo.faces(f, 0), topo.faces(f, 1), topo.faces(f, 2)};
            std::sort(key.begin(), key.end());
            const auto it = index.find(key);
            if (it == index.end() || tri_side[it->second] < 0) continue;
            Eigen::Vector3d fc = Eigen::Vector3d::Zero();
            for (int j = 0; j < 3; ++j) fc += mesh.points.row(key[j]).transpose() / 3;
            seeds[tri_side[it->second]].push_back({t, (tet_centroid(mesh, t) - fc).norm()});
        }
    const std::vector<double> d0 = distances_from(mesh, topo, out, b, seeds[0]);
    const std::vector<double> d1 = distances_from(mesh, topo, out, b, seeds[1]);
    Eigen::VectorXi labels = out.tet_block;
    for (int t : out.blocks[b].tets) labels[t] = d1[t] < d0[t] ? out.count : b;
    return labels;
}

// Block ids of `out` and of `tried` (out with block b cut) mapped both ways; the two halves of
// b have no earlier counterpart.
EarlierBlocks map_cut(const BlockDecomposition& out, const Validated& v, const BlockDecomposition& tried, int b) {
    EarlierBlocks earlier{out, v, std::vector<int>(tried.count, -1), std::vector<int>(out.count, -1)};
    for (int o = 0; o < out.count; ++o) {
        const int n = tried.tet_block[out.blocks[o].tets.front()];
        earlier.new_of_old[o] = n;
        if (o != b) earlier.old_of_new[n] = o;
    }
    return earlier;
}

int non_conforming(const BlockDecomposition& b) { return b.pairs - b.conforming_pairs; }

// Whether `tried` keeps every block of `out` but b valid (their tets' blocks), has more valid
// blocks, no more non-conforming pairs, and scores better.
bool better_cut(const BlockDecomposition& out, const BlockDecomposition& tried, int b) {
    if (tried.valid <= out.valid || non_conforming(tried) > non_conforming(out) || !(score(tried) > score(out)))
        return false;
    for (int o = 0; o < out.count; ++o)
        if (o != b && out.blocks[o].valid && !tried.blocks[tried.tet_block[out.blocks[o].tets.front()]].valid)
            return false;
    return true;
}

std::optional<std::pair<BlockDecomposition, Validated>> cut_block(const TetMesh& mesh, const TetTopology& topo,
                                                                  const std::vector<int>& group, double h,
                                                                  const BlockOptions& options,
                                                                  const BlockDecomposition& out, const Validated& v,
                                                                  int b, const Eigen::VectorXi& labels) {
    BlockDecomposition tried = out;
    std::vector<char> near(size_t(out.count) + 1, 0);
    near[size_t(b)] = near[size_t(out.count)] = 1;
    for (int n : out.blocks[b].neighbours) near[size_t(n)] = 1;
    tried.tet_block = clean_staircase(mesh, topo, labels, near);
    tried.count = compact_labels(tried.tet_block);
    Validated w = collect_boundaries(mesh, topo, group, tried);
    const EarlierBlocks earlier = map_cut(out, v, tried, b);
    validate_collected(mesh, h, options, tried, w, &earlier);
    count_conformity(w, h, options, tried);
    if (!better_cut(out, tried, b)) return std::nullopt;
    return std::pair{std::move(tried), std::move(w)};
}

// Mean outward normal of each patch.
std::vector<Eigen::Vector3d> patch_normals(const BlockFaces& f, const std::vector<BoundaryTriangle>& surface) {
    std::vector<Eigen::Vector3d> n(f.label.size(), Eigen::Vector3d::Zero());
    for (size_t i = 0; i < surface.size(); ++i) n[size_t(f.patch[i])] += surface[i].normal;
    for (Eigen::Vector3d& x : n) x.normalize();
    return n;
}

// Cuts in order of how flat the block is where they start and end (a cut at a flat lateral edge
// leaves two corners of about 90 degrees).
std::vector<std::vector<int>> ordered_cuts(const Prism& prism, const BlockFaces& f,
                                           const std::vector<BoundaryTriangle>& surface) {
    const std::vector<Eigen::Vector3d> normal = patch_normals(f, surface);
    std::vector<std::pair<double, std::vector<int>>> scored;
    const int n = prism.n;
    for (const std::vector<int>& side : prism_cut_sides(prism, f.label)) {
        double flat = 0;
        for (int i = 0; i < n; ++i) {
            const int a = side[(i + n - 1) % n], c = side[i];
            if (a != c && a != 2 && c != 2)
                flat += normal[prism.laterals[(i + n - 1) % n]].dot(normal[prism.laterals[i]]);
        }
        scored.push_back({-flat, side});
    }
    std::sort(scored.begin(), scored.end());
    std::vector<std::vector<int>> cuts;
    for (auto& [s, side] : scored) cuts.push_back(std::move(side));
    return cuts;
}

// One prism cut that gives better blocks, into `out`. False if none does.
bool cut_one(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
             const BlockOptions& options, BlockDecomposition& out, Validated& v, std::set<std::pair<int, int>>& failed) {
    for (int b = 0; b < out.count; ++b) {
        const BlockInfo& info = out.blocks[b];
        const std::pair<int, int> name{info.tets.front(), int(info.tets.size())};
        if (info.valid || failed.count(name)) continue;
        const std::optional<Prism> prism = prism_of(v.faces[b], info);
        if (!prism) continue;
        for (const std::vector<int>& side : ordered_cuts(*prism, v.faces[b], v.surface[b])) {
            const std::vector<int> tri_side = triangle_sides(*prism, v.faces[b], v.surface[b], side, mesh);
            const Eigen::VectorXi labels = cut_labels(mesh, topo, out, b, v.surface[b], tri_side);
            auto tried = cut_block(mesh, topo, group, h, options, out, v, b, labels);
            if (!tried) continue;
            out = std::move(tried->first), v = std::move(tried->second), ++out.prism_cuts;
            return true;
        }
        failed.insert(name);
    }
    return false;
}

}  // namespace

void cut_prisms(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                const BlockOptions& options, BlockDecomposition& out, Validated& v) {
    std::set<std::pair<int, int>> failed;
    for (int round = 0; round < options.prism_rounds && cut_one(mesh, topo, group, h, options, out, v, failed); ++round) {
    }
}

}  // namespace framefix
