#pragma once
// Test fixture shared by the frame-field tests.
#include <cmath>

#include "backend/mesh/cube_fixture.h"
#include "framefix/frame_field/frame_field.h"

namespace framefix {

// A cube whose bottom face is fixed to the identity frame and top face to a frame turned 40 deg
// about z, sides normal-aligned: a non-trivial field.
inline testing::Fixture twisted_cube(int n = 5) { return testing::cube_tets(n); }

inline Constraints twisted_constraints(const TetMesh& mesh) {
    Constraints c;
    const int nv = mesh.num_vertices();
    c.kind.assign(nv, ConstraintKind::Free);
    c.normal = decltype(c.normal)::Zero(nv, 3);
    c.fixed = decltype(c.fixed)::Zero(nv, 9);
    const Eigen::Matrix3d top = Eigen::AngleAxisd(40 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (int v = 0; v < nv; ++v) {
        const Eigen::Vector3d p = mesh.points.row(v);
        if (p.z() < 1e-12 || p.z() > 1 - 1e-12) {
            c.kind[v] = ConstraintKind::Fixed;
            c.fixed.row(v) = frame_from_rotation(p.z() < 0.5 ? Eigen::Matrix3d::Identity() : top).transpose();
        } else if (p.x() < 1e-12 || p.x() > 1 - 1e-12 || p.y() < 1e-12 || p.y() > 1 - 1e-12) {
            c.kind[v] = ConstraintKind::NormalAligned;
            const Eigen::Vector3d n(p.x() < 1e-12 ? -1 : p.x() > 1 - 1e-12 ? 1 : 0, p.y() < 1e-12 ? -1 : p.y() > 1 - 1e-12 ? 1 : 0, 0);
            c.normal.row(v) = n.normalized().transpose();
        }
    }
    return c;
}

}  // namespace framefix
