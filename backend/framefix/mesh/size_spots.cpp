#include "framefix/mesh/size_spots.h"

#include <algorithm>
#include <cmath>

namespace framefix {
namespace {

Eigen::Vector3i cell_of(const Eigen::Vector3d& p, double cell) {
    return {int(std::floor(p.x() / cell)), int(std::floor(p.y() / cell)), int(std::floor(p.z() / cell))};
}

}  // namespace

SizeField::SizeField(std::vector<SizeSpot> spots) : spots_(std::move(spots)) {
    double largest = 0;
    for (const SizeSpot& s : spots_) largest = std::max(largest, s.radius);
    if (largest > 0) cell_ = largest;
    for (int i = 0; i < int(spots_.size()); ++i) cells_[key(cell_of(spots_[size_t(i)].point, cell_))].push_back(i);
}

long long SizeField::key(const Eigen::Vector3i& c) const {
    // 21 bits per axis: cells within +-2^20 of the origin, far beyond any part at this cell size.
    constexpr long long kMask = (1LL << 21) - 1;
    return ((c.x() & kMask) << 42) | ((c.y() & kMask) << 21) | (c.z() & kMask);
}

double SizeField::at(const Eigen::Vector3d& p) const {
    if (spots_.empty()) return 0;
    const Eigen::Vector3i c = cell_of(p, cell_);
    double best = 0;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                if (it == cells_.end()) continue;
                for (int i : it->second) {
                    const SizeSpot& s = spots_[size_t(i)];
                    if ((p - s.point).norm() <= s.radius && (best == 0 || s.size < best)) best = s.size;
                }
            }
    return best;
}

}  // namespace framefix
