#pragma once
// Test fixtures built in code: a cube [0,1]^3 (or an L-shaped prism) split into n^3 grid cells of
// 6 tets each (Kuhn subdivision along the main diagonal, so neighbouring cells conform), tets
// positively oriented, boundary triangles outward and tagged by cube face (1: x=0, 2: x=1,
// 3: y=0, 4: y=1, 5: z=0, 6: z=1), the 12 cube edges as feature edges tagged 1..12 with a
// FeatureSet of valence 1, the 8 cube corners as corner_vertices. Shared by test_mesh and
// test_frame_field (header only: the two test executables link different libraries).
#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "framefix/mesh/features.h"
#include "framefix/mesh/mesh_io.h"

namespace framefix::testing {

struct Fixture {
    TetMesh mesh;
    FeatureSet features;
};

// keep(i, j, k): which grid cells exist (all for the cube).
template <class Keep>
TetMesh grid_tets(int n, Keep keep) {
    const int m = n + 1;
    Points P(m * m * m, 3);
    auto id = [m](int i, int j, int k) { return (k * m + j) * m + i; };
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) P.row(id(i, j, k)) << double(i) / n, double(j) / n, double(k) / n;
    std::vector<std::array<int, 4>> tets;
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if (!keep(i, j, k)) continue;
                for (const auto& p : perms) {
                    std::array<int, 3> c = {i, j, k};
                    std::array<int, 4> t;
                    t[0] = id(c[0], c[1], c[2]);
                    for (int s = 0; s < 3; ++s) {
                        c[p[s]] += 1;
                        t[s + 1] = id(c[0], c[1], c[2]);
                    }
                    tets.push_back(t);
                }
            }
    Tets T(int(tets.size()), 4);
    for (int t = 0; t < T.rows(); ++t)
        for (int k = 0; k < 4; ++k) T(t, k) = tets[t][k];
    // assemble_tet_mesh orients the tets and extracts the outward boundary.
    return assemble_tet_mesh(P, T, Triangles(0, 3), Eigen::VectorXi(0));
}

// Face tag from the outward normal of an axis-aligned boundary triangle.
inline void tag_axis_faces(TetMesh& mesh) {
    mesh.face_tags.resize(mesh.boundary_faces.rows());
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d a = mesh.points.row(mesh.boundary_faces(f, 0)), b = mesh.points.row(mesh.boundary_faces(f, 1)),
                              c = mesh.points.row(mesh.boundary_faces(f, 2));
        const Eigen::Vector3d n = (b - a).cross(c - a);
        int axis;
        n.cwiseAbs().maxCoeff(&axis);
        mesh.face_tags(f) = 2 * axis + (n(axis) > 0 ? 2 : 1);
    }
}

inline Fixture cube_tets(int n) {
    Fixture fx;
    fx.mesh = grid_tets(n, [](int, int, int) { return true; });
    tag_axis_faces(fx.mesh);
    // Cube edges: boundary edges whose two endpoints share two extreme coordinates.
    std::map<std::array<int, 2>, int> edges;
    auto extreme = [](double x) { return x < 1e-12 ? 0 : x > 1 - 1e-12 ? 1 : -1; };
    for (int f = 0; f < fx.mesh.boundary_faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            int u = fx.mesh.boundary_faces(f, k), v = fx.mesh.boundary_faces(f, (k + 1) % 3);
            if (u > v) std::swap(u, v);
            int fixed_axes = 0, key = 0;
            for (int a = 0; a < 3; ++a) {
                const int eu = extreme(fx.mesh.points(u, a)), ev = extreme(fx.mesh.points(v, a));
                if (eu >= 0 && eu == ev) {
                    fixed_axes += 1;
                    key = key * 4 + a * 2 + eu;
                }
            }
            if (fixed_axes == 2) edges[{u, v}] = key;
        }
    std::map<int, int> tag_of_key;
    for (const auto& [e, key] : edges) tag_of_key.emplace(key, 0);
    int next = 0;
    for (auto& [key, tag] : tag_of_key) tag = ++next;
    fx.mesh.feature_edges.resize(int(edges.size()), 2);
    fx.mesh.edge_tags.resize(int(edges.size()));
    int row = 0;
    for (const auto& [e, key] : edges) {
        fx.mesh.feature_edges.row(row) << e[0], e[1];
        fx.mesh.edge_tags(row++) = tag_of_key[key];
    }
    std::vector<int> corners;
    for (int v = 0; v < fx.mesh.num_vertices(); ++v) {
        int ext = 0;
        for (int a = 0; a < 3; ++a) ext += extreme(fx.mesh.points(v, a)) >= 0;
        if (ext == 3) corners.push_back(v);
    }
    fx.mesh.corner_vertices = Eigen::Map<Eigen::VectorXi>(corners.data(), int(corners.size()));
    for (int e = 1; e <= 12; ++e) {
        EdgeFeature f;
        f.edge = e;
        f.valence = 1;
        f.angle_min_deg = f.angle_max_deg = 90;
        fx.features.edges.push_back(f);
    }
    return fx;
}

// The same solid moved by a rotation (tags unchanged).
inline Fixture rotated(Fixture fx, const Eigen::Matrix3d& Q) {
    for (int v = 0; v < fx.mesh.num_vertices(); ++v) fx.mesh.points.row(v) = (Q * fx.mesh.points.row(v).transpose()).transpose();
    return fx;
}

// Extruded L: the cube minus the cells with x > 1/2 and y > 1/2 (n even); untagged.
inline TetMesh l_prism_tets(int n) {
    return grid_tets(n, [n](int i, int j, int) { return !(2 * i >= n && 2 * j >= n); });
}

}  // namespace framefix::testing
