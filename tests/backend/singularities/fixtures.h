#pragma once
// Synthetic frame fields for the singularity tests, built in code on the cube fixture of
// tests/backend/mesh/cube_fixture.h (n^3 cells x 6 Kuhn tets, tagged faces, edges, corners).
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "backend/mesh/cube_fixture.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/sh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix::testing {

constexpr double kPi = 3.14159265358979323846;

inline Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A frame field sampled at the mesh vertices from frame(x) -> rotation (coefficients and axes).
template <class Frame>
FrameField field_of(const TetMesh& mesh, Frame frame) {
    FrameField f;
    const int nv = mesh.num_vertices();
    f.coefficients.resize(nv, 9);
    f.axes.resize(nv, 9);
    for (int v = 0; v < nv; ++v) {
        const Eigen::Matrix3d R = frame(Eigen::Vector3d(mesh.points.row(v).transpose()));
        f.coefficients.row(v) = frame_from_rotation(R).transpose();
        for (int k = 0; k < 3; ++k) f.axes.row(v).segment<3>(3 * k) = R.col(k).transpose();
    }
    return f;
}

// Orthonormal basis [e1 e2 d] with third column along d.
inline Eigen::Matrix3d basis_along(const Eigen::Vector3d& d) {
    const Eigen::Vector3d z = d.normalized();
    const Eigen::Vector3d e1 = (std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
                                   .cross(z)
                                   .normalized();
    Eigen::Matrix3d A;
    A << e1, z.cross(e1), z;
    return A;
}

// A straight singular line through c along d: the frame turns by index * theta about d, theta the
// polar angle about the line (counter-clockwise seen from +d). index +1/4 -> valence 3.
// flip(t), t = coordinate along d from c: the stable direction is turned by pi * flip(t) about
// e1 (0 -> along +d, 1 -> along -d): a 3-5 curve when flip goes from 0 to 1.
struct LineField {
    Eigen::Vector3d c, d;
    double index = 0.25;
    double flip_from = 1e9, flip_to = 2e9;  // flip ramps smoothly from 0 to 1 over [flip_from, flip_to]

    Eigen::Matrix3d operator()(const Eigen::Vector3d& x) const {
        const Eigen::Matrix3d A = basis_along(d);
        const Eigen::Vector3d l = A.transpose() * (x - c);
        const double theta = std::atan2(l.y(), l.x());
        double s = std::clamp((l.z() - flip_from) / (flip_to - flip_from), 0.0, 1.0);
        s = s * s * (3 - 2 * s);
        return A * rot(Eigen::Vector3d::UnitX(), kPi * s) * rot(Eigen::Vector3d::UnitZ(), index * theta);
    }
};

// Labels faces crossed by the segment p-q (for hand-made singular curves).
inline bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    auto vol = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
                  const Eigen::Vector3d& x) { return (v - u).cross(w - u).dot(x - u); };
    const double sp = vol(a, b, c, p), sq = vol(a, b, c, q);
    if ((sp > 0) == (sq > 0) || sp == 0 || sq == 0) return false;
    const double s1 = vol(p, q, a, b), s2 = vol(p, q, b, c), s3 = vol(p, q, c, a);
    return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

inline Eigen::Vector3d point(const TetMesh& mesh, int v) { return mesh.points.row(v).transpose(); }

// Sets `label` on every face crossed by the segment p-q; returns how many.
inline int label_segment(const TetMesh& mesh, const TetTopology& topo, const Eigen::Vector3d& p,
                         const Eigen::Vector3d& q, int label, std::vector<int>& val) {
    int n = 0;
    for (int f = 0; f < topo.faces.rows(); ++f)
        if (segment_crosses_triangle(p, q, point(mesh, topo.faces(f, 0)), point(mesh, topo.faces(f, 1)),
                                     point(mesh, topo.faces(f, 2)))) {
            val[f] = label;
            ++n;
        }
    return n;
}

}  // namespace framefix::testing
