// Table of hex-meshable node types and the boundary rule (docs/algorithms.md#node-validity).
#include <gtest/gtest.h>

#include "framefix/singularities/node_validity.h"

namespace framefix {
namespace {

TEST(NodeValidity, TableSatisfiesEuler) {
    EXPECT_EQ(hex_node_types().size(), 11u);
    for (const auto& t : hex_node_types()) EXPECT_EQ(3 * t[0] + 2 * t[1] + t[2], 12);
}

TEST(NodeValidity, GenuineNodeTypesAreValid) {
    for (auto [n3, n5] : {std::pair{4, 0}, {2, 2}, {1, 3}, {2, 6}, {0, 4}, {0, 6}, {0, 8}, {0, 12}})
        EXPECT_TRUE(is_valid_interior_node(n3, n5)) << n3 << "," << n5;
}

TEST(NodeValidity, CurvePointsAreValid) {
    for (auto [n3, n5] : {std::pair{0, 0}, {2, 0}, {0, 2}}) EXPECT_TRUE(is_valid_interior_node(n3, n5));
}

TEST(NodeValidity, TransitionsAndDeadEndsAreInvalid) {
    for (auto [n3, n5] : {std::pair{1, 1}, {1, 0}, {0, 1}, {3, 0}, {3, 1}, {1, 2}, {4, 1}, {2, 1}, {0, 3}, {0, 5},
                          {6, 0}, {2, 4}})
        EXPECT_FALSE(is_valid_interior_node(n3, n5)) << n3 << "," << n5;
}

TEST(NodeValidity, SmoothBoundaryRule) {
    EXPECT_TRUE(is_valid_smooth_boundary_node(1, 0));   // surface index +1/4
    EXPECT_TRUE(is_valid_smooth_boundary_node(0, 1));   // surface index -1/4
    EXPECT_TRUE(is_valid_smooth_boundary_node(0, 2));
    EXPECT_FALSE(is_valid_smooth_boundary_node(1, 1));  // a 3-5 transition on the surface
    EXPECT_FALSE(is_valid_smooth_boundary_node(2, 0));
    EXPECT_FALSE(is_valid_smooth_boundary_node(0, 4));
}

}  // namespace
}  // namespace framefix
