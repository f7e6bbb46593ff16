// The size model TetGen's callers size meshes with: estimate and inverse agree, the calibration
// constant is the one applied, and check_memory refuses with a size that would be accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framefix/core/error.h"
#include "framefix/mesh/size_model.h"
#include "framefix/mesh/surface_mesh.h"

namespace framefix {
namespace {

TEST(SizeModel, EstimateAndInverseAgree) {
    EXPECT_NEAR(estimate_tets(2.0, size_for_tets(2.0, 12345)), 12345, 1e-6);
    EXPECT_GT(estimate_memory_mb(1e6), estimate_memory_mb(1e5));
}

TEST(SizeModel, UsesTheTetGenCalibration) {
    const double h = 0.1;
    EXPECT_DOUBLE_EQ(estimate_tets(1.0, h), 1.0 / (kMeanTetVolumePerH3 * h * h * h));
}

TEST(SizeModel, DefaultTargetIsTheMeshOptionsDefault) {
    EXPECT_EQ(MeshOptions{}.target_tets, kDefaultTargetTets);
    EXPECT_EQ(MeshOptions{}.size, 0.0);
}

TEST(SizeModel, CheckMemorySuggestsAnAcceptedSize) {
    MeshOptions o;
    o.max_memory_mb = 1000;
    std::string message;
    try {
        check_memory(1.0, 0.001, o);
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "mesh");
        message = e.message();
    }
    const std::string marker = "use --size ";
    const size_t at = message.find(marker);
    ASSERT_NE(at, std::string::npos) << message;
    const double suggested = std::stod(message.substr(at + marker.size()));
    EXPECT_NO_THROW(check_memory(1.0, suggested, o));
    EXPECT_THROW(check_memory(1.0, 0.0, o), Error);
}

}  // namespace
}  // namespace framefix
