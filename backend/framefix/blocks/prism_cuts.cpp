// Prism blocks cut into hexahedra (docs/algorithms.md#prism-cuts).
#include "framefix/blocks/prism_cuts.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "framefix/blocks/carried_cuts.h"
#include "framefix/blocks/partition.h"
#include "framefix/core/segment_distance.h"

namespace framefix {
namespace {

constexpr int kMaxSides = 8;
// A prism cut carried on through its neighbours cuts at most this many blocks: a sheet across
// a part crosses a few blocks; one that runs on further rather comes back round.
constexpr int kMaxCutBlocks = 16;

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

std::vector<std::vector<int>> prism_cut_sides(const Prism& prism) {
    const int n = prism.n;
    std::set<std::vector<int>> cuts;
    for (int s = 0; s < n; ++s) {
        std::vector<int> side(n, 1);
        for (int k = 0; k < 3; ++k) side[(s + k) % n] = 0;  // three faces and the cut: a quad
        if (n % 2 == 1) side[(s + 2) % n] = 2;  // two faces, then the middle of the third
        if (side[0] == 1) for (int& x : side) x = x == 2 ? 2 : 1 - x;  // one name per cut
        cuts.insert(side);
    }
    return {cuts.begin(), cuts.end()};
}

bool cuts_a_neighbour_across(const Prism& prism, const std::vector<int>& side, const std::vector<int>& face_label) {
    for (int i = 0; i < prism.n; ++i)
        if (side[i] == 2 && face_label[prism.laterals[i]] >= 0) return true;
    return false;
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

// Block ids of `out` and of `tried` (out with the blocks of `cut` cut) mapped both ways; the
// halves of a cut block have no earlier counterpart.
EarlierBlocks map_cut(const BlockDecomposition& out, const Validated& v, const BlockDecomposition& tried,
                      const CarriedCut& cut) {
    EarlierBlocks earlier{out, v, std::vector<int>(tried.count, -1), std::vector<int>(out.count, -1)};
    for (int o = 0; o < out.count; ++o) {
        const int n = tried.tet_block[out.blocks[o].tets.front()];
        earlier.new_of_old[o] = n;
        if (std::find(cut.blocks.begin(), cut.blocks.end(), o) == cut.blocks.end()) earlier.old_of_new[n] = o;
    }
    return earlier;
}

int non_conforming(const BlockDecomposition& b) { return b.pairs - b.conforming_pairs; }

// Whether `tried` has more valid blocks, no more non-conforming pairs, a better score, and keeps
// every block valid in `out` valid: the block of its first tet, and for a cut hexahedron the
// blocks of all its tets (both halves).
bool better_cut(const BlockDecomposition& out, const BlockDecomposition& tried, const CarriedCut& cut) {
    if (tried.valid <= out.valid || non_conforming(tried) > non_conforming(out) || !(score(tried) > score(out)))
        return false;
    for (int o = 0; o < out.count; ++o) {
        if (!out.blocks[o].valid) continue;
        const bool was_cut = std::find(cut.blocks.begin(), cut.blocks.end(), o) != cut.blocks.end();
        for (int t : out.blocks[o].tets) {
            if (!tried.blocks[tried.tet_block[t]].valid) return false;
            if (!was_cut) break;
        }
    }
    return true;
}

std::optional<std::pair<BlockDecomposition, Validated>> cut_block(const TetMesh& mesh, const TetTopology& topo,
                                                                  const std::vector<int>& group, double h,
                                                                  const BlockOptions& options,
                                                                  const BlockDecomposition& out, const Validated& v,
                                                                  const CarriedCut& cut) {
    BlockDecomposition tried = out;
    Eigen::VectorXi labels = out.tet_block;
    std::vector<char> near(size_t(out.count) + cut.blocks.size(), 0);
    for (size_t k = 0; k < cut.blocks.size(); ++k) {
        const int c = cut.blocks[k], half = out.count + int(k);
        near[size_t(c)] = near[size_t(half)] = 1;
        for (int n : out.blocks[c].neighbours) near[size_t(n)] = 1;
        for (int t : out.blocks[c].tets)
            if (cut.side[size_t(t)] == 1) labels[t] = half;
    }
    tried.tet_block = clean_staircase(mesh, topo, labels, near);
    tried.count = compact_labels(tried.tet_block);
    Validated w = collect_boundaries(mesh, topo, group, tried);
    const EarlierBlocks earlier = map_cut(out, v, tried, cut);
    validate_collected(mesh, h, options, tried, w, &earlier);
    count_conformity(w, h, options, tried);
    if (!better_cut(out, tried, cut)) return std::nullopt;
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
    for (const std::vector<int>& side : prism_cut_sides(prism)) {
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
            // The block alone first, unless the cut runs across a face shared with a neighbour
            // (which would see two faces where it has one); then carried on through the
            // neighbours whose faces it splits.
            std::optional<std::pair<BlockDecomposition, Validated>> tried;
            if (!cuts_a_neighbour_across(*prism, side, v.faces[b].label))
                tried = cut_block(mesh, topo, group, h, options, out, v, cut_alone(mesh, topo, out, v, b, tri_side));
            std::optional<CarriedCut> carried;
            if (!tried && (carried = carry_cut(mesh, topo, out, v, b, tri_side, kMaxCutBlocks)) &&
                carried->blocks.size() > 1)
                tried = cut_block(mesh, topo, group, h, options, out, v, *carried);
            if (!tried) continue;
            out = std::move(tried->first), v = std::move(tried->second), ++out.prism_cuts;
            out.carried_cuts += carried.has_value();  // reached only when the carried cut was kept
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
