#include "framefix/singularities/polyline.h"

namespace framefix {

Points smooth_polyline(const std::vector<Eigen::Vector3d>& points, bool closed, int passes) {
    const int n = int(points.size());
    std::vector<Eigen::Vector3d> p = points, q(n);
    const bool smooth = n >= 3;
    for (int it = 0; smooth && it < passes; ++it) {
        for (int i = 0; i < n; ++i) {
            if (!closed && (i == 0 || i == n - 1)) {
                q[i] = p[i];
                continue;
            }
            const Eigen::Vector3d& prev = p[(i + n - 1) % n];
            const Eigen::Vector3d& next = p[(i + 1) % n];
            q[i] = (prev + 2 * p[i] + next) / 4;
        }
        std::swap(p, q);
    }
    const int rows = closed && n > 0 ? n + 1 : n;
    Points out(rows, 3);
    for (int i = 0; i < rows; ++i) out.row(i) = p[i % n].transpose();
    return out;
}

double polyline_length(const Points& points) {
    double len = 0;
    for (int i = 1; i < points.rows(); ++i) len += (points.row(i) - points.row(i - 1)).norm();
    return len;
}

Eigen::Vector3d mean_axis(const std::vector<Eigen::Vector3d>& axes) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& a : axes) sum += sum.dot(a) < 0 ? -a : a;
    const double norm = sum.norm();
    return norm > 0 ? Eigen::Vector3d(sum / norm) : Eigen::Vector3d::Zero();
}

}  // namespace framefix
