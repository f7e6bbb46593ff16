// Rule 7 of section 0: the vertex partition leaves staircase boundaries where a block touches
// itself along a mesh edge (two separate fans of boundary faces) or at a vertex (a pinched link).
// Both are removed by moving the minority side of the edge ring / vertex star.
#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "framefix/blocks/partition.h"

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

long long key2(long long a, long long b, long long n) { return a * n + b; }

// One pass over block-boundary faces: (edge, block) with >= 4 boundary faces of that block.
int fix_edges(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi& lab) {
    const long long nv = mesh.num_vertices();
    const long long nb = lab.maxCoeff() + 2;
    std::unordered_map<long long, int> count;  // key (edge key, block)
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        const int t0 = topo.face_tets(f, 0), t1 = topo.face_tets(f, 1);
        const int l0 = t0 >= 0 ? lab[t0] : -1, l1 = t1 >= 0 ? lab[t1] : -1;
        if (l0 == l1) continue;
        for (int k = 0; k < 3; ++k) {
            const int a = topo.faces(f, k), c = topo.faces(f, (k + 1) % 3);
            const long long e = key2(std::min(a, c), std::max(a, c), nv);
            for (int l : {l0, l1}) if (l >= 0) count[key2(e, l, nb)] += 1;
        }
    }
    std::vector<long long> bad;
    for (auto [k, c] : count) if (c >= 4) bad.push_back(k);
    std::sort(bad.begin(), bad.end());  // deterministic order
    int moved = 0;
    for (long long k : bad) {
        const long long e = k / nb;
        const int b = int(k % nb), a = int(e / nv), c = int(e % nv);
        std::vector<int> ring;
        for (int t : star(topo, a))
            for (int i = 0; i < 4; ++i) if (mesh.tets(t, i) == c) { ring.push_back(t); break; }
        moved += move_minority(ring, b, lab);
    }
    return moved;
}

// One pass: (vertex, block) whose link in the block's boundary triangles has >= 2 components.
int fix_vertices(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi& lab) {
    const long long nb = lab.maxCoeff() + 2;
    std::unordered_map<long long, std::vector<std::pair<int, int>>> link;  // (vertex, block) -> link edges
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        const int t0 = topo.face_tets(f, 0), t1 = topo.face_tets(f, 1);
        const int l0 = t0 >= 0 ? lab[t0] : -1, l1 = t1 >= 0 ? lab[t1] : -1;
        if (l0 == l1) continue;
        for (int l : {l0, l1}) {
            if (l < 0) continue;
            for (int k = 0; k < 3; ++k)
                link[key2(topo.faces(f, k), l, nb)].push_back({topo.faces(f, (k + 1) % 3), topo.faces(f, (k + 2) % 3)});
        }
    }
    std::vector<long long> bad;
    for (auto& [k, edges] : link) {
        // Components of the link graph, by repeated flooding (links are small).
        std::unordered_map<int, int> comp;
        std::unordered_map<int, std::vector<int>> adj;
        for (auto [a, c] : edges) adj[a].push_back(c), adj[c].push_back(a);
        int n = 0;
        for (auto& [v, _] : adj) {
            if (comp.count(v)) continue;
            ++n;
            std::vector<int> stack{v};
            comp[v] = n;
            while (!stack.empty()) {
                const int x = stack.back();
                stack.pop_back();
                for (int y : adj[x]) if (!comp.count(y)) comp[y] = n, stack.push_back(y);
            }
        }
        if (n >= 2) bad.push_back(k);
    }
    std::sort(bad.begin(), bad.end());
    int moved = 0;
    for (long long k : bad) moved += move_minority(star(topo, int(k / nb)), int(k % nb), lab);
    return moved;
}

}  // namespace

Eigen::VectorXi clean_staircase(const TetMesh& mesh, const TetTopology& topo, Eigen::VectorXi lab) {
    for (int pass = 0; pass < 10 && fix_edges(mesh, topo, lab) > 0; ++pass) compact_labels(lab);
    for (int pass = 0; pass < 6 && fix_vertices(mesh, topo, lab) > 0; ++pass) compact_labels(lab);
    for (int pass = 0; pass < 10 && fix_edges(mesh, topo, lab) > 0; ++pass) compact_labels(lab);
    compact_labels(lab);
    return lab;
}

}  // namespace framefix
