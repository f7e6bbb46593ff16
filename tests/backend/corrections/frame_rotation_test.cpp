// Locality measure: frame rotation modulo the cube group.
#include <gtest/gtest.h>

#include <cmath>

#include "framefix/corrections/snapping.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

FrameField rotated(const FrameField& f, const Eigen::Matrix3d& Q, int vertices_to_rotate) {
    FrameField g = f;
    for (int v = 0; v < vertices_to_rotate; ++v) {
        Eigen::Matrix3d R;
        for (int k = 0; k < 3; ++k) R.col(k) = f.axes.row(v).segment<3>(3 * k).transpose();
        R = Q * R;
        for (int k = 0; k < 3; ++k) g.axes.row(v).segment<3>(3 * k) = R.col(k).transpose();
    }
    return g;
}

Eigen::Matrix3d rot_z(double degrees) {
    return Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

TEST(FrameRotation, CubeSymmetriesDoNotCount) {
    const test::Cube c = test::cube_tets(2);
    const FrameField after = rotated(c.field, rot_z(90), c.mesh.num_vertices());
    EXPECT_LT(frame_rotation_degrees(c.field, after).maxCoeff(), 1e-6);
    EXPECT_EQ(rotated_fraction(c.field, c.field), 0.0);
}

TEST(FrameRotation, MeasuresTheSmallestRotation) {
    const test::Cube c = test::cube_tets(2);
    const int nv = c.mesh.num_vertices();
    const FrameField after = rotated(c.field, rot_z(30), nv / 3);
    const Eigen::VectorXd d = frame_rotation_degrees(c.field, after);
    EXPECT_NEAR(d(0), 30, 1e-6);
    const FrameField after70 = rotated(c.field, rot_z(70), 1);
    EXPECT_NEAR(frame_rotation_degrees(c.field, after70)(0), 20, 1e-6);  // 70 = 90 - 20
    EXPECT_NEAR(rotated_fraction(c.field, after, 10), double(nv / 3) / nv, 1e-12);
    EXPECT_EQ(rotated_fraction(c.field, after, 45), 0.0);
}

}  // namespace
}  // namespace framefix
