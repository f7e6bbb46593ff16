// Boundary vertices near snapped paths.
#include "framefix/corrections/free_boundary.h"

#include <algorithm>

#include <omp.h>

namespace framefix {

std::vector<int> vertices_near_paths(const Points& points, const std::vector<int>& candidates,
                                     const std::vector<std::vector<int>>& paths, double radius,
                                     int threads) {
    struct Segment {
        Eigen::Vector3d a, b, lo, hi;  // end points and their box grown by the radius
    };
    std::vector<Segment> segments;
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius);
    auto add = [&](int va, int vb) {
        const Eigen::Vector3d a = points.row(va), b = points.row(vb);
        segments.push_back({a, b, a.cwiseMin(b) - r, a.cwiseMax(b) + r});
    };
    for (const auto& path : paths) {
        if (path.size() == 1) add(path[0], path[0]);
        for (size_t k = 0; k + 1 < path.size(); ++k) add(path[k], path[k + 1]);
    }
    std::vector<char> near(candidates.size(), 0);
    // A few thousand segments against the boundary vertices: the box test makes brute force cheap.
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
    for (int i = 0; i < int(candidates.size()); ++i) {
        const Eigen::Vector3d p = points.row(candidates[i]);
        for (const Segment& s : segments) {
            if ((p.array() < s.lo.array()).any() || (p.array() > s.hi.array()).any()) continue;
            if (point_segment_distance(p, s.a, s.b) <= radius) {
                near[i] = 1;
                break;
            }
        }
    }
    std::vector<int> result;
    for (size_t i = 0; i < candidates.size(); ++i)
        if (near[i]) result.push_back(candidates[i]);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
}

}  // namespace framefix
