#pragma once
// Unit-cube fixture built in code: an n x n x n grid, each cell split into 6 positively oriented
// tets (Kuhn split), boundary faces tagged 1..6 (x=0, x=1, y=0, y=1, z=0, z=1), the 12 cube
// edges tagged 1..12 as convex features, cube-aligned constraints (identity frames).
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Dense>

#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/sh.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix::test {

struct Cube {
    int n = 0;
    TetMesh mesh;
    TetTopology topo;
    FeatureSet features;
    Constraints constraints;
    FrameField field;  // identity frames everywhere

    int vertex(int i, int j, int k) const { return (k * (n + 1) + j) * (n + 1) + i; }
    Eigen::Vector3d point(int v) const { return mesh.points.row(v).transpose(); }
};

inline bool on_01(double x) { return std::abs(x) < 1e-9 || std::abs(x - 1) < 1e-9; }

inline Cube cube_tets(int n) {
    Cube c;
    c.n = n;
    const int nv = (n + 1) * (n + 1) * (n + 1);
    c.mesh.points.resize(nv, 3);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) c.mesh.points.row(c.vertex(i, j, k)) << double(i) / n, double(j) / n, double(k) / n;

    // Kuhn split: one tet per axis order, walking from corner (0,0,0) to (1,1,1) of the cell.
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::vector<Eigen::Vector4i> tets;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& order : orders) {
                    int p[3] = {i, j, k};
                    Eigen::Vector4i t;
                    t[0] = c.vertex(p[0], p[1], p[2]);
                    for (int s = 0; s < 3; ++s) ++p[order[s]], t[s + 1] = c.vertex(p[0], p[1], p[2]);
                    Eigen::Matrix3d d;
                    for (int s = 0; s < 3; ++s) d.col(s) = c.point(t[s + 1]) - c.point(t[0]);
                    if (d.determinant() < 0) std::swap(t[1], t[2]);
                    tets.push_back(t);
                }
    c.mesh.tets.resize(int(tets.size()), 4);
    for (int t = 0; t < int(tets.size()); ++t) c.mesh.tets.row(t) = tets[t].transpose();

    // Boundary faces: tet faces seen once, in the tet's outward local order.
    std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;
    for (const auto& t : tets)
        for (const auto& lf : kTetFace) {
            std::array<int, 3> f{t[lf[0]], t[lf[1]], t[lf[2]]}, key = f;
            std::sort(key.begin(), key.end());
            auto& entry = faces[key];
            ++entry.first;
            entry.second = f;
        }
    std::vector<std::array<int, 3>> boundary;
    for (const auto& [key, entry] : faces)
        if (entry.first == 1) boundary.push_back(entry.second);
    c.mesh.boundary_faces.resize(int(boundary.size()), 3);
    c.mesh.face_tags.resize(int(boundary.size()));
    for (int f = 0; f < int(boundary.size()); ++f) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int s = 0; s < 3; ++s) c.mesh.boundary_faces(f, s) = boundary[f][s], centroid += c.point(boundary[f][s]) / 3;
        int tag = 0;
        for (int axis = 0; axis < 3; ++axis)
            if (on_01(centroid[axis])) tag = 1 + 2 * axis + (centroid[axis] > 0.5);
        c.mesh.face_tags(f) = tag;
    }

    // Feature edges: grid edges with both other coordinates on {0, 1}; tag = 1 + 4 axis + 2 c1 + c2.
    std::vector<std::array<int, 3>> features;  // a, b, tag
    for (int v = 0; v < nv; ++v)
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Vector3d p = c.point(v);
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            if (!on_01(p[a1]) || !on_01(p[a2]) || p[axis] > 1 - 1e-9) continue;
            int idx[3] = {int(std::lround(p[0] * n)), int(std::lround(p[1] * n)), int(std::lround(p[2] * n))};
            ++idx[axis];
            features.push_back({v, c.vertex(idx[0], idx[1], idx[2]), 1 + 4 * axis + 2 * int(p[a1] > 0.5) + int(p[a2] > 0.5)});
        }
    c.mesh.feature_edges.resize(int(features.size()), 2);
    c.mesh.edge_tags.resize(int(features.size()));
    for (int e = 0; e < int(features.size()); ++e) {
        c.mesh.feature_edges.row(e) << features[e][0], features[e][1];
        c.mesh.edge_tags(e) = features[e][2];
    }
    c.mesh.corner_vertices.resize(8);
    for (int s = 0; s < 8; ++s) c.mesh.corner_vertices(s) = c.vertex((s & 1) * n, ((s >> 1) & 1) * n, ((s >> 2) & 1) * n);
    c.mesh.size = 1.0 / n;
    c.topo = build_topology(c.mesh);

    for (int e = 1; e <= 12; ++e) c.features.edges.push_back({e, 1, 90, 90, 1.0, false, ""});

    // Cube-aligned constraints: identity frames on edges and corners, tangency on faces.
    const SH9 identity = frame_from_rotation(Eigen::Matrix3d::Identity());
    c.constraints.kind.assign(nv, ConstraintKind::Free);
    c.constraints.normal = decltype(c.constraints.normal)::Zero(nv, 3);
    c.constraints.fixed = decltype(c.constraints.fixed)::Zero(nv, 9);
    for (int v = 0; v < nv; ++v) {
        const Eigen::Vector3d p = c.point(v);
        int on = 0;
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        for (int axis = 0; axis < 3; ++axis)
            if (on_01(p[axis])) ++on, normal[axis] = p[axis] > 0.5 ? 1 : -1;
        if (on == 1) c.constraints.kind[v] = ConstraintKind::NormalAligned, c.constraints.normal.row(v) = normal;
        if (on >= 2) c.constraints.kind[v] = ConstraintKind::Fixed, c.constraints.fixed.row(v) = identity.transpose();
    }
    c.field.coefficients = FrameCoefficients::Zero(nv, 9);
    c.field.axes = decltype(c.field.axes)::Zero(nv, 9);
    for (int v = 0; v < nv; ++v) {
        c.field.coefficients.row(v) = identity.transpose();
        c.field.axes.row(v) << 1, 0, 0, 0, 1, 0, 0, 0, 1;
    }
    c.field.kind = c.constraints.kind;
    return c;
}

// A graph node / curve pair for hand-made singularity graphs.
inline SingularNode node_at(int id, const Eigen::Vector3d& p, bool boundary) {
    SingularNode node;
    node.id = id;
    node.position = p;
    node.boundary = boundary;
    return node;
}

inline SingularCurve curve_between(int id, int a, int b, CurveKind kind, int faces = 10) {
    SingularCurve c;
    c.id = id;
    c.kind = kind;
    c.ends[0] = a, c.ends[1] = b;
    for (int f = 0; f < faces; ++f) c.faces.push_back(f), c.valences.push_back(kind == CurveKind::Valence5 ? 5 : 3);
    return c;
}

}  // namespace framefix::test
