// Direct factorisations of the reduced system P^T (mass_weight M + stiff_weight K) P (kept for
// measurement: see bench/bench_field.cpp; projected CG is the default). The reduced matrix is
// assembled block by block: a_ij P_i^T P_j with P = I9 (free), P_n (normal-aligned), empty (fixed).
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "framefix/core/error.h"
#include "framefix/frame_field/linear_solver.h"

namespace framefix {

using SpMat = Eigen::SparseMatrix<double>;

struct ConstrainedSolver::Direct {
    Direct(const P1System& s, const ConstrainedSpace& c, SparseSolver k) : sys(s), space(c), kind(k) {}
    const P1System& sys;
    const ConstrainedSpace& space;
    SparseSolver kind;
    std::vector<int> offset;  // #V + 1, first reduced dof of each vertex
    Eigen::SimplicialLDLT<SpMat> ldlt;
    Eigen::CholmodSupernodalLLT<SpMat> cholmod;
    bool analysed = false;
    double mw = -1, sw = -1;  // weights of the current factorisation
};

namespace {

// Columns of vertex v's P block as a 9 x d matrix (d = 9, 2 or 0).
Eigen::Matrix<double, 9, Eigen::Dynamic> basis(const ConstrainedSpace& s, int v) {
    if (s.kind[v] == ConstraintKind::Free) return Eigen::Matrix<double, 9, 9>::Identity();
    if (s.kind[v] == ConstraintKind::NormalAligned) return s.families[s.family[v]].P;
    return Eigen::Matrix<double, 9, Eigen::Dynamic>(9, 0);
}

SpMat reduced_matrix(const ConstrainedSolver::Direct& d, double mw, double sw) {
    std::vector<Eigen::Triplet<double>> trip;
    const int nv = d.sys.rows();
    for (int i = 0; i < nv; ++i) {
        const auto Pi = basis(d.space, i);
        if (Pi.cols() == 0) continue;
        for (int k = d.sys.row_start[i]; k < d.sys.row_start[i + 1]; ++k) {
            const int j = d.sys.col[k];
            const double a = sw * d.sys.K[k] + (i == j ? mw * d.sys.mass(i) : 0.0);
            const auto Pj = basis(d.space, j);
            if (Pj.cols() == 0) continue;
            const Eigen::MatrixXd blk = a * Pi.transpose() * Pj;
            for (int r = 0; r < blk.rows(); ++r)
                for (int c = 0; c < blk.cols(); ++c)
                    if (blk(r, c) != 0) trip.emplace_back(d.offset[i] + r, d.offset[j] + c, blk(r, c));
        }
    }
    SpMat A(d.offset[nv], d.offset[nv]);
    A.setFromTriplets(trip.begin(), trip.end());
    return A;
}

}  // namespace

ConstrainedSolver::Direct* make_direct(const P1System& sys, const ConstrainedSpace& space, SparseSolver kind) {
    auto* d = new ConstrainedSolver::Direct(sys, space, kind);
    d->offset.assign(sys.rows() + 1, 0);
    for (int v = 0; v < sys.rows(); ++v) d->offset[v + 1] = d->offset[v] + int(basis(space, v).cols());
    return d;
}

void destroy_direct(ConstrainedSolver::Direct* d) { delete d; }

LinearSolveStats solve_direct(ConstrainedSolver::Direct& d, double mw, double sw, const FrameCoefficients& b,
                              FrameCoefficients& x) {
    const int nv = d.sys.rows();
    if (mw != d.mw || sw != d.sw) {
        const SpMat A = reduced_matrix(d, mw, sw);
        bool ok;
        if (d.kind == SparseSolver::Cholmod) {
            if (!d.analysed) d.cholmod.analyzePattern(A);
            d.cholmod.factorize(A);
            ok = d.cholmod.info() == Eigen::Success;
        } else {
            if (!d.analysed) d.ldlt.analyzePattern(A);
            d.ldlt.factorize(A);
            ok = d.ldlt.info() == Eigen::Success;
        }
        if (!ok) throw Error("field", "sparse factorisation failed (the constrained system is singular: is some part "
                                      "of the solid without any boundary constraint?)");
        d.analysed = true;
        d.mw = mw;
        d.sw = sw;
    }
    Eigen::VectorXd rhs(d.offset[nv]);
    for (int v = 0; v < nv; ++v) {
        const auto P = basis(d.space, v);
        if (P.cols()) rhs.segment(d.offset[v], P.cols()) = P.transpose() * b.row(v).transpose();
    }
    const Eigen::VectorXd y = d.kind == SparseSolver::Cholmod ? Eigen::VectorXd(d.cholmod.solve(rhs))
                                                              : Eigen::VectorXd(d.ldlt.solve(rhs));
    for (int v = 0; v < nv; ++v) {
        const auto P = basis(d.space, v);
        const SH9 xv = P.cols() ? SH9(P * y.segment(d.offset[v], P.cols())) : SH9::Zero();
        x.row(v) = xv.transpose();
    }
    LinearSolveStats s;
    s.iterations = 1;
    return s;
}

}  // namespace framefix
