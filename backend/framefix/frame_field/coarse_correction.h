#pragma once
// Two-level additive preconditioner for projected CG (docs/algorithms.md#large-meshes):
//   z = D^-1 r + R^T A_c^-1 R r,   A_c = R (mass_weight M + stiff_weight K) R^T,
// R the 0/1 restriction onto aggregates of free vertices (two rounds of neighbour aggregation).
// R reads and R^T writes free vertices only, where the projector Pi is the identity, so the
// correction keeps the iterates in V; the nine channels share the scalar A_c. It removes the
// smooth modes that Jacobi leaves to hundreds of iterations when stiff_weight >> h^2 mass_weight.
// Internal to frame_field.
#include <memory>
#include <vector>

#include "framefix/frame_field/constrained_space.h"

namespace framefix {

class CoarseCorrection {
public:
    CoarseCorrection(const P1System& sys, const ConstrainedSpace& space);
    ~CoarseCorrection();
    CoarseCorrection(const CoarseCorrection&) = delete;
    CoarseCorrection& operator=(const CoarseCorrection&) = delete;

    int aggregates() const { return aggregates_; }
    // Factorises A_c for this weight pair (the pattern is analysed once).
    void factorize(double mass_weight, double stiff_weight);
    // y = A_c^-1 R r (#aggregates x 9); returns (R r) . y, the coarse part of r . z.
    double solve(const FrameCoefficients& r, FrameCoefficients& y);
    // -1 for vertices outside the coarse space (constrained ones).
    const std::vector<int>& aggregate_of() const { return aggregate_of_; }

    struct Factor;  // Eigen's sparse Cholesky (coarse_correction.cpp)

private:
    std::vector<int> aggregate_of_;  // #V
    int aggregates_ = 0;
    std::unique_ptr<Factor> factor_;
};

}  // namespace framefix
