#pragma once
// Per-triangle holonomy of a per-vertex frame field (docs/algorithms.md#edge-transport-and-holonomy,
// #valence-sign-rule): internal to singularities/, exposed for the tests.
//
// Transport along a mesh edge (a, b), a < b, is one cube rotation T_ab: R_b T_ab is the
// representative of frame b that the field carries over from R_a. It is found by matching through
// the projected samples at 1/3 and 2/3 of the edge (q interpolated linearly, projected with a warm
// start), so consecutive frames stay < 45 deg apart. Since matching is equivariant
// (match(Ra h, Rb) = match(Ra, Rb) h), the holonomy of the loop i0 -> i1 -> i2 -> i0 is the product
// g_H = T_20 T_12 T_01: R_i0 g_H is frame i0 after one turn. It is a rotation of angle 0, 90, 120
// or 180 deg; for 90 deg the world axis w = R_i0 axis(g_H) and the loop normal
// n = (x1 - x0) x (x2 - x0) give the valence: 3 iff w.n > 0 (index +1/4), 5 iff w.n < 0.
// Reversing the loop inverts g_H and flips both w and n, so the label is the face's own.
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

struct HolonomyOptions {
    // Edges whose end frames match within this angle are transported without sub-sampling: the
    // projected samples lie near the short geodesic, so they cannot change the matched result.
    // Degrees, 0 = always sub-sample; useful range 0..25 (keep well below 45).
    double direct_match_deg = 20;
    int threads = 0;  // OpenMP threads, 0 = all
};

struct FaceHolonomy {
    std::vector<int> valence;  // #F (topology faces): 0 regular, 3, 5, or -1 complex (120/180 deg)
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> axis;  // #F x 3 unit world axis w, 0 if regular
    int subsampled_edges = 0;  // edges whose end frames were more than direct_match_deg apart
};

// Frame rotation at every vertex: #V rotations (columns = axes). Warm-started from field.axes
// when it has one row per vertex, else a full multi-start projection of the coefficients.
std::vector<Eigen::Matrix3d> vertex_rotations(const FrameField& field, int threads);

// Cube rotation T_ab carried along the segment from frame (qa, Ra) to frame (qb, Rb);
// `subsampled` tells whether the 1/3, 2/3 samples were needed.
int edge_transport(const SH9& qa, const SH9& qb, const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb,
                   double direct_match_deg, bool* subsampled = nullptr);

// Holonomy g_H of a closed sequence of frames (the last one connects back to the first) by
// successive matching. Reference implementation for the tests.
int loop_holonomy(const std::vector<Eigen::Matrix3d>& frames);

// Label of a loop with holonomy g through x0 -> x1 -> x2, frame R0 at x0: 0, 3, 5 or -1;
// `axis` receives the world axis w (zero when regular).
int loop_valence(int g, const Eigen::Matrix3d& R0, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                 const Eigen::Vector3d& x2, Eigen::Vector3d* axis);

// Holonomy of every topology face, interior and boundary.
FaceHolonomy face_holonomy(const TetMesh& mesh, const TetTopology& topo, const FrameField& field,
                           const HolonomyOptions& options);

}  // namespace framefix
