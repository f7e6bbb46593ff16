#include "framefix/blocks/block_surfaces.h"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

struct SurfaceGraph {
    std::vector<std::vector<int>> sheet_nb;  // per vertex: neighbours over edges inside one sheet
    std::vector<std::vector<int>> line_nb;   // per vertex: neighbours over block-edge edges
    std::vector<char> on_boundary;           // vertex on the part's boundary
    std::map<int, std::vector<PairKey>> block_lines;  // per block: its edges' mesh edges
};

// An edge is on a block edge when the triangles of one block there carry two or more labels
// (`sheet`: per triangle, its block and cleaned label). Judged per block: the two sides of an
// interface may clean a staircase sliver differently.
SurfaceGraph surface_graph(const TetMesh& mesh, const std::vector<Eigen::Vector3i>& tris,
                           const std::vector<std::pair<int, int>>& sheet) {
    const int nv = mesh.num_vertices();
    std::unordered_map<PairKey, std::vector<std::pair<int, int>>> sheets_of;  // edge -> (block, label)
    for (size_t t = 0; t < tris.size(); ++t)
        for (int k = 0; k < 3; ++k) sheets_of[edge_key(tris[t][k], tris[t][(k + 1) % 3], nv)].push_back(sheet[t]);
    SurfaceGraph g{std::vector<std::vector<int>>(nv), std::vector<std::vector<int>>(nv), std::vector<char>(nv, 0), {}};
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b)
        for (int k = 0; k < 3; ++k) g.on_boundary[mesh.boundary_faces(b, k)] = 1;
    for (auto& [key, ids] : sheets_of) {
        std::sort(ids.begin(), ids.end());
        bool line = false;
        for (size_t i = 1; i < ids.size(); ++i)
            if (ids[i].first == ids[i - 1].first && ids[i].second != ids[i - 1].second) {
                line = true;
                auto& lines = g.block_lines[ids[i].first];
                if (lines.empty() || lines.back() != key) lines.push_back(key);
            }
        const auto [a, b] = key_ids(key, nv);
        auto& nb = line ? g.line_nb : g.sheet_nb;
        nb[a].push_back(b), nb[b].push_back(a);
    }
    return g;
}

// Laplacian rounds; returns the moved positions of all mesh vertices.
Points smooth(const TetMesh& mesh, const SurfaceGraph& g, const std::vector<char>& used, int iterations) {
    const int nv = mesh.num_vertices();
    std::vector<char> on_feature(nv, 0);
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e) on_feature[mesh.feature_edges(e, 0)] = on_feature[mesh.feature_edges(e, 1)] = 1;
    std::vector<Eigen::Vector3d> normal(nv, Eigen::Vector3d::Zero());  // outward area normals on the boundary
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b) {
        const Eigen::Vector3d p0 = mesh.points.row(mesh.boundary_faces(b, 0)), p1 = mesh.points.row(mesh.boundary_faces(b, 1)),
                              p2 = mesh.points.row(mesh.boundary_faces(b, 2));
        for (int k = 0; k < 3; ++k) normal[mesh.boundary_faces(b, k)] += (p1 - p0).cross(p2 - p0);
    }
    Points P = mesh.points, next = P;
    for (int it = 0; it < iterations; ++it) {
        for (int v = 0; v < nv; ++v) {
            if (!used[v] || on_feature[v]) continue;
            const std::vector<int>* nb = nullptr;
            if (g.line_nb[v].size() == 2) nb = &g.line_nb[v];                        // on a block edge
            else if (g.line_nb[v].empty() && !g.on_boundary[v]) nb = &g.sheet_nb[v];  // inside an interface
            if (!nb || nb->empty()) continue;                                         // corners stay
            Eigen::Vector3d mean = Eigen::Vector3d::Zero();
            for (int w : *nb) mean += P.row(w).transpose();
            Eigen::Vector3d step = 0.5 * (mean / double(nb->size()) - P.row(v).transpose());
            if (g.on_boundary[v] && normal[v].norm() > 0) step -= step.dot(normal[v].normalized()) * normal[v].normalized();
            next.row(v) = P.row(v) + step.transpose();
        }
        P = next;
    }
    return P;
}

