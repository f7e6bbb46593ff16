#pragma once
// Projection of a 9-vector onto the frame manifold (docs/algorithms.md#projection-onto-frames): multi-start Riemannian
// Newton on SO(3). Also the axis queries that streamlines and holonomy need.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framefix/frame_field/sh.h"

namespace framefix {

struct ProjectedFrame {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // columns are the frame axes
    SH9 q = SH9::Zero();      // D(rotation) f_ref, unit norm
    double distance = 0;      // |q_in/|q_in| - q|, 0 on the manifold, ~0..1.3
    bool defined = true;      // false when |q_in| < 1e-8 (a singular point): then the warm start
                              // (or the identity) is returned with distance sqrt(2)
};

struct ProjectionOptions {
    int starts = 5;           // best candidates of the 48 fixed start rotations tried (top-3 misses ~0.2 % of random q; top-5 none)
    int starts_with_warm = 0; // candidates tried in addition to a warm start (MBO uses 1)
    int max_iterations = 20;
    double tolerance = 1e-10; // on the Riemannian gradient norm
};

ProjectedFrame project_frame(const SH9& q, const ProjectionOptions& options = {});
// One Newton run from `warm` (MBO, streamlines, holonomy: neighbouring frames are close).
// Plus options.starts_with_warm candidates; the best result wins.
ProjectedFrame project_frame_from(const SH9& q, const Eigen::Matrix3d& warm, const ProjectionOptions& options = {});
// warm == nullptr: as project_frame. Convenient in loops where only some points have a warm start.
ProjectedFrame project_frame_from(const SH9& q, const Eigen::Matrix3d* warm, const ProjectionOptions& options = {});

// The frame axis (column of R, with its sign) closest to v.
Eigen::Vector3d closest_direction(const Eigen::Vector3d& v, const Eigen::Matrix3d& R);
// R_b * g for the cube rotation g that brings frame b closest to frame a.
Eigen::Matrix3d match_frame(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb);
// Index into octahedral_group() of that g (maximises trace(Ra^T Rb g); 0 is the identity).
int match_index(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb);

}  // namespace framefix
