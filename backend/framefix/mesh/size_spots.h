#pragma once
// Local edge lengths around points: a ball of `radius` about `point` asks for edges no longer than
// `size` (the blocks' thin-block refinement, docs/algorithms.md#thin-blocks). The surface
// refinement reads them; TetGen's quality bound grades the tets from the finer surface.
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace framefix {

struct SizeSpot {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // model units
    double radius = 0;                                 // model units
    double size = 0;                                   // edge length asked for inside, model units
};

// Lookup of the smallest size whose ball holds a point (a hash grid of cell = the largest radius).
class SizeField {
public:
    explicit SizeField(std::vector<SizeSpot> spots);
    // The smallest size of the spots whose ball holds p; 0 when none does.
    double at(const Eigen::Vector3d& p) const;
    bool empty() const { return spots_.empty(); }

private:
    long long key(const Eigen::Vector3i& c) const;
    std::vector<SizeSpot> spots_;
    double cell_ = 1;
    std::unordered_map<long long, std::vector<int>> cells_;
};

}  // namespace framefix