// Polylines of one block's edges, between vertices of degree != 2 (corners), then closed loops.
std::vector<Points> edge_polylines(const std::vector<PairKey>& lines, int nv, const Points& P) {
    std::unordered_map<int, std::vector<int>> nb;
    for (PairKey key : lines) {
        const auto [a, b] = key_ids(key, nv);
        nb[a].push_back(b), nb[b].push_back(a);
    }
    std::unordered_set<PairKey> done;
    std::vector<Points> out;
    auto walk = [&](int start, int first) {
        std::vector<int> chain{start};
        int prev = start, cur = first;
        done.insert(edge_key(start, first, nv));
        while (true) {
            chain.push_back(cur);
            if (nb[cur].size() != 2 || cur == start) break;
            const int nxt = nb[cur][0] == prev ? nb[cur][1] : nb[cur][0];
            if (!done.insert(edge_key(cur, nxt, nv)).second) break;
            prev = cur, cur = nxt;
        }
        Points poly(Eigen::Index(chain.size()), 3);
        for (size_t i = 0; i < chain.size(); ++i) poly.row(Eigen::Index(i)) = P.row(chain[i]);
        out.push_back(std::move(poly));
    };
    std::vector<int> verts;
    for (const auto& [v, w] : nb) verts.push_back(v);
    std::sort(verts.begin(), verts.end());  // deterministic output order
    for (int pass = 0; pass < 2; ++pass)
        for (int v : verts) {
            if (pass == 0 && nb[v].size() == 2) continue;
            for (int w : nb[v])
                if (!done.count(edge_key(v, w, nv))) walk(v, w);
        }
    return out;
}

}  // namespace

BlockSurfaces block_surfaces(const TetMesh& mesh, const std::vector<std::vector<BoundaryTriangle>>& surface,
                             const std::vector<BlockFaces>& faces, int iterations) {
    std::vector<Eigen::Vector3i> tris;
    std::vector<std::pair<int, int>> sheet;
    std::vector<int> block, across;
    std::vector<char> used(mesh.num_vertices(), 0);
    for (int b = 0; b < int(surface.size()); ++b)
        for (size_t i = 0; i < surface[b].size(); ++i) {
            const BoundaryTriangle& s = surface[b][i];
            Eigen::Vector3i tri = s.verts;
            const Eigen::Vector3d p0 = mesh.points.row(tri[0]);
            const Eigen::Vector3d n = (Eigen::Vector3d(mesh.points.row(tri[1])) - p0).cross(Eigen::Vector3d(mesh.points.row(tri[2])) - p0);
            if (n.dot(s.normal) < 0) std::swap(tri[1], tri[2]);
            tris.push_back(tri), block.push_back(b), across.push_back(std::max(s.label, -1));
            sheet.push_back({b, i < faces[b].cleaned.size() ? faces[b].cleaned[i] : s.label});
            for (int k = 0; k < 3; ++k) used[tri[k]] = 1;
        }
    const SurfaceGraph g = surface_graph(mesh, tris, sheet);
    const Points P = smooth(mesh, g, used, iterations);

    BlockSurfaces out;
    std::vector<int> index(mesh.num_vertices(), -1);
    int n = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (used[v]) index[v] = n++;
    out.points.resize(n, 3);
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (used[v]) out.points.row(index[v]) = P.row(v);
    out.triangles.resize(Eigen::Index(tris.size()), 3);
    out.block.resize(Eigen::Index(tris.size()));
    out.neighbour.resize(Eigen::Index(tris.size()));
    for (size_t t = 0; t < tris.size(); ++t) {
        for (int k = 0; k < 3; ++k) out.triangles(Eigen::Index(t), k) = index[tris[t][k]];
        out.block[Eigen::Index(t)] = block[t], out.neighbour[Eigen::Index(t)] = across[t];
    }
    for (const auto& [b, lines] : g.block_lines)
        for (Points& poly : edge_polylines(lines, mesh.num_vertices(), P)) {
            out.edges.push_back(std::move(poly));
            out.edge_block.push_back(b);
        }
    return out;
}

}  // namespace framefix
