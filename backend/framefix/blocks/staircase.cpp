// docs/algorithms.md#staircase-cleaning: the vertex partition leaves staircase boundaries where a block touches
// itself along a mesh edge (two separate fans of boundary faces) or at a vertex (a pinched link).
// Both are removed by moving the minority side of the edge ring / vertex star.
#include <algorithm>
#include <unordered_map>

#include "framefix/blocks/partition.h"
#include "framefix/core/disjoint_set.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

std::vector<int> star(const TetTopology& topo, int vert) {
    return {topo.vert_tets.begin() + topo.vert_tets_start[vert], topo.vert_tets.begin() + topo.vert_tets_start[vert + 1]};
}

// Tets of `ring` labelled b go to the most common other label if b owns at most half of the ring;
// otherwise the others join b.
bool move_minority(const std::vector<int>& ring, int b, Eigen::VectorXi& lab) {
    int inside = 0;
    std::unordered_map<int, int> other;
    for (int t : ring) {
        if (lab[t] == b) ++inside;
        else other[lab[t]] += 1;
    }
    if (2 * inside <= int(ring.size())) {
        int best = -1, most = 0;
        for (auto [l, c] : other) if (c > most || (c == most && l < best)) most = c, best = l;
        if (best < 0) return false;
        for (int t : ring) if (lab[t] == b) lab[t] = best;
    } else {
        for (int t : ring) lab[t] = b;
    }
    return true;
}

// Block-boundary faces as (face, block on this side): both sides of faces between two blocks,
// the inner side of domain-boundary faces; only the sides of the blocks `only` flags, when given.
template <class F>
void for_each_block_face(const TetTopology& topo, const Eigen::VectorXi& lab, const std::vector<char>& only, F&& f) {
    auto wanted = [&](int l) { return l >= 0 && (only.empty() || (l < int(only.size()) && only[l])); };
    for (int face = 0; face < int(topo.faces.rows()); ++face) {
        const int t0 = topo.face_tets(face, 0), t1 = topo.face_tets(face, 1);
        const int l0 = t0 >= 0 ? lab[t0] : -1, l1 = t1 >= 0 ? lab[t1] : -1;
        if (l0 == l1) continue;
        if (wanted(l0)) f(face, l0);
        if (wanted(l1)) f(face, l1);
    }
}

// One pass: (edge, block) pairs with >= 4 boundary faces of that block (two fans of the block
// touching along the edge). Sorting keys is several times faster than hashing them.
int fix_edges(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi& lab, const std::vector<char>& only) {
    const std::uint64_t nv = mesh.num_vertices();
    std::vector<std::pair<PairKey, int>> entries;  // (edge key, block), sorted: (edge, block) order
    for_each_block_face(topo, lab, only, [&](int f, int b) {
        for (int k = 0; k < 3; ++k) {
            entries.push_back({edge_key(topo.faces(f, k), topo.faces(f, (k + 1) % 3), nv), b});
        }
    });
    std::sort(entries.begin(), entries.end());
    int moved = 0;
    for (size_t i = 0; i < entries.size();) {
        size_t j = i;
        while (j < entries.size() && entries[j] == entries[i]) ++j;
        if (j - i >= 4) {
            const auto [a, c] = key_ids(entries[i].first, nv);
            std::vector<int> ring;
            for (int t : star(topo, a))
                for (int k = 0; k < 4; ++k) if (mesh.tets(t, k) == c) { ring.push_back(t); break; }
            moved += move_minority(ring, entries[i].second, lab);
        }
        i = j;
    }
    return moved;
}

// One pass: (vertex, block) whose link in the block's boundary triangles has >= 2 components.
int fix_vertices(const TetTopology& topo, Eigen::VectorXi& lab, const std::vector<char>& only) {
    struct Link { PairKey vert_block; int a, c; bool operator<(const Link& o) const { return vert_block < o.vert_block; } };
    const std::uint64_t nb = lab.maxCoeff() + 1;
    std::vector<Link> links;
    for_each_block_face(topo, lab, only, [&](int f, int b) {
        for (int k = 0; k < 3; ++k)
            links.push_back({pair_key(topo.faces(f, k), b, nb), topo.faces(f, (k + 1) % 3), topo.faces(f, (k + 2) % 3)});
    });
    std::sort(links.begin(), links.end());
    std::vector<PairKey> bad;
    std::vector<int> verts;
    DisjointSet link;
    for (size_t i = 0; i < links.size();) {
        size_t j = i;
        while (j < links.size() && links[j].vert_block == links[i].vert_block) ++j;
        verts.clear();
        for (size_t k = i; k < j; ++k) verts.push_back(links[k].a), verts.push_back(links[k].c);
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        link.reset(int(verts.size()));
        auto local = [&](int v) { return int(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin()); };
        int components = int(verts.size());
        for (size_t k = i; k < j; ++k) components -= link.merge_into(local(links[k].a), local(links[k].c));
        if (components >= 2) bad.push_back(links[i].vert_block);
        i = j;
    }
    int moved = 0;
    for (PairKey k : bad) {
        const auto [vert, block] = key_ids(k, nb);
        moved += move_minority(star(topo, vert), block, lab);
    }
    return moved;
}

}  // namespace

Eigen::VectorXi clean_staircase(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi lab,
                                const std::vector<char>& only) {
    // Fixing an edge can pinch a vertex and the other way round: alternate until both are clean.
    // With `only`, the labels keep their ids until the end, so that `only` names the same blocks.
    auto compact = [&] { if (only.empty()) compact_labels(lab); };
    for (int round = 0; round < 4; ++round) {
        int moved = 0;
        for (int pass = 0, m = 1; pass < 10 && m > 0; ++pass) moved += m = fix_edges(mesh, topo, lab, only), compact();
        for (int pass = 0, m = 1; pass < 6 && m > 0; ++pass) moved += m = fix_vertices(topo, lab, only), compact();
        if (moved == 0) break;
    }
    compact_labels(lab);
    return lab;
}

}  // namespace framefix
