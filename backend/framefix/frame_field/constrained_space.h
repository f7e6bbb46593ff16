#pragma once
// The admissible fields of the constrained problem (docs/algorithms.md#constrained-space): q = c + x with x in
// V = range(P), P block-diagonal per vertex (I9 free, the 9x2 normal-aligned basis P_n, or empty
// for fixed frames). The columns of every P block are orthonormal, so the orthogonal projector
// onto V is P P^T vertex by vertex and the reduced system P^T A P y = P^T b is equivalent to
// "x in V, Pi (A x - b) = 0" on full #V x 9 fields. Internal to frame_field.
#include <vector>

#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/p1_system.h"

namespace framefix {

struct ConstrainedSpace {
    std::vector<ConstraintKind> kind;    // #V
    FrameCoefficients c;                 // #V x 9: the fixed frame, sqrt(7/12) B_n e4, or 0 (free)
    std::vector<int> family;             // #V, index into `families` for NormalAligned, else -1
    std::vector<NormalAligned> families; // one per NormalAligned vertex, in vertex order
    std::vector<Eigen::Matrix3d> fixed_rotation;  // #V, the Fixed frame's rotation (identity elsewhere)

    int vertices() const { return int(kind.size()); }
};

ConstrainedSpace make_space(const Constraints& constraints);

// In-place kernels on #V x 9 row-major fields, parallel over vertices with `threads` threads.
// Dot products sum fixed blocks of rows in a fixed order: results do not depend on the thread count.
void project_to_space(const ConstrainedSpace& space, FrameCoefficients& x, int threads);  // x <- Pi x
// y = mass_weight * M x + stiff_weight * K x   (no projection)
void apply_system(const P1System& sys, double mass_weight, double stiff_weight, const FrameCoefficients& x,
                  FrameCoefficients& y, int threads);
double dot(const FrameCoefficients& a, const FrameCoefficients& b, int threads);
// sum_c q_c^T K q_c
double dirichlet_energy(const P1System& sys, const FrameCoefficients& q, int threads);
// sqrt(sum_i M_ii |a_i - b_i|^2): the M-norm of a - b (b may be a zero-row matrix = 0)
double mass_norm_diff(const P1System& sys, const FrameCoefficients& a, const FrameCoefficients& b, int threads);

}  // namespace framefix
