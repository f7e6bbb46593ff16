// Locality of a correction: how far each vertex frame turned, modulo the cube group.
#include <algorithm>
#include <cmath>
#include <string>

#include <omp.h>

#include "framefix/core/error.h"
#include "framefix/corrections/snapping.h"
#include "framefix/frame_field/projection.h"

namespace framefix {

namespace {

Eigen::Matrix3d rotation_of(const FrameField& f, int v) {
    Eigen::Matrix3d R;
    for (int k = 0; k < 3; ++k) R.col(k) = f.axes.row(v).segment<3>(3 * k).transpose();
    return R;
}

}  // namespace

Eigen::VectorXd frame_rotation_degrees(const FrameField& before, const FrameField& after, int threads) {
    const int nv = int(before.axes.rows());
    if (after.axes.rows() != nv)
        throw Error("snap", "cannot compare fields with " + std::to_string(nv) + " and " +
                                std::to_string(after.axes.rows()) + " vertices; they must share the mesh");
    Eigen::VectorXd degrees(nv);
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
    for (int v = 0; v < nv; ++v) {
        const Eigen::Matrix3d Ra = rotation_of(before, v);
        // match_frame picks the cube-group representative of `after` closest to `before`.
        const Eigen::Matrix3d Rb = match_frame(Ra, rotation_of(after, v));
        const double c = std::clamp(((Ra.transpose() * Rb).trace() - 1) / 2, -1.0, 1.0);
        degrees(v) = std::acos(c) * 180.0 / M_PI;
    }
    return degrees;
}

double rotated_fraction(const FrameField& before, const FrameField& after, double threshold_deg, int threads) {
    const Eigen::VectorXd degrees = frame_rotation_degrees(before, after, threads);
    if (degrees.size() == 0) return 0;
    return double((degrees.array() > threshold_deg).count()) / double(degrees.size());
}

}  // namespace framefix
