// Point-to-segment and point-to-triangle distances (core/segment_distance.h) against hand values.
#include <gtest/gtest.h>

#include "framefix/core/segment_distance.h"

namespace framefix {
namespace {

using V = Eigen::Vector3d;

TEST(Distance, SegmentInsideAtTheEndsAndDegenerate) {
    const V a(0, 0, 0), b(2, 0, 0);
    EXPECT_DOUBLE_EQ(point_segment_distance(V(1, 3, 0), a, b), 3);       // beside its middle
    EXPECT_DOUBLE_EQ(point_segment_distance(V(-3, 4, 0), a, b), 5);      // past a: to a
    EXPECT_DOUBLE_EQ(point_segment_distance(V(5, 0, 4), a, b), 5);       // past b: to b
    EXPECT_DOUBLE_EQ(point_segment_distance(V(0, 0, 2), a, a), 2);       // a point
}

TEST(Distance, TriangleFaceSidesAndCorners) {
    const V a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
    EXPECT_DOUBLE_EQ(point_triangle_distance(V(1, 1, 2), a, b, c), 2);     // above the inside
    EXPECT_DOUBLE_EQ(point_triangle_distance(V(1, 1, -2), a, c, b), 2);    // below, either winding
    EXPECT_DOUBLE_EQ(point_triangle_distance(V(2, -3, 0), a, b, c), 3);    // beside side ab
    EXPECT_DOUBLE_EQ(point_triangle_distance(V(-3, -4, 0), a, b, c), 5);   // off corner a
    EXPECT_NEAR(point_triangle_distance(V(3, 3, 0), a, b, c), std::sqrt(2.0), 1e-12);  // beside bc
    EXPECT_DOUBLE_EQ(point_triangle_distance(V(1, 3, 0), a, b, V(2, 0, 0)), 3);  // degenerate: its sides
}

}  // namespace
}  // namespace framefix
