// Boundary edge graph, feature flags, vertex normals and Dijkstra paths.
#include "framefix/corrections/boundary_graph.h"

#include <algorithm>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "framefix/core/error.h"

namespace framefix {

namespace {

void mark_features(const TetMesh& mesh, const FeatureSet& features, BoundaryGraph& g) {
    const int n_edges = int(mesh.feature_edges.rows());
    const bool tagged = mesh.edge_tags.size() == n_edges;
    for (int e = 0; e < n_edges; ++e) {
        // An imported mesh may carry crease edges without a FeatureSet entry: they are features.
        const bool is_feature = !tagged || features.edges.empty() || features.valence_of(mesh.edge_tags(e)) > 0;
        if (!is_feature) continue;
        for (int k = 0; k < 2; ++k) g.is_feature[mesh.feature_edges(e, k)] = 1;
    }
}

void build_adjacency(const TetMesh& mesh, BoundaryGraph& g) {
    const int nv = mesh.num_vertices();
    std::vector<std::pair<int, int>> edges;
    edges.reserve(3 * mesh.boundary_faces.rows());
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.boundary_faces(f, k), b = mesh.boundary_faces(f, (k + 1) % 3);
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    std::vector<int> degree(nv, 0);
    for (const auto& [a, b] : edges) ++degree[a], ++degree[b];
    g.adjacency_start.assign(nv + 1, 0);
    for (int v = 0; v < nv; ++v) g.adjacency_start[v + 1] = g.adjacency_start[v] + degree[v];
    g.adjacency.resize(g.adjacency_start[nv]);
    g.adjacency_length.resize(g.adjacency_start[nv]);
    std::vector<int> fill(g.adjacency_start.begin(), g.adjacency_start.end() - 1);
    double total = 0;
    for (const auto& [a, b] : edges) {
        const double len = (mesh.points.row(a) - mesh.points.row(b)).norm();
        total += len;
        g.adjacency[fill[a]] = b, g.adjacency_length[fill[a]++] = len;
        g.adjacency[fill[b]] = a, g.adjacency_length[fill[b]++] = len;
    }
    g.hb = edges.empty() ? 0 : total / double(edges.size());
}

void compute_normals(const TetMesh& mesh, BoundaryGraph& g) {
    g.normal = Points::Zero(mesh.num_vertices(), 3);
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d p0 = mesh.points.row(mesh.boundary_faces(f, 0));
        const Eigen::Vector3d p1 = mesh.points.row(mesh.boundary_faces(f, 1));
        const Eigen::Vector3d p2 = mesh.points.row(mesh.boundary_faces(f, 2));
        const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);  // twice the area, outward
        for (int k = 0; k < 3; ++k) g.normal.row(mesh.boundary_faces(f, k)) += n.transpose();
    }
    for (int v = 0; v < g.normal.rows(); ++v) {
        const double len = g.normal.row(v).norm();
        if (len > 0) g.normal.row(v) /= len;
    }
}

// Dijkstra from `from`; with avoid_blocked, blocked vertices are entered only as `to`.
std::vector<int> dijkstra(const BoundaryGraph& g, int from, int to, bool avoid_blocked, double& length) {
    const int nv = g.num_vertices();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> dist(nv, inf);
    std::vector<int> pred(nv, -1);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    dist[from] = 0;
    heap.emplace(0.0, from);
    while (!heap.empty()) {
        const auto [d, v] = heap.top();
        heap.pop();
        if (d > dist[v]) continue;
        if (v == to) break;
        for (int i = g.adjacency_start[v]; i < g.adjacency_start[v + 1]; ++i) {
            const int w = g.adjacency[i];
            // Only `from` can be a blocked v here: skipping blocked-blocked edges keeps the path
            // off feature edges even between two adjacent feature targets.
            if (avoid_blocked && g.is_blocked[w] && (w != to || g.is_blocked[v])) continue;
            const double dw = d + g.adjacency_length[i];
            if (dw < dist[w]) dist[w] = dw, pred[w] = v, heap.emplace(dw, w);
        }
    }
    length = dist[to];
    if (dist[to] == inf) return {};
    std::vector<int> path{to};
    while (path.back() != from) path.push_back(pred[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
}

}  // namespace

BoundaryGraph build_boundary_graph(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                   const Constraints& constraints) {
    const int nv = mesh.num_vertices();
    if (int(constraints.kind.size()) != nv)
        throw Error("snap", "constraints have " + std::to_string(constraints.kind.size()) + " vertices, mesh has " +
                                std::to_string(nv) + "; pass the constraints the field was solved with");
    BoundaryGraph g;
    g.is_boundary.assign(nv, 0);
    g.is_feature.assign(nv, 0);
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) g.is_boundary[mesh.boundary_faces(f, k)] = 1;
    mark_features(mesh, features, g);
    g.is_blocked = g.is_feature;
    for (int v = 0; v < nv; ++v)
        if (g.is_boundary[v] && constraints.kind[v] == ConstraintKind::Fixed) g.is_blocked[v] = 1;
    for (int v = 0; v < nv; ++v) {
        if (g.is_boundary[v]) g.boundary_vertices.push_back(v);
        if (g.is_feature[v]) g.feature_vertices.push_back(v);
    }
    build_adjacency(mesh, g);
    compute_normals(mesh, g);

    g.h_mean = mean_edge_length(mesh, topo, g.hb);
    return g;
}

BoundaryPath shortest_boundary_path(const BoundaryGraph& g, int from, int to) {
    FF_ASSERT(from >= 0 && from < g.num_vertices() && to >= 0 && to < g.num_vertices());
    BoundaryPath path;
    if (from == to) {
        path.vertices = {from};
        return path;
    }
    path.vertices = dijkstra(g, from, to, true, path.length);
    if (path.vertices.empty()) {
        // E.g. the two targets lie on faces separated by feature curves: crossing one is the
        // only way, and it is accepted (crosses_features).
        path.vertices = dijkstra(g, from, to, false, path.length);
        path.crosses_features = true;
    }
    if (path.vertices.empty())
        throw Error("snap", "boundary vertices " + std::to_string(from) + " and " + std::to_string(to) +
                                " are on disconnected boundary components; cannot snap a curve between them");
    return path;
}

int nearest_vertex(const Points& points, const std::vector<int>& candidates, const Eigen::Vector3d& p) {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int v : candidates) {
        const double d2 = (points.row(v).transpose() - p).squaredNorm();
        if (d2 < best_d2) best_d2 = d2, best = v;
    }
    return best;
}

}  // namespace framefix
