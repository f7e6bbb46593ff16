#include "framefix/singularities/chains.h"

#include <utility>

#include "framefix/core/error.h"
#include "framefix/singularities/chain_ends.h"

namespace framefix {
namespace detail {

Eigen::Vector3d face_centroid(const TetMesh& mesh, const TetTopology& topo, int f) {
    return (mesh.points.row(topo.faces(f, 0)) + mesh.points.row(topo.faces(f, 1)) + mesh.points.row(topo.faces(f, 2)))
               .transpose() / 3;
}


ChainContext classify_tets(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& val) {
    const int nt = mesh.num_tets();
    ChainContext c{mesh, topo, val, std::vector<int>(nt, 0), std::vector<int>(nt, -1), 0};
    std::vector<char> node(nt, 0);
    for (int t = 0; t < nt; ++t)
        for (int lf = 0; lf < 4; ++lf) {
            const int v = val[topo.tet_faces(t, lf)];
            c.ns[t] += v != 0;
            node[t] |= v == -1;  // complex faces are node material (docs/algorithms.md#valence-sign-rule)
        }
    for (int t = 0; t < nt; ++t) node[t] |= c.ns[t] >= 3;
    // Junction clusters: node tets sharing a vertex.
    DisjointSet uf(nt);
    const int nv = mesh.num_vertices();
    for (int v = 0; v < nv; ++v) {
        int first = -1;
        for (int k = topo.vert_tets_start[v]; k < topo.vert_tets_start[v + 1]; ++k) {
            const int t = topo.vert_tets[k];
            if (!node[t]) continue;
            if (first < 0) first = t;
            else uf.unite(first, t);
        }
    }
    std::vector<int> id(nt, -1);
    for (int t = 0; t < nt; ++t) {
        if (!node[t]) continue;
        const int r = uf.find(t);
        if (id[r] < 0) id[r] = c.nclusters++;
        c.cluster[t] = id[r];
    }
    return c;
}

bool step(const ChainContext& c, int f, int side, int* next, int* next_side, RawEnd* end) {
    const int t = c.topo.face_tets(f, side);
    end->face = f;
    end->tet = t;
    if (t < 0) {
        end->type = EndType::Boundary;
        return false;
    }
    if (c.cluster[t] >= 0) {
        end->type = EndType::Junction;
        end->group = c.cluster[t];
        return false;
    }
    if (c.ns[t] == 1) {
        end->type = EndType::Dead;
        return false;
    }
    FF_ASSERT(c.ns[t] == 2);
    *next = -1;
    for (int lf = 0; lf < 4; ++lf) {
        const int g = c.topo.tet_faces(t, lf);
        if (g != f && c.val[g] != 0) *next = g;
    }
    FF_ASSERT(*next >= 0);
    *next_side = c.topo.face_tets(*next, 0) == t ? 0 : 1;
    return true;
}

std::vector<RawChain> walk_chains(const ChainContext& c) {
    const int nf = int(c.val.size());
    std::vector<char> visited(nf, 0);
    std::vector<RawChain> chains;
    for (int f0 = 0; f0 < nf; ++f0) {
        if ((c.val[f0] != 3 && c.val[f0] != 5) || visited[f0]) continue;
        // Walk backwards (out through side 0) to the start of the chain, or around a loop.
        int cur = f0, out = 0, g = -1, gside = 0, guard = 0;
        RawEnd start;
        bool closed = false;
        while (step(c, cur, out, &g, &gside, &start)) {
            cur = g;
            out = 1 - gside;
            FF_ASSERT(++guard <= nf);
            if (cur == f0) {
                closed = true;
                break;
            }
        }
        RawChain ch;
        ch.closed = closed;
        ch.ends[0] = start;
        int fwd = closed ? 1 : 1 - out;
        cur = closed ? f0 : cur;
        for (;;) {
            FF_ASSERT(!visited[cur]);
            ch.faces.push_back(cur);
            visited[cur] = 1;
            RawEnd end;
            if (!step(c, cur, fwd, &g, &gside, &end)) {
                FF_ASSERT(!closed);
                ch.ends[1] = end;
                break;
            }
            cur = g;
            fwd = 1 - gside;
            if (closed && cur == f0) break;
        }
        chains.push_back(std::move(ch));
    }
    return chains;
}

}  // namespace detail

ChainGraph trace_chains(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& face_valence,
                        const ChainOptions& options) {
    if (face_valence.size() != size_t(topo.faces.rows()))
        throw Error("singularities", "face labels have " + std::to_string(face_valence.size()) + " entries for " +
                                         std::to_string(topo.faces.rows()) + " topology faces");
    const detail::ChainContext c = detail::classify_tets(mesh, topo, face_valence);
    std::vector<detail::RawChain> chains = detail::walk_chains(c);
    ChainGraph graph;
    graph.h_mean = mean_edge_length(mesh, topo);
    const detail::EndStats stats = detail::resolve_ends(c, options.attach_distance * graph.h_mean, chains);
    graph.dead_ends = stats.dead_ends;
    graph.dead_ends_attached = stats.attached;
    detail::assemble(c, chains, graph);
    graph.joined = detail::join_and_drop_loops(graph, mesh);
    detail::renumber(graph);
    return graph;
}

}  // namespace framefix
