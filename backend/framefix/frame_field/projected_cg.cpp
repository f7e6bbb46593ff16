// Jacobi-preconditioned CG on the constrained space V (constrained_space.h), on full #V x 9
// fields. On V the Jacobi preconditioner of the reduced matrix is a scalar per vertex
// (P_n^T P_n = I2), so it commutes with Pi and keeps the iterates in V.
#include <cmath>
#include <vector>

#include "framefix/frame_field/linear_solver.h"

namespace framefix {
namespace {

constexpr int kBlock = 2048;  // rows per partial sum, fixed for thread-count independent results

// y = Pi (mass_weight M + stiff_weight K) x, and returns x . y (summed by fixed blocks).
double apply_projected(const P1System& sys, const ConstrainedSpace& space, double mw, double sw,
                       const FrameCoefficients& x, FrameCoefficients& y, int threads) {
    const int nv = sys.rows();
    const int blocks = (nv + kBlock - 1) / kBlock;
    std::vector<double> partial(blocks, 0.0);
    const double* X = x.data();
    double* Y = y.data();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int b = 0; b < blocks; ++b) {
        double s = 0;
        const int end = std::min(nv, (b + 1) * kBlock);
        for (int i = b * kBlock; i < end; ++i) {
            double* yi = Y + 9 * size_t(i);
            if (space.kind[i] == ConstraintKind::Fixed) {
                for (int c = 0; c < 9; ++c) yi[c] = 0;
                continue;
            }
            double acc[9];
            const double m = mw * sys.mass(i);
            for (int c = 0; c < 9; ++c) acc[c] = m * X[9 * size_t(i) + c];
            for (int k = sys.row_start[i]; k < sys.row_start[i + 1]; ++k) {
                const double a = sw * sys.K[k];
                const double* xj = X + 9 * size_t(sys.col[k]);
                for (int c = 0; c < 9; ++c) acc[c] += a * xj[c];
            }
            if (space.kind[i] == ConstraintKind::NormalAligned) {
                const auto& P = space.families[space.family[i]].P;
                Eigen::Map<const SH9> a(acc);
                const Eigen::Vector2d yv = P.transpose() * a;
                Eigen::Map<SH9> out(yi);
                out = P * yv;
            } else {
                for (int c = 0; c < 9; ++c) yi[c] = acc[c];
            }
            for (int c = 0; c < 9; ++c) s += X[9 * size_t(i) + c] * yi[c];
        }
        partial[b] = s;
    }
    double total = 0;
    for (double p : partial) total += p;
    return total;
}

}  // namespace

LinearSolveStats solve_projected_cg(const P1System& sys, const ConstrainedSpace& space, double mw, double sw,
                                    const FrameCoefficients& b, FrameCoefficients& x, double tolerance,
                                    int threads) {
    const int nv = sys.rows();
    LinearSolveStats stats;
    Eigen::VectorXd inv_diag(nv);
    for (int i = 0; i < nv; ++i) inv_diag(i) = 1.0 / (mw * sys.mass(i) + sw * sys.K[sys.diag[i]]);

    FrameCoefficients r(nv, 9), z(nv, 9), p(nv, 9), Ap(nv, 9);
    project_to_space(space, x, threads);
    apply_projected(sys, space, mw, sw, x, Ap, threads);
    FrameCoefficients bV = b;
    project_to_space(space, bV, threads);
    const double b_norm = std::sqrt(dot(bV, bV, threads));
    r = bV - Ap;
    if (b_norm == 0) {  // the solution is 0
        x.setZero();
        return stats;
    }
    z = inv_diag.asDiagonal() * r;
    p = z;
    double rz = dot(r, z, threads);
    double r_norm = std::sqrt(dot(r, r, threads));
    const int max_iterations = 20000;
    const int blocks = (nv + kBlock - 1) / kBlock;
    std::vector<double> part_rz(blocks), part_rr(blocks);
    while (r_norm > tolerance * b_norm && stats.iterations < max_iterations) {
        const double pAp = apply_projected(sys, space, mw, sw, p, Ap, threads);
        const double alpha = rz / pAp;
        // x += alpha p, r -= alpha Ap, z = D^-1 r, with r.z and r.r, in one pass.
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int blk = 0; blk < blocks; ++blk) {
            double srz = 0, srr = 0;
            const int end = std::min(nv, (blk + 1) * kBlock);
            for (int i = blk * kBlock; i < end; ++i)
                for (int c = 0; c < 9; ++c) {
                    x(i, c) += alpha * p(i, c);
                    const double ri = r(i, c) - alpha * Ap(i, c);
                    r(i, c) = ri;
                    const double zi = inv_diag(i) * ri;
                    z(i, c) = zi;
                    srz += ri * zi;
                    srr += ri * ri;
                }
            part_rz[blk] = srz;
            part_rr[blk] = srr;
        }
        double rz_new = 0, rr = 0;
        for (int blk = 0; blk < blocks; ++blk) {
            rz_new += part_rz[blk];
            rr += part_rr[blk];
        }
        const double beta = rz_new / rz;
        rz = rz_new;
        r_norm = std::sqrt(rr);
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int i = 0; i < nv; ++i)
            for (int c = 0; c < 9; ++c) p(i, c) = z(i, c) + beta * p(i, c);
        stats.iterations += 1;
    }
    stats.relative_residual = r_norm / b_norm;
    stats.converged = r_norm <= tolerance * b_norm;
    return stats;
}

}  // namespace framefix
