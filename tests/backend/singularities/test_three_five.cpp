// 3-5 classification of label chains (docs/algorithms.md#3-5-detection).
#include <gtest/gtest.h>

#include "framefix/singularities/three_five.h"

namespace framefix {
namespace {

std::vector<int> run(std::initializer_list<std::pair<int, int>> parts) {  // (label, count)
    std::vector<int> v;
    for (auto [label, n] : parts) v.insert(v.end(), n, label);
    return v;
}

TEST(ThreeFive, PureCurvesKeepTheirValence) {
    EXPECT_EQ(classify_labels(run({{3, 20}}), false, 5).kind, CurveKind::Valence3);
    EXPECT_EQ(classify_labels(run({{5, 20}}), false, 5).kind, CurveKind::Valence5);
    EXPECT_EQ(classify_labels(run({{3, 1}}), false, 5).kind, CurveKind::Valence3);
}

TEST(ThreeFive, IsolatedWrongLabelsAreSmoothedAway) {
    const std::vector<int> labels = {3, 3, 5, 3, 3, 3, 5, 3, 3, 3};
    EXPECT_EQ(smooth_labels(labels, 5, false), run({{3, 10}}));
    EXPECT_EQ(classify_labels(labels, false, 5).kind, CurveKind::Valence3);
}

TEST(ThreeFive, NotchLikeShortMinorityIsA35Curve) {
    // Notch: 3 val-3 + 29 val-5 triangles; no minimum run length.
    const LabelClass c = classify_labels(run({{3, 3}, {5, 29}}), false, 5);
    EXPECT_EQ(c.kind, CurveKind::ThreeFive);
    EXPECT_EQ(c.end_label[0], 3);
    EXPECT_EQ(c.end_label[1], 5);
    EXPECT_EQ(c.transition, 3);
}

TEST(ThreeFive, TwoTriangleTailIsA35Curve) {
    EXPECT_EQ(classify_labels(run({{5, 20}, {3, 2}}), false, 5).kind, CurveKind::ThreeFive);
}

TEST(ThreeFive, OneTriangleTailIsNot) {
    // Known limit (docs/algorithms.md#3-5-detection): a 1-triangle minority tail is smoothed away.
    EXPECT_EQ(classify_labels(run({{5, 20}, {3, 1}}), false, 5).kind, CurveKind::Valence5);
}

TEST(ThreeFive, TransitionAtTheBestCut) {
    const LabelClass c = classify_labels(run({{5, 10}, {3, 14}}), false, 5);
    EXPECT_EQ(c.kind, CurveKind::ThreeFive);
    EXPECT_EQ(c.transition, 10);
}

TEST(ThreeFive, SameLabelAtBothEndsIsNot35) {
    EXPECT_EQ(classify_labels(run({{3, 6}, {5, 8}, {3, 6}}), false, 5).kind, CurveKind::Valence3);
}

TEST(ThreeFive, ClosedMixedLoopIsADefectNot35) {
    const LabelClass c = classify_labels(run({{3, 10}, {5, 10}}), true, 5);
    EXPECT_EQ(c.kind, CurveKind::Other);
    EXPECT_EQ(c.transition, -1);
    EXPECT_EQ(classify_labels(run({{5, 12}}), true, 5).kind, CurveKind::Valence5);
}

TEST(ThreeFive, ClosedSmoothingWrapsAround) {
    // The lone 3 at index 0 is surrounded by 5s across the wrap.
    EXPECT_EQ(smooth_labels({3, 5, 5, 5, 5, 5}, 5, true), run({{5, 6}}));
    EXPECT_EQ(smooth_labels({3, 5, 5, 5, 5, 5}, 5, false)[0], 5);
}

}  // namespace
}  // namespace framefix
