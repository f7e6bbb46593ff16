#pragma once
// The cube of tests/backend/mesh/cube_fixture.h with what the correction, streamline and block
// tests start from: its topology, cube-aligned constraints and the identity frame field.
#include <utility>

#include <Eigen/Dense>

#include "backend/mesh/cube_fixture.h"
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

    int vertex(int i, int j, int k) const { return testing::cube_vertex(n, i, j, k); }
    Eigen::Vector3d point(int v) const { return mesh.points.row(v).transpose(); }
};

inline Cube cube_tets(int n) {
    Cube c;
    c.n = n;
    testing::Fixture fx = testing::cube_tets(n);
    c.mesh = std::move(fx.mesh);
    c.features = std::move(fx.features);
    c.topo = build_topology(c.mesh);
    const int nv = c.mesh.num_vertices();

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
            if (testing::on_01(p[axis])) ++on, normal[axis] = p[axis] > 0.5 ? 1 : -1;
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
