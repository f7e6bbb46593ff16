#pragma once
// MBO extrapolation at the tau floor (docs/algorithms.md, "Extrapolation at the floor"; evaluated,
// off by default: FieldOptions::extrapolate). Internal to frame_field: at the floor MBO creeps,
// its steps pointing the same way for dozens of iterations while singular curves slide; a jump
// along that direction, kept only when it lowers the Dirichlet energy, skips those iterations.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "framefix/frame_field/constrained_space.h"
#include "framefix/frame_field/p1_system.h"

namespace framefix {

class FloorExtrapolation {
public:
    // Projects the given vertices of a field onto the frames their constraints allow, warm from
    // and updating R.
    using Projector =
        std::function<void(FrameCoefficients&, std::vector<Eigen::Matrix3d>&, const std::vector<int>& vertices)>;
    FloorExtrapolation(const P1System& sys, Projector project, int threads);

    // After a plain MBO step previous -> next (both projected, R the rotations of next): when this
    // step and the last one drift together, replace next and R by a jump further along the step.
    // Returns whether it jumped. The step after a jump is checked against it: when MBO walks
    // back, later jumps go at most half as far.
    bool after_step(const FrameCoefficients& previous, FrameCoefficients& next, std::vector<Eigen::Matrix3d>& R);

private:
    bool jump(double ratio, FrameCoefficients& next, std::vector<Eigen::Matrix3d>& R);

    const P1System& sys_;
    Projector project_;
    int threads_;
    FrameCoefficients step_, last_, trial_, best_;  // #V x 9 buffers kept across iterations
    std::vector<Eigen::Matrix3d> R_trial_, R_best_;
    std::vector<int> moving_;  // vertices whose step is not negligible: only they jump
    bool have_last_ = false;  // last_ holds the previous plain step
    bool jumped_ = false;     // the previous call jumped along last_
    double max_jump_;         // steps; halved each time MBO walks back after a jump
    double last_jump_ = 0;    // steps of the last jump kept
};

}  // namespace framefix
