#include "framefix/streamlines/feature_seeds.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

Eigen::Vector3d axis(const FrameField& field, int vert, int k) { return field.axes.row(vert).segment<3>(3 * k).transpose(); }

Eigen::Vector3d unit_or_zero(const Eigen::Vector3d& v) {
    const double n = v.norm();
    return n > 1e-30 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::Zero();
}

// The frame axis at v closest to `want` (up to sign), turned to agree with it.
Eigen::Vector3d closest_axis(const FrameField& field, int v, const Eigen::Vector3d& want) {
    int best = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(axis(field, v, k).dot(want)) > std::abs(axis(field, v, best).dot(want))) best = k;
    const Eigen::Vector3d a = axis(field, v, best);
    return a.dot(want) < 0 ? Eigen::Vector3d(-a) : a;
}

// Outward area normals per (boundary vertex, B-rep face), and the faces of each boundary edge,
// and per (vertex, face) the sum of the triangle centroids (where the face lies around v).
struct FaceNormals {
    std::unordered_map<PairKey, Eigen::Vector3d> normal;   // pair_key(vertex, face tag)
    std::unordered_map<PairKey, Eigen::Vector3d> side;     // pair_key(vertex, face tag): sum of (centroid - v)
    std::unordered_map<PairKey, std::vector<int>> edge_faces;  // edge_key(a, b): face tags
};

FaceNormals face_normals(const TetMesh& mesh) {
    FaceNormals f;
    const int nv = mesh.num_vertices();
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b) {
        const Eigen::Vector3i t = mesh.boundary_faces.row(b).transpose();
        const Eigen::Vector3d p0 = mesh.points.row(t[0]), p1 = mesh.points.row(t[1]), p2 = mesh.points.row(t[2]);
        const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0), c = (p0 + p1 + p2) / 3;
        const int tag = mesh.face_tags[b];
        for (int k = 0; k < 3; ++k) {
            const PairKey key = pair_key(t[k], tag, kAnyIdStride);
            const Eigen::Vector3d side = c - mesh.points.row(t[k]).transpose();
            // Eigen vectors are not zeroed by default: insert the first value, then add.
            if (auto [it, fresh] = f.normal.try_emplace(key, n); !fresh) it->second += n;
            if (auto [it, fresh] = f.side.try_emplace(key, side); !fresh) it->second += side;
            f.edge_faces[edge_key(t[k], t[(k + 1) % 3], nv)].push_back(tag);
        }
    }
    return f;
}

// The curve's vertices in order (open: from a degree-1 end).
std::vector<int> chain_of(const TetMesh& mesh, const std::vector<int>& edges) {
    std::unordered_map<int, std::vector<int>> adj;
    for (int e : edges) {
        const int a = mesh.feature_edges(e, 0), b = mesh.feature_edges(e, 1);
        adj[a].push_back(b), adj[b].push_back(a);
    }
    int start = adj.begin()->first;
    for (const auto& [v, nb] : adj)
        if (nb.size() == 1) { start = v; break; }
    std::vector<int> chain{start};
    for (int prev = -1, cur = start;;) {
        int next = -1;
        for (int w : adj[cur])
            if (w != prev && (chain.size() < 2 || w != chain.front())) { next = w; break; }
        if (next < 0 || std::find(chain.begin(), chain.end(), next) != chain.end()) break;
        chain.push_back(next), prev = cur, cur = next;
    }
    return chain;
}

// Directions at vertex v of a valence-k curve between faces f0 and f1: the inward continuations
// of the faces (the axes closest to -n0, -n1; one for k = 2, where n0 ~ n1), and for a slit (k = 4)
// the axis across the curve pointing away from both faces.
std::vector<Eigen::Vector3d> inward_directions(const FaceNormals& fn, const FrameField& field, int v, int k, int f0,
                                               int f1, const Eigen::Vector3d& tangent) {
    std::vector<Eigen::Vector3d> out;
    const auto n0 = fn.normal.find(pair_key(v, f0, kAnyIdStride)), n1 = fn.normal.find(pair_key(v, f1, kAnyIdStride));
    const bool has0 = n0 != fn.normal.end() && n0->second.norm() > 0, has1 = n1 != fn.normal.end() && n1->second.norm() > 0;
    const Eigen::Vector3d a = has0 ? n0->second.normalized() : Eigen::Vector3d::Zero();
    const Eigen::Vector3d b = has1 ? n1->second.normalized() : Eigen::Vector3d::Zero();
    if (k == 2) return has0 || has1 ? std::vector<Eigen::Vector3d>{closest_axis(field, v, -(a + b))} : out;
    if (has0) out.push_back(closest_axis(field, v, -a));
    if (has1) out.push_back(closest_axis(field, v, -b));
    if (k == 4 && has0 && has1) {
        const Eigen::Vector3d faces = fn.side.at(pair_key(v, f0, kAnyIdStride)) + fn.side.at(pair_key(v, f1, kAnyIdStride));
        const Eigen::Vector3d across = unit_or_zero(tangent.cross(a));
        if (across.norm() > 0) out.push_back(closest_axis(field, v, across.dot(faces) > 0 ? Eigen::Vector3d(-across) : across));
    }
    return out;
}

}  // namespace

std::vector<FeatureSeeds> feature_seeds(const TetMesh& mesh, const FeatureSet& features, const FrameField& field,
                                        const std::vector<int>& edges) {
    const FaceNormals fn = face_normals(mesh);
    const int nv = mesh.num_vertices();
    std::map<int, std::vector<int>> by_edge;  // B-rep edge -> its mesh feature edges
    for (int e = 0; e < int(mesh.feature_edges.rows()); ++e) {
        const int tag = mesh.edge_tags[e], k = features.valence_of(tag);
        if (k >= 2 && k <= 4 && std::find(edges.begin(), edges.end(), tag) != edges.end()) by_edge[tag].push_back(e);
    }
    std::vector<FeatureSeeds> out;
    for (const auto& [tag, list] : by_edge) {
        std::map<int, int> face_count;
        for (int e : list)
            for (int t : fn.edge_faces.at(edge_key(mesh.feature_edges(e, 0), mesh.feature_edges(e, 1), nv))) face_count[t] += 1;
        std::vector<std::pair<int, int>> by_count;
        for (auto [t, c] : face_count) by_count.push_back({c, t});
        std::sort(by_count.rbegin(), by_count.rend());
        if (by_count.size() < 2) continue;
        FeatureSeeds curve{tag, features.valence_of(tag), {}};
        const std::vector<int> chain = chain_of(mesh, list);
        const int m = int(chain.size());
        for (int i = 0; i < m; ++i) {
            FeatureSeed s;
            s.vertex = chain[i];
            s.point = mesh.points.row(s.vertex).transpose();
            s.tangent = unit_or_zero((mesh.points.row(chain[std::min(i + 1, m - 1)]) - mesh.points.row(chain[std::max(i - 1, 0)])).transpose());
            s.directions = inward_directions(fn, field, s.vertex, curve.valence, by_count[0].second, by_count[1].second, s.tangent);
            curve.seeds.push_back(std::move(s));
        }
        out.push_back(std::move(curve));
    }
    return out;
}

}  // namespace framefix
