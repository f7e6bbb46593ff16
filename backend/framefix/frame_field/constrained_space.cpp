#include "framefix/frame_field/constrained_space.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/frame_field/projection.h"

namespace framefix {
namespace {

constexpr int kBlock = 2048;  // rows per partial sum; fixed so sums do not depend on threads

template <class RowFn>
double blocked_sum(int rows, int threads, RowFn&& row_value) {
    const int blocks = (rows + kBlock - 1) / kBlock;
    std::vector<double> partial(blocks, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int b = 0; b < blocks; ++b) {
        double s = 0;
        const int end = std::min(rows, (b + 1) * kBlock);
        for (int i = b * kBlock; i < end; ++i) s += row_value(i);
        partial[b] = s;
    }
    double total = 0;
    for (double p : partial) total += p;
    return total;
}

NormalAligned singular_family(const Constraints& cons, int v) {
    const Eigen::Vector3d n = cons.normal.row(v).transpose();
    if (!(n.norm() > 1e-12)) throw Error("field", "constraints: singular vertex " + std::to_string(v) + " has a zero axis");
    return normal_aligned(n);
}

}  // namespace

ConstrainedSpace make_space(const Constraints& cons) {
    const int nv = int(cons.kind.size());
    if (cons.normal.rows() != nv || cons.fixed.rows() != nv || (!cons.singular.empty() && int(cons.singular.size()) != nv))
        throw Error("field", "constraints: kind has " + std::to_string(nv) + " rows but normal/fixed have " +
                                 std::to_string(cons.normal.rows()) + "/" + std::to_string(cons.fixed.rows()));
    ConstrainedSpace s;
    s.kind = cons.kind;
    s.c = FrameCoefficients::Zero(nv, 9);
    s.family.assign(nv, -1);
    s.fixed_rotation.assign(nv, Eigen::Matrix3d::Identity());
    for (int v = 0; v < nv; ++v) {
        if (s.kind[v] == ConstraintKind::NormalAligned) {
            const Eigen::Vector3d n = cons.normal.row(v).transpose();
            if (!(n.norm() > 1e-12)) throw Error("field", "constraints: vertex " + std::to_string(v) + " has a zero normal");
            s.family[v] = int(s.families.size());
            s.families.push_back(normal_aligned(n));
            s.c.row(v) = s.families.back().c.transpose();
        } else if (s.kind[v] == ConstraintKind::Fixed && !cons.singular.empty() && cons.singular[size_t(v)]) {
            const NormalAligned fam = singular_family(cons, v);
            s.c.row(v) = fam.c.transpose();
            s.fixed_rotation[v] = normal_aligned_rotation(fam, Eigen::Vector2d(0, 1));  // any turn about the axis
        } else if (s.kind[v] == ConstraintKind::Fixed) {
            const SH9 g = cons.fixed.row(v).transpose();
            const ProjectedFrame f = project_frame(g);
            if (!f.defined || f.distance > 1e-6)
                throw Error("field", "constraints: the fixed value of vertex " + std::to_string(v) +
                                         " is not a frame (distance " + std::to_string(f.distance) + ")");
            s.c.row(v) = g.transpose();
            s.fixed_rotation[v] = f.rotation;
        }
    }
    return s;
}

void project_to_space(const ConstrainedSpace& s, FrameCoefficients& x, int threads) {
    const int nv = s.vertices();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int v = 0; v < nv; ++v) {
        if (s.kind[v] == ConstraintKind::Free) continue;
        if (s.kind[v] == ConstraintKind::Fixed) {
            x.row(v).setZero();
            continue;
        }
        const auto& P = s.families[s.family[v]].P;
        const Eigen::Vector2d y = P.transpose() * x.row(v).transpose();
        x.row(v) = (P * y).transpose();
    }
}

void apply_system(const P1System& sys, double mass_weight, double stiff_weight, const FrameCoefficients& x,
                  FrameCoefficients& y, int threads) {
    const int nv = sys.rows();
    y.resize(nv, 9);
    const double* X = x.data();
    double* Y = y.data();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int i = 0; i < nv; ++i) {
        double acc[9];
        const double m = mass_weight * sys.mass(i);
        for (int c = 0; c < 9; ++c) acc[c] = m * X[9 * i + c];
        for (int k = sys.row_start[i]; k < sys.row_start[i + 1]; ++k) {
            const double a = stiff_weight * sys.K[k];
            const double* xj = X + 9 * size_t(sys.col[k]);
            for (int c = 0; c < 9; ++c) acc[c] += a * xj[c];
        }
        for (int c = 0; c < 9; ++c) Y[9 * i + c] = acc[c];
    }
}

double dot(const FrameCoefficients& a, const FrameCoefficients& b, int threads) {
    const double* A = a.data();
    const double* B = b.data();
    return blocked_sum(int(a.rows()), threads, [&](int i) {
        double s = 0;
        for (int c = 0; c < 9; ++c) s += A[9 * i + c] * B[9 * i + c];
        return s;
    });
}

// AVX2+FMA clone, as the CG kernels (projected_cg.cpp).
__attribute__((target_clones("arch=x86-64-v3", "default"))) double dirichlet_energy(const P1System& sys, const FrameCoefficients& q, int threads) {
    const double* Q = q.data();
    return blocked_sum(sys.rows(), threads, [&](int i) {  // q_i . (K q)_i, no #V x 9 temporary
        double acc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        for (int k = sys.row_start[i]; k < sys.row_start[i + 1]; ++k) {
            const double* qj = Q + 9 * size_t(sys.col[k]);
            for (int c = 0; c < 9; ++c) acc[c] += sys.K[k] * qj[c];
        }
        double s = 0;
        for (int c = 0; c < 9; ++c) s += Q[9 * size_t(i) + c] * acc[c];
        return s;
    });
}

double mass_norm_diff(const P1System& sys, const FrameCoefficients& a, const FrameCoefficients& b, int threads) {
    const bool zero_b = b.rows() == 0;
    return std::sqrt(blocked_sum(int(a.rows()), threads, [&](int i) {
        const double d = zero_b ? a.row(i).squaredNorm() : (a.row(i) - b.row(i)).squaredNorm();
        return sys.mass(i) * d;
    }));
}

}  // namespace framefix
