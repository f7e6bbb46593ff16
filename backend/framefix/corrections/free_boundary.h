#pragma once
// Which boundary vertices lose their tangency constraint (docs/algorithms.md#free-boundary):
// those within Euclidean distance r of a snapped path polyline. Without this the 45 deg path
// frames and the normal-aligned frames next to them are incompatible and the solver keeps a
// singular arc along the path (r = 0 fails; 1..6 hb all work).
#include <vector>

#include <Eigen/Core>

#include "framefix/core/segment_distance.h"  // point_segment_distance, for callers
#include "framefix/mesh/types.h"

namespace framefix {

// Vertices of `candidates` within `radius` of any segment of any polyline (paths of vertex ids
// into `points`; a one-vertex path is a point). Ascending, without duplicates.
std::vector<int> vertices_near_paths(const Points& points, const std::vector<int>& candidates,
                                     const std::vector<std::vector<int>>& paths, double radius,
                                     int threads = 0);

}  // namespace framefix
