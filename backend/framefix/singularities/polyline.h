#pragma once
// Display geometry of a singular curve: Laplacian-smoothed polyline, its length, and the stable
// direction (mean holonomy axis). Internal to singularities/, exposed for the tests.
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/types.h"

namespace framefix {

// `passes` passes of p_i <- (p_{i-1} + 2 p_i + p_{i+1}) / 4. Open polylines keep their two end
// points (they sit on nodes); closed ones are cyclic and the result repeats the first point at
// the end so that drawing it closes the loop.
Points smooth_polyline(const std::vector<Eigen::Vector3d>& points, bool closed, int passes);
double polyline_length(const Points& points);

// Mean of unit axes whose signs are aligned with the running sum (holonomy axes are only
// defined up to sign along a curve); unit length, or zero if `axes` is empty.
Eigen::Vector3d mean_axis(const std::vector<Eigen::Vector3d>& axes);

}  // namespace framefix
