// Geometric queries (brep/queries.cpp) on shapes whose measures are known.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "fixtures.h"
#include "framefix/brep/brep_model.h"

namespace framefix {
namespace {

std::vector<double> widths(const BrepModel& m) {
    std::vector<double> w;
    for (int f = 1; f <= m.num_faces; ++f) w.push_back(face_width(m, f));
    std::sort(w.begin(), w.end());
    return w;
}

TEST(FaceWidth, ABoxFaceGivesTwiceItsAreaOverItsPerimeter) {
    // 2 x 1 x 0.5: faces 1 x 0.5 (width 1/3), 2 x 0.5 (0.4) and 2 x 1 (2/3), two of each.
    const std::vector<double> w = widths(test::box(2, 1, 0.5));
    const std::vector<double> expected{1.0 / 3, 1.0 / 3, 0.4, 0.4, 2.0 / 3, 2.0 / 3};
    ASSERT_EQ(w.size(), expected.size());
    for (size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(w[i], expected[i], 1e-9) << "face " << i;
}

TEST(FaceWidth, ADiscGivesItsRadius) {
    // cylinder.step: radius 0.5, height 1; its two discs are its narrowest faces.
    const std::vector<double> w = widths(load_shape(test::sample("cylinder")));
    ASSERT_EQ(w.size(), 3u);
    EXPECT_NEAR(w[0], 0.5, 1e-6);
    EXPECT_NEAR(w[1], 0.5, 1e-6);
    EXPECT_GT(w[2], 0.5);
}

}  // namespace
}  // namespace framefix
