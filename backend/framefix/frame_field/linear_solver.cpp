#include "framefix/frame_field/linear_solver.h"

#include "framefix/core/error.h"

namespace framefix {

// Defined in direct_solvers.cpp (the only file that includes Eigen's sparse factorisations).
ConstrainedSolver::Direct* make_direct(const P1System& sys, const ConstrainedSpace& space,
                                                        SparseSolver kind);
LinearSolveStats solve_direct(ConstrainedSolver::Direct& d, double mw, double sw, const FrameCoefficients& b,
                              FrameCoefficients& x);
void destroy_direct(ConstrainedSolver::Direct* d);

ConstrainedSolver::ConstrainedSolver(const P1System& sys, const ConstrainedSpace& space, SparseSolver kind,
                                     int threads, int coarse_min_vertices)
    : sys_(sys), space_(space), kind_(kind), threads_(threads) {
    FF_ASSERT(sys.rows() == space.vertices());
    if (kind != SparseSolver::ConjugateGradient)
        direct_ = std::unique_ptr<Direct, void (*)(Direct*)>(make_direct(sys, space, kind), destroy_direct);
    else if (coarse_min_vertices > 0 && sys.rows() >= coarse_min_vertices) {
        work_.coarse = std::make_unique<CoarseCorrection>(sys, space);
        if (work_.coarse->aggregates() == 0) work_.coarse.reset();  // every vertex constrained
    }
}

ConstrainedSolver::~ConstrainedSolver() = default;

LinearSolveStats ConstrainedSolver::solve(double mw, double sw, const FrameCoefficients& b, FrameCoefficients& x,
                                          double tolerance) {
    if (kind_ == SparseSolver::ConjugateGradient)
        return solve_projected_cg(sys_, space_, mw, sw, b, x, tolerance, threads_, work_);
    return solve_direct(*direct_, mw, sw, b, x);
}

std::string ConstrainedSolver::name() const {
    switch (kind_) {
        case SparseSolver::ConjugateGradient:
            return work_.coarse ? "projected CG (Jacobi + coarse correction on " +
                                      std::to_string(work_.coarse->aggregates()) +
                                      " aggregates), 9 channels on one scalar CSR"
                                : "projected CG (Jacobi), 9 channels on one scalar CSR";
        case SparseSolver::SimplicialLDLT: return "Eigen SimplicialLDLT on the reduced system";
        case SparseSolver::Cholmod: return "CHOLMOD supernodal LLT on the reduced system";
    }
    return "?";
}

}  // namespace framefix
