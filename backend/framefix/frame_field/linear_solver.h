#pragma once
// The one place that picks a sparse solver for the constrained diffusion systems
//   x in V,  Pi ((mass_weight M + stiff_weight K) x - b) = 0        (see constrained_space.h).
// ConjugateGradient works on full #V x 9 fields with the projector Pi (no reduced matrix is
// built: the nine channels share the scalar K, so one CSR SpMV serves all of them); the direct
// solvers assemble the reduced matrix P^T A P and refactorise it for each new weight pair.
// Internal to frame_field.
#include <memory>
#include <string>

#include "framefix/frame_field/coarse_correction.h"
#include "framefix/frame_field/constrained_space.h"

namespace framefix {

struct LinearSolveStats {
    int iterations = 0;            // CG iterations (1 for a direct solve)
    double relative_residual = 0;  // |Pi (b - A x)| / |Pi b| at exit
    bool converged = true;
};

class ConstrainedSolver {
public:
    // coarse_min_vertices: CG adds the coarse correction (coarse_correction.h) from this many
    // vertices on (0: never).
    ConstrainedSolver(const P1System& sys, const ConstrainedSpace& space, SparseSolver kind, int threads,
                      int coarse_min_vertices = 0);
    ~ConstrainedSolver();
    ConstrainedSolver(const ConstrainedSolver&) = delete;
    ConstrainedSolver& operator=(const ConstrainedSolver&) = delete;

    // x holds the warm start (in V) on entry and the solution on exit. tolerance: relative residual.
    LinearSolveStats solve(double mass_weight, double stiff_weight, const FrameCoefficients& b, FrameCoefficients& x,
                           double tolerance);
    std::string name() const;

    struct Direct;  // reduced matrix + factorisation (direct_solvers.cpp)
    struct CgWork {  // CG vectors kept across solves (at 1M tets each is 12 MB: re-allocating
        FrameCoefficients r, p, Ap;  // them per solve cost 10 % in page faults)
        Eigen::VectorXd inv_diag;
        std::unique_ptr<CoarseCorrection> coarse;  // null: Jacobi alone
        FrameCoefficients y;                       // #aggregates x 9, the coarse part of z
    };

private:
    const P1System& sys_;
    const ConstrainedSpace& space_;
    SparseSolver kind_;
    int threads_;
    std::unique_ptr<Direct, void (*)(Direct*)> direct_{nullptr, nullptr};
    CgWork work_;
};

LinearSolveStats solve_projected_cg(const P1System& sys, const ConstrainedSpace& space, double mass_weight,
                                    double stiff_weight, const FrameCoefficients& b, FrameCoefficients& x,
                                    double tolerance, int threads, ConstrainedSolver::CgWork& work);

}  // namespace framefix
