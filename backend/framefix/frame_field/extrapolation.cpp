#include "framefix/frame_field/extrapolation.h"

#include <algorithm>
#include <utility>

namespace framefix {
namespace {

constexpr double kDriftCosine = 0.9;  // two steps at least this aligned (M inner product) drift together
constexpr double kMaxGrowth = 1.1;    // a step more than this larger than the last is no steady drift
constexpr double kFirstJump = 8.0;    // the first trial goes at most this many steps ahead
constexpr double kMaxJump = 64.0;     // and the doubling stops here: the drift is only nearly linear
// Only vertices whose step is at least this fraction of the largest one jump: the drift sits near
// the singular curves; re-projecting the whole field per trial added 9 % to the field time of the
// 55-model sweep, the moving vertices alone 4 %.
constexpr double kMovingFraction = 1e-2;

}  // namespace

FloorExtrapolation::FloorExtrapolation(const P1System& sys, Projector project, int threads)
    : sys_(sys), project_(std::move(project)), threads_(threads), max_jump_(kMaxJump) {}

bool FloorExtrapolation::after_step(const FrameCoefficients& previous, FrameCoefficients& next,
                                    std::vector<Eigen::Matrix3d>& R) {
    step_ = next - previous;
    const FrameCoefficients none;
    const double a = mass_norm_diff(sys_, step_, none, threads_);
    auto cosine_with = [&](const FrameCoefficients& other, double& b) {
        b = mass_norm_diff(sys_, other, none, threads_);
        const double d = mass_norm_diff(sys_, step_, other, threads_);
        return a > 0 && b > 0 ? (a * a + b * b - d * d) / (2 * a * b) : 0.0;
    };
    double b = 0;
    if (jumped_ && cosine_with(last_, b) < 0) {
        // MBO walks back after the jump: its fixed point is not the energy's minimum along the
        // drift (MBO does not descend the energy). Later jumps go at most half as far.
        max_jump_ = last_jump_ / 2;
    }
    bool jumped = false;
    if (have_last_ && !jumped_) {
        const double cosine = cosine_with(last_, b);
        if (cosine >= kDriftCosine && a <= kMaxGrowth * b && max_jump_ >= 1) jumped = jump(a / b, next, R);
    }
    have_last_ = true;
    jumped_ = jumped;
    last_.swap(step_);  // after a jump: the step jumped along, for the walk-back check
    return jumped;
}

// Aitken: a linear iteration whose steps shrink by r each has its fixed point r / (1 - r) steps
// beyond the last one. A drift at about constant speed (r ~ 1) gives no such estimate, so the
// jump doubles while the energy keeps falling, up to max_jump_ steps.
bool FloorExtrapolation::jump(double ratio, FrameCoefficients& next, std::vector<Eigen::Matrix3d>& R) {
    double largest = 0;
    for (int v = 0; v < step_.rows(); ++v) largest = std::max(largest, step_.row(v).squaredNorm());
    moving_.clear();
    for (int v = 0; v < step_.rows(); ++v)
        if (step_.row(v).squaredNorm() >= kMovingFraction * kMovingFraction * largest) moving_.push_back(v);
    double best = dirichlet_energy(sys_, next, threads_);
    bool found = false;
    for (double w = std::min(ratio < 1 ? std::min(ratio / (1 - ratio), kFirstJump) : kFirstJump, max_jump_);
         w <= max_jump_; w *= 2) {
        trial_ = next;
        for (int v : moving_) trial_.row(v) += w * step_.row(v);
        R_trial_ = R;
        project_(trial_, R_trial_, moving_);
        const double e = dirichlet_energy(sys_, trial_, threads_);
        if (e >= best) break;
        best = e;
        found = true;
        last_jump_ = w;
        best_.swap(trial_);
        R_best_.swap(R_trial_);
    }
    if (found) {
        next.swap(best_);
        R.swap(R_best_);
    }
    return found;
}

}  // namespace framefix
