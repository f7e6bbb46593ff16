#include "framefix/streamlines/point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace framefix {

PointGrid::PointGrid(const Points& points, double cell) : points_(points), cell_(std::max(cell, 1e-12)) {
    const int n = int(points.rows());
    if (n == 0) return;
    lo_ = points.colwise().minCoeff().transpose();
    const Eigen::Vector3d ext = points.colwise().maxCoeff().transpose() - lo_;
    // Coarsen huge grids: the dense CSR must stay small (<= ~4M cells).
    while ((ext / cell_).array().ceil().prod() > 4e6) cell_ *= 2;
    for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, int(std::ceil(ext[k] / cell_)) + 1);
    const long long ncell = (long long)dims_[0] * dims_[1] * dims_[2];
    start_.assign(ncell + 1, 0);
    std::vector<long long> keys(n);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d c = (points.row(i).transpose() - lo_) / cell_;
        keys[i] = key(int(c[0]), int(c[1]), int(c[2]));
        start_[keys[i] + 1] += 1;
    }
    for (long long c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
    items_.resize(n);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int i = 0; i < n; ++i) items_[fill[keys[i]]++] = i;
}

long long PointGrid::key(int i, int j, int k) const {
    i = std::clamp(i, 0, dims_[0] - 1), j = std::clamp(j, 0, dims_[1] - 1), k = std::clamp(k, 0, dims_[2] - 1);
    return ((long long)k * dims_[1] + j) * dims_[0] + i;
}

template <class F>
void PointGrid::visit(const Eigen::Vector3d& p, double radius, F&& f) const {
    if (points_.rows() == 0) return;
    Eigen::Vector3i a, b;
    for (int k = 0; k < 3; ++k) {
        a[k] = int(std::floor((p[k] - radius - lo_[k]) / cell_));
        b[k] = int(std::floor((p[k] + radius - lo_[k]) / cell_));
        if (b[k] < 0 || a[k] > dims_[k] - 1) return;
        a[k] = std::max(a[k], 0), b[k] = std::min(b[k], dims_[k] - 1);
    }
    for (int k = a[2]; k <= b[2]; ++k)
        for (int j = a[1]; j <= b[1]; ++j)
            for (int i = a[0]; i <= b[0]; ++i) {
                const long long c = key(i, j, k);
                for (int s = start_[c]; s < start_[c + 1]; ++s) f(items_[s]);
            }
}

int PointGrid::nearest(const Eigen::Vector3d& p, double radius) const {
    int best = -1;
    double d2 = radius * radius;
    visit(p, radius, [&](int i) {
        const double d = (points_.row(i).transpose() - p).squaredNorm();
        if (d <= d2) d2 = d, best = i;
    });
    return best;
}

void PointGrid::within(const Eigen::Vector3d& p, double radius, std::vector<int>& out) const {
    out.clear();
    visit(p, radius, [&](int i) {
        if ((points_.row(i).transpose() - p).squaredNorm() <= radius * radius) out.push_back(i);
    });
}

}  // namespace framefix
