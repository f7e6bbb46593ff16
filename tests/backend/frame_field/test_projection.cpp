#include <random>

#include <gtest/gtest.h>

#include "framefix/frame_field/projection.h"

namespace framefix {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

TEST(Projection, RecoversRotationsModuloTheCubeGroup) {
    std::mt19937 rng(11);
    for (int i = 0; i < 300; ++i) {
        const Eigen::Matrix3d R = random_rotation(rng);
        const ProjectedFrame p = project_frame(frame_from_rotation(R));
        EXPECT_LT(p.distance, 1e-9);
        EXPECT_LT((match_frame(R, p.rotation) - R).norm(), 1e-7);
    }
}

TEST(Projection, NeverWorseThanTheBestOf2000RandomRotations) {
    std::mt19937 rng(13);
    std::normal_distribution<double> n;
    std::vector<SH9> samples;
    for (int k = 0; k < 2000; ++k) samples.push_back(frame_from_rotation(random_rotation(rng)));
    for (int i = 0; i < 200; ++i) {
        SH9 q;
        for (int c = 0; c < 9; ++c) q(c) = n(rng);
        const SH9 qn = q.normalized();
        double best = -2;
        for (const SH9& s : samples) best = std::max(best, qn.dot(s));
        const ProjectedFrame p = project_frame(q);
        EXPECT_GE(qn.dot(p.q), best - 1e-12);
        EXPECT_NEAR(p.distance, (qn - p.q).norm(), 1e-9);
    }
}

TEST(Projection, WarmStartConvergesToTheNearbyFrame) {
    std::mt19937 rng(17);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Matrix3d R = random_rotation(rng);
        const Eigen::Matrix3d warm = Eigen::AngleAxisd(0.2, Eigen::Vector3d(1, 2, 3).normalized()) * R;
        const ProjectedFrame p = project_frame_from(frame_from_rotation(R), warm);
        EXPECT_LT(p.distance, 1e-9);
        EXPECT_LT((match_frame(R, p.rotation) - R).norm(), 1e-7);
    }
}

TEST(Projection, ZeroVectorIsUndefined) {
    EXPECT_FALSE(project_frame(SH9::Zero()).defined);
}

TEST(Projection, ClosestDirectionAndMatch) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d d = closest_direction(Eigen::Vector3d(-1, 0.1, 0), R);
    EXPECT_LT((d + R.col(0)).norm(), 1e-15);
    const Eigen::Matrix3d g = octahedral_group()[7];
    EXPECT_LT((match_frame(R, R * g) - R).norm(), 1e-12);
    EXPECT_EQ(match_index(R, R), 0);
}

}  // namespace
}  // namespace framefix
