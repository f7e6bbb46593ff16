#pragma once
// Dirichlet frames along a snapped path (docs/algorithms.md#path-frames):
//   t_k = chord x_{k+w} - x_{k-w} (indices clamped), projected onto the tangent plane, unit;
//   n   = outward vertex normal (at a feature-curve end point: the next path vertex's normal);
//   a1 = t, a2 = cos(angle) n + sin(angle) (t x n), a3 = t x a2.
// At 45 deg the path behaves as a valence-1/3 "feature curve" on a smooth face: the frame is half
// way between the two ways a hex layer can meet the surface there. The sign of the angle does not
// matter (+-45 deg are the same frame modulo the cube group).
#include <vector>

#include <Eigen/Core>

#include "framefix/corrections/boundary_graph.h"

namespace framefix {

// One rotation per path vertex (columns a1 a2 a3), path.size() >= 2.
std::vector<Eigen::Matrix3d> path_frames(const Points& points, const BoundaryGraph& graph, const std::vector<int>& path,
                                         double angle_deg, int tangent_half_width);

}  // namespace framefix
