#pragma once
// Test fixtures built in code: a cube [0,1]^3 (or an L-shaped prism) split into n^3 grid cells of
// 6 tets each (Kuhn subdivision along the main diagonal, so neighbouring cells conform), tets
// positively oriented, boundary triangles outward and tagged by cube face (1: x=0, 2: x=1,
// 3: y=0, 4: y=1, 5: z=0, 6: z=1), the 12 cube edges as feature edges tagged 1..12 with a
// FeatureSet of valence 1, the 8 cube corners as corner_vertices. The one cube of the backend
// tests (header only and mesh-level: the test executables link different libraries);
// corrections/cube_frames.h adds topology, constraints and a field on it.
#include <algorithm>
#include <array>
#include <cmath>
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

inline bool on_01(double x) { return std::abs(x) < 1e-9 || std::abs(x - 1) < 1e-9; }

// Vertex of grid point (i, j, k) of the n^3 cube (grid_tets keeps every point of the full cube).
inline int cube_vertex(int n, int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; }

// Grid edges along the 12 cube edges, lower vertex first, tagged 1 + 4 axis + 2 c1 + c2 where
// axis is the edge direction and c1, c2 its two other (0/1) coordinates.
inline void tag_cube_edges(int n, TetMesh& mesh) {
    std::vector<std::array<int, 3>> edges;  // a, b, tag
    for (int v = 0; v < mesh.num_vertices(); ++v)
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Vector3d p = mesh.points.row(v).transpose();
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            if (!on_01(p[a1]) || !on_01(p[a2]) || p[axis] > 1 - 1e-9) continue;
            int idx[3] = {int(std::lround(p[0] * n)), int(std::lround(p[1] * n)), int(std::lround(p[2] * n))};
            ++idx[axis];
            edges.push_back({v, cube_vertex(n, idx[0], idx[1], idx[2]), 1 + 4 * axis + 2 * int(p[a1] > 0.5) + int(p[a2] > 0.5)});
        }
    mesh.feature_edges.resize(int(edges.size()), 2);
    mesh.edge_tags.resize(int(edges.size()));
    for (int e = 0; e < int(edges.size()); ++e) {
        mesh.feature_edges.row(e) << edges[e][0], edges[e][1];
        mesh.edge_tags(e) = edges[e][2];
    }
}

inline Fixture cube_tets(int n) {
    Fixture fx;
    fx.mesh = grid_tets(n, [](int, int, int) { return true; });
    tag_axis_faces(fx.mesh);
    tag_cube_edges(n, fx.mesh);
    fx.mesh.corner_vertices.resize(8);
    for (int s = 0; s < 8; ++s) fx.mesh.corner_vertices(s) = cube_vertex(n, (s & 1) * n, ((s >> 1) & 1) * n, ((s >> 2) & 1) * n);
    fx.mesh.size = 1.0 / n;
    for (int e = 1; e <= 12; ++e) fx.features.edges.push_back({e, 1, 90, 90, 1.0, false, ""});
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
