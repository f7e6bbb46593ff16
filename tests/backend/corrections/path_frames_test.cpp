// 45 deg Dirichlet frames along snapped paths.
#include <gtest/gtest.h>

#include <cmath>

#include "framefix/corrections/path_frames.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

const double kCos45 = std::sqrt(0.5);

void expect_rotation(const Eigen::Matrix3d& R) {
    EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

TEST(PathFrames, StraightPathHasAnAxisAlongItAndTheOthersAt45DegFromTheNormal) {
    const test::Cube c = test::cube_tets(6);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    std::vector<int> path;
    for (int j = 0; j <= 6; ++j) path.push_back(c.vertex(3, j, 0));  // x = 0.5 on z = 0, ends on features
    const auto frames = path_frames(c.mesh.points, g, path, 45, 2);
    ASSERT_EQ(frames.size(), path.size());
    const Eigen::Vector3d normal(0, 0, -1);
    for (const Eigen::Matrix3d& R : frames) {
        expect_rotation(R);
        EXPECT_NEAR(std::abs(R.col(0).dot(Eigen::Vector3d::UnitY())), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(R.col(1).dot(normal)), kCos45, 1e-12);
        EXPECT_NEAR(std::abs(R.col(2).dot(normal)), kCos45, 1e-12);
    }
}

TEST(PathFrames, ChordTangentsSmoothAZigZagPath) {
    const test::Cube c = test::cube_tets(8);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    // A staircase on z = 0 going along +x: raw tangents alternate between x and y.
    std::vector<int> path;
    for (int i = 1; i <= 6; ++i) path.push_back(c.vertex(i, 3 + (i % 2), 0)), path.push_back(c.vertex(i, 3 + ((i + 1) % 2), 0));
    const auto frames = path_frames(c.mesh.points, g, path, 45, 2);
    for (size_t k = 2; k + 2 < frames.size(); ++k) {
        expect_rotation(frames[k]);
        EXPECT_GT(std::abs(frames[k].col(0).x()), 0.85) << "vertex " << k;  // within ~30 deg of x
        EXPECT_NEAR(frames[k].col(0).z(), 0.0, 1e-12);                     // in the tangent plane
    }
}

TEST(PathFrames, FeatureEndPointUsesTheNeighbourNormal) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    // Starts on the edge y = 0, z = 0, whose averaged normal mixes -y and -z.
    const std::vector<int> path = {c.vertex(2, 0, 0), c.vertex(2, 1, 0), c.vertex(2, 2, 0)};
    const auto frames = path_frames(c.mesh.points, g, path, 45, 2);
    EXPECT_NEAR(std::abs(frames[0].col(1).z()), kCos45, 1e-12);
    EXPECT_NEAR(std::abs(frames[0].col(2).z()), kCos45, 1e-12);
    EXPECT_NEAR(std::abs(frames[0].col(0).y()), 1.0, 1e-12);
}

TEST(PathFrames, ZeroAngleGivesTheNormalAlignedFrame) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    const std::vector<int> path = {c.vertex(1, 2, 0), c.vertex(2, 2, 0), c.vertex(3, 2, 0)};
    for (const Eigen::Matrix3d& R : path_frames(c.mesh.points, g, path, 0, 2))
        EXPECT_NEAR(std::abs(R.col(1).z()), 1.0, 1e-12);
}

}  // namespace
}  // namespace framefix
