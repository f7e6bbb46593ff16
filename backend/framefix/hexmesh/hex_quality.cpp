#include <Eigen/Geometry>

#include "framefix/hexmesh/hexmesh.h"

namespace framefix {

namespace {
// Per VTK corner: its three neighbours, ordered so that a right-handed hex gives det > 0.
constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
}  // namespace

double hex_scaled_jacobian(const std::array<Eigen::Vector3d, 8>& p) {
    double worst = 1;
    for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d a = p[kCornerEdges[c][0]] - p[c], b = p[kCornerEdges[c][1]] - p[c], d = p[kCornerEdges[c][2]] - p[c];
        const double norms = a.norm() * b.norm() * d.norm();
        const double sj = norms > 0 ? a.dot(b.cross(d)) / norms : -1;
        worst = std::min(worst, sj);
    }
    return worst;
}

double hex_volume(const std::array<Eigen::Vector3d, 8>& p) {
    const double g = 0.5 / std::sqrt(3.0);  // Gauss points at 0.5 -+ g on [0, 1]
    double volume = 0;
    for (double u : {0.5 - g, 0.5 + g})
        for (double v : {0.5 - g, 0.5 + g})
            for (double w : {0.5 - g, 0.5 + g}) {
                // Derivatives of the trilinear map x(u, v, w) over VTK's corners.
                const Eigen::Vector3d du = (1 - v) * (1 - w) * (p[1] - p[0]) + v * (1 - w) * (p[2] - p[3]) +
                                           (1 - v) * w * (p[5] - p[4]) + v * w * (p[6] - p[7]);
                const Eigen::Vector3d dv = (1 - u) * (1 - w) * (p[3] - p[0]) + u * (1 - w) * (p[2] - p[1]) +
                                           (1 - u) * w * (p[7] - p[4]) + u * w * (p[6] - p[5]);
                const Eigen::Vector3d dw = (1 - u) * (1 - v) * (p[4] - p[0]) + u * (1 - v) * (p[5] - p[1]) +
                                           (1 - u) * v * (p[7] - p[3]) + u * v * (p[6] - p[2]);
                volume += du.dot(dv.cross(dw)) / 8;
            }
    return volume;
}

}  // namespace framefix
