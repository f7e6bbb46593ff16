#pragma once
// Nearest-point queries on a fixed point set (a uniform hash grid). Used to stop streamlines near
// singular curves and by the block partition to find mesh edges near polylines.
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/types.h"

namespace framefix {

class PointGrid {
public:
    // `cell`: grid spacing in model units, about the typical query radius.
    PointGrid(const Points& points, double cell);
    // Index of the nearest point within `radius` of p, -1 if none.
    int nearest(const Eigen::Vector3d& p, double radius) const;
    // Indices of all points within `radius` of p.
    void within(const Eigen::Vector3d& p, double radius, std::vector<int>& out) const;
    bool empty() const { return points_.rows() == 0; }

private:
    long long key(int i, int j, int k) const;
    template <class F> void visit(const Eigen::Vector3d& p, double radius, F&& f) const;

    Points points_;                        // #P x 3, model units
    double cell_ = 1;
    Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
    Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
    std::vector<int> start_, items_;       // CSR over cells (dense: the grids here are small)
};

}  // namespace framefix
