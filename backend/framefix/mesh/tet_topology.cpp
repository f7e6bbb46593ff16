#include "framefix/mesh/tet_topology.h"

#include <algorithm>
#include <array>

#include "framefix/core/error.h"

namespace framefix {
namespace {

using Key3 = std::array<int, 4>;  // sorted vertices + (tet * 4 + lf)

}  // namespace

TetTopology build_topology(const TetMesh& mesh) {
    TetTopology topo;
    const int nt = mesh.num_tets(), nv = mesh.num_vertices();

    // Faces: sort (v0, v1, v2, owner) records; equal keys are the two sides of one face.
    std::vector<Key3> recs(size_t(nt) * 4);
    for (int t = 0; t < nt; ++t)
        for (int lf = 0; lf < 4; ++lf) {
            std::array<int, 3> v = {mesh.tets(t, kTetFace[lf][0]), mesh.tets(t, kTetFace[lf][1]),
                                    mesh.tets(t, kTetFace[lf][2])};
            std::sort(v.begin(), v.end());
            recs[size_t(t) * 4 + lf] = {v[0], v[1], v[2], t * 4 + lf};
        }
    std::sort(recs.begin(), recs.end());
    std::vector<std::array<int, 5>> faces;  // v0 v1 v2 tetA tetB
    topo.tet_faces.resize(nt, 4);
    for (size_t i = 0; i < recs.size();) {
        size_t j = i + 1;
        while (j < recs.size() && recs[j][0] == recs[i][0] && recs[j][1] == recs[i][1] &&
               recs[j][2] == recs[i][2])
            ++j;
        if (j - i > 2) throw Error("topology", "a triangle is shared by more than two tets; the mesh is not a manifold solid");
        const int f = int(faces.size());
        faces.push_back({recs[i][0], recs[i][1], recs[i][2], recs[i][3] / 4, j - i == 2 ? recs[i + 1][3] / 4 : -1});
        for (size_t k = i; k < j; ++k) topo.tet_faces(recs[k][3] / 4, recs[k][3] % 4) = f;
        i = j;
    }
    topo.faces.resize(int(faces.size()), 3);
    topo.face_tets.resize(int(faces.size()), 2);
    topo.on_boundary.assign(nv, 0);
    for (int f = 0; f < int(faces.size()); ++f) {
        for (int k = 0; k < 3; ++k) topo.faces(f, k) = faces[f][k];
        topo.face_tets(f, 0) = faces[f][3];
        topo.face_tets(f, 1) = faces[f][4];
        if (faces[f][4] < 0)
            for (int k = 0; k < 3; ++k) topo.on_boundary[faces[f][k]] = 1;
    }

    // Edges: six per tet, deduplicated.
    std::vector<std::array<int, 2>> edges;
    edges.reserve(size_t(nt) * 6);
    for (int t = 0; t < nt; ++t)
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) {
                int u = mesh.tets(t, a), v = mesh.tets(t, b);
                edges.push_back({std::min(u, v), std::max(u, v)});
            }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    topo.edges.resize(int(edges.size()), 2);
    for (int e = 0; e < int(edges.size()); ++e) topo.edges.row(e) << edges[e][0], edges[e][1];

    // Vertex -> tets (CSR).
    topo.vert_tets_start.assign(nv + 1, 0);
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 4; ++k) topo.vert_tets_start[mesh.tets(t, k) + 1] += 1;
    for (int v = 0; v < nv; ++v) topo.vert_tets_start[v + 1] += topo.vert_tets_start[v];
    topo.vert_tets.resize(size_t(nt) * 4);
    std::vector<int> fill(topo.vert_tets_start.begin(), topo.vert_tets_start.end() - 1);
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 4; ++k) topo.vert_tets[fill[mesh.tets(t, k)]++] = t;
    return topo;
}

double mean_edge_length(const TetMesh& mesh, const TetTopology& topo, double if_no_edges) {
    const int ne = int(topo.edges.rows());
    if (ne == 0) return if_no_edges;
    double sum = 0;  // in edge order: callers rely on bit-identical results
    for (int e = 0; e < ne; ++e) sum += (mesh.points.row(topo.edges(e, 0)) - mesh.points.row(topo.edges(e, 1))).norm();
    return sum / double(ne);
}

}  // namespace framefix
