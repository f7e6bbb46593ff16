#include "framefix/mesh/crease_features.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "framefix/core/disjoint_set.h"
#include "framefix/core/error.h"

namespace framefix {
namespace {

using Vec3 = Eigen::Vector3d;

struct BoundaryEdge {
    int a, b;      // sorted vertices
    int f0, f1;    // the two boundary triangles
    bool crease = false;
    double theta = 180;  // dihedral angle inside the solid, degrees
};

}  // namespace

CreaseFeatures detect_crease_features(TetMesh mesh, const CreaseOptions& o) {
    const int nb = int(mesh.boundary_faces.rows()), nv = mesh.num_vertices();
    if (nb == 0) throw Error("features", "the mesh has no boundary triangles");
    std::vector<Vec3> normal(nb);
    for (int f = 0; f < nb; ++f) {
        const Vec3 p0 = mesh.points.row(mesh.boundary_faces(f, 0));
        normal[f] = (Vec3(mesh.points.row(mesh.boundary_faces(f, 1))) - p0)
                        .cross(Vec3(mesh.points.row(mesh.boundary_faces(f, 2))) - p0)
                        .normalized();
    }
    // Boundary edges: (a, b, triangle) records sorted; a closed manifold surface pairs them.
    std::vector<std::array<int, 3>> rec;
    rec.reserve(size_t(nb) * 3);
    for (int f = 0; f < nb; ++f)
        for (int k = 0; k < 3; ++k) {
            const int u = mesh.boundary_faces(f, k), v = mesh.boundary_faces(f, (k + 1) % 3);
            rec.push_back({std::min(u, v), std::max(u, v), f});
        }
    std::sort(rec.begin(), rec.end());
    std::vector<BoundaryEdge> edges;
    const double cos_threshold = std::cos(o.angle_deg * M_PI / 180.0);
    for (size_t i = 0; i < rec.size(); i += 2) {
        if (i + 1 >= rec.size() || rec[i + 1][0] != rec[i][0] || rec[i + 1][1] != rec[i][1] ||
            (i + 2 < rec.size() && rec[i + 2][0] == rec[i][0] && rec[i + 2][1] == rec[i][1]))
            throw Error("features", "boundary edge (" + std::to_string(rec[i][0]) + ", " + std::to_string(rec[i][1]) +
                                        ") is not shared by exactly two boundary triangles; the surface is not a closed manifold");
        BoundaryEdge e{rec[i][0], rec[i][1], rec[i][2], rec[i + 1][2]};
        const double c = std::clamp(normal[e.f0].dot(normal[e.f1]), -1.0, 1.0);
        e.crease = c < cos_threshold;
        // Convex iff the far vertex of f1 lies below the plane of f0.
        int far = 0;
        for (int k = 0; k < 3; ++k)
            if (mesh.boundary_faces(e.f1, k) != e.a && mesh.boundary_faces(e.f1, k) != e.b) far = mesh.boundary_faces(e.f1, k);
        const double side = normal[e.f0].dot(Vec3(mesh.points.row(far)) - Vec3(mesh.points.row(e.a)));
        const double alpha = std::acos(c) * 180.0 / M_PI;
        e.theta = side <= 0 ? 180.0 - alpha : 180.0 + alpha;
        edges.push_back(e);
    }

    // Faces: union of triangles across non-crease edges, numbered by their smallest triangle.
    DisjointSet sets(nb);
    for (const BoundaryEdge& e : edges)
        if (!e.crease) sets.unite(e.f0, e.f1);
    std::vector<int> face_id(nb, 0);
    int faces = 0;
    mesh.face_tags.resize(nb);
    for (int f = 0; f < nb; ++f) {
        const int r = sets.find(f);
        if (face_id[r] == 0) face_id[r] = ++faces;
        mesh.face_tags(f) = face_id[r];
    }

    // Curves: walk crease edges through vertices with exactly two creases and the same face pair.
    std::vector<std::vector<int>> crease_at(nv);
    for (int e = 0; e < int(edges.size()); ++e)
        if (edges[e].crease) {
            crease_at[edges[e].a].push_back(e);
            crease_at[edges[e].b].push_back(e);
        }
    auto face_pair = [&](const BoundaryEdge& e) {
        const int x = mesh.face_tags(e.f0), y = mesh.face_tags(e.f1);
        return std::array<int, 2>{std::min(x, y), std::max(x, y)};
    };
    auto continues = [&](int v, int e) {  // the crease edge after e at v, or -1 if the curve stops
        if (crease_at[v].size() != 2) return -1;
        const int next = crease_at[v][0] == e ? crease_at[v][1] : crease_at[v][0];
        return face_pair(edges[next]) == face_pair(edges[e]) ? next : -1;
    };
    std::vector<int> curve_of(edges.size(), 0);
    std::vector<std::array<int, 2>> feature_edges;
    std::vector<int> edge_tags;
    std::vector<std::vector<double>> thetas;
    std::vector<double> lengths;
    for (int e0 = 0; e0 < int(edges.size()); ++e0) {
        if (!edges[e0].crease || curve_of[e0]) continue;
        const int curve = int(thetas.size()) + 1;
        thetas.emplace_back();
        lengths.push_back(0.0);
        // Grow in both directions from e0 (a closed loop stops when it meets e0 again).
        std::vector<int> stack = {e0};
        curve_of[e0] = curve;
        for (size_t s = 0; s < stack.size(); ++s) {
            const BoundaryEdge& e = edges[stack[s]];
            for (int v : {e.a, e.b}) {
                const int next = continues(v, stack[s]);
                if (next >= 0 && !curve_of[next]) {
                    curve_of[next] = curve;
                    stack.push_back(next);
                }
            }
        }
        std::sort(stack.begin(), stack.end());
        for (int e : stack) {
            feature_edges.push_back({edges[e].a, edges[e].b});
            edge_tags.push_back(curve);
            thetas.back().push_back(edges[e].theta);
            lengths.back() += (mesh.points.row(edges[e].a) - mesh.points.row(edges[e].b)).norm();
        }
    }
    mesh.feature_edges.resize(int(feature_edges.size()), 2);
    mesh.edge_tags.resize(int(edge_tags.size()));
    for (int e = 0; e < int(feature_edges.size()); ++e) {
        mesh.feature_edges.row(e) << feature_edges[e][0], feature_edges[e][1];
        mesh.edge_tags(e) = edge_tags[e];
    }
    std::vector<int> corners;
    for (int v = 0; v < nv; ++v)
        if (crease_at[v].size() >= 3) corners.push_back(v);
    mesh.corner_vertices = Eigen::Map<Eigen::VectorXi>(corners.data(), int(corners.size()));

    CreaseFeatures out;
    for (int c = 0; c < int(thetas.size()); ++c) {
        EdgeFeature f;
        f.edge = c + 1;
        const auto& t = thetas[c];
        const double mean = std::accumulate(t.begin(), t.end(), 0.0) / double(t.size());
        f.valence = std::clamp(int(std::lround(mean / 90.0)), 1, 4);
        f.angle_min_deg = *std::min_element(t.begin(), t.end());
        f.angle_max_deg = *std::max_element(t.begin(), t.end());
        f.valence_varies = std::lround(f.angle_min_deg / 90.0) != std::lround(f.angle_max_deg / 90.0);
        f.length = lengths[c];
        out.features.edges.push_back(f);
    }
    out.mesh = std::move(mesh);
    return out;
}

}  // namespace framefix
