#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "framefix/blocks/partition.h"
#include "framefix/core/disjoint_set.h"

namespace framefix {

namespace {

// Neighbouring tet across each local face, -1 on the boundary.
int across(const TetTopology& topo, int tet, int lf) {
    const int f = topo.tet_faces(tet, lf);
    return topo.face_tets(f, 0) == tet ? topo.face_tets(f, 1) : topo.face_tets(f, 0);
}

// Labels of vertex components; components smaller than min_size take the most frequent label of
// their neighbours in big components (repeated, so chains of small components are absorbed).
std::vector<int> vertex_labels(const TetMesh& mesh, const TetTopology& topo, const std::vector<char>& cut,
                               int min_size) {
    const int nv = mesh.num_vertices(), ne = int(topo.edges.rows());
    DisjointSet uf(nv);  // merge_into: vertex labels are roots and break vote ties
    for (int e = 0; e < ne; ++e)
        if (!cut[e]) uf.merge_into(topo.edges(e, 0), topo.edges(e, 1));
    std::vector<int> label(nv), size(nv, 0);
    for (int v = 0; v < nv; ++v) label[v] = uf.find(v), size[label[v]] += 1;
    std::vector<std::vector<int>> adj(nv);
    for (int e = 0; e < ne; ++e) adj[topo.edges(e, 0)].push_back(topo.edges(e, 1)), adj[topo.edges(e, 1)].push_back(topo.edges(e, 0));
    for (int pass = 0; pass < 20; ++pass) {
        std::vector<int> next = label;
        bool changed = false;
        for (int v = 0; v < nv; ++v) {
            if (size[label[v]] >= min_size) continue;
            std::unordered_map<int, int> votes;
            for (int w : adj[v])
                if (size[label[w]] >= min_size) votes[label[w]] += 1;
            int best = -1, most = 0;
            for (auto [l, c] : votes)
                if (c > most || (c == most && l < best)) most = c, best = l;
            if (best >= 0) next[v] = best, changed = true;
        }
        label.swap(next);
        if (!changed) break;
    }
    return label;
}

}  // namespace

int compact_labels(Eigen::VectorXi& labels) {
    std::unordered_map<int, int> id;
    for (int i = 0; i < int(labels.size()); ++i) {
        auto [it, fresh] = id.try_emplace(labels[i], int(id.size()));
        labels[i] = it->second;
    }
    return int(id.size());
}

int small_piece_tets(int num_tets, const BlockOptions& options) {
    return std::max(10, int(options.min_piece_fraction * num_tets));
}

int merge_small_pieces(const TetTopology& topo, Eigen::VectorXi& lab, int threshold) {
    const int nt = int(lab.size());
    int merged = 0;
    // Face-connected pieces of each label.
    DisjointSet uf(nt);
    for (int f = 0; f < int(topo.face_tets.rows()); ++f) {
        const int a = topo.face_tets(f, 0), b = topo.face_tets(f, 1);
        if (a >= 0 && b >= 0 && lab[a] == lab[b]) uf.merge_into(a, b);
    }
    for (int t = 0; t < nt; ++t) lab[t] = uf.find(t);
    compact_labels(lab);
    // Small pieces merge into the neighbour with the most shared faces; only into a larger piece
    // (or an equal one with a larger id), so that no two pieces swap.
    for (int it = 0; it < 50; ++it) {
        const int n = lab.maxCoeff() + 1;
        std::vector<int> sz(n, 0);
        for (int t = 0; t < nt; ++t) sz[lab[t]] += 1;
        std::vector<std::unordered_map<int, int>> contact(n);
        for (int f = 0; f < int(topo.face_tets.rows()); ++f) {
            const int a = topo.face_tets(f, 0), b = topo.face_tets(f, 1);
            if (a < 0 || b < 0 || lab[a] == lab[b]) continue;
            const int la = lab[a], lb = lab[b];
            auto bigger = [&](int x, int y) { return sz[y] > sz[x] || (sz[y] == sz[x] && y > x); };
            if (sz[la] < threshold && bigger(la, lb)) contact[la][lb] += 1;
            if (sz[lb] < threshold && bigger(lb, la)) contact[lb][la] += 1;
        }
        std::vector<int> map(n);
        std::iota(map.begin(), map.end(), 0);
        bool any = false;
        for (int l = 0; l < n; ++l) {
            int best = -1, most = 0;
            for (auto [m, c] : contact[l])
                if (c > most || (c == most && m < best)) most = c, best = m;
            if (best >= 0) map[l] = best, any = true;
        }
        if (!any) break;
        for (int l = 0; l < n; ++l) merged += map[l] != l;
        for (int l = 0; l < n; ++l)  // chains end: every step goes to a strictly "bigger" piece
            while (map[map[l]] != map[l]) map[l] = map[map[l]];
        for (int t = 0; t < nt; ++t) lab[t] = map[lab[t]];
        compact_labels(lab);
    }
    return merged;
}

Eigen::VectorXi partition_tets(const TetMesh& mesh, const TetTopology& topo, const std::vector<char>& cut,
                               const BlockOptions& options) {
    const int nt = mesh.num_tets();
    const std::vector<int> vl = vertex_labels(mesh, topo, cut, options.min_component_vertices);
    std::vector<int> size(mesh.num_vertices(), 0);
    for (int l : vl) size[l] += 1;
    // Tets: majority of their vertices' labels, ties to the larger component.
    Eigen::VectorXi lab(nt);
    for (int t = 0; t < nt; ++t) {
        long long best = -1;
        for (int i = 0; i < 4; ++i) {
            const int l = vl[mesh.tets(t, i)];
            int same = 0;
            for (int j = 0; j < 4; ++j) same += vl[mesh.tets(t, j)] == l;
            const long long score = (long long)same * 1000000000LL + size[l];
            if (score > best) best = score, lab[t] = l;
        }
    }
    merge_small_pieces(topo, lab, small_piece_tets(nt, options));
    // Spikes of the staircase: a tet with >= 3 face neighbours in one other block joins it.
    for (int pass = 0; pass < 10; ++pass) {
        int changed = 0;
        for (int t = 0; t < nt; ++t) {
            int nb[4];
            for (int k = 0; k < 4; ++k) {
                const int o = across(topo, t, k);
                nb[k] = o >= 0 ? lab[o] : -1;
            }
            for (int k = 0; k < 4; ++k) {
                if (nb[k] < 0 || nb[k] == lab[t]) continue;
                int same = 0;
                for (int j = 0; j < 4; ++j) same += nb[j] == nb[k];
                if (same >= 3) { lab[t] = nb[k], ++changed; break; }
            }
        }
        if (!changed) break;
    }
    compact_labels(lab);
    return lab;
}

}  // namespace framefix
