// Singular curves that emit no sheet (blocks/sheet_sources.h, boundary_wisps): from the boundary to
// the boundary and shorter than 1 h. A curve with an interior end, a closed loop, or one of 1 h or
// more keeps its sheets, however short.
#include <gtest/gtest.h>

#include "framefix/blocks/sheet_sources.h"

namespace framefix {
namespace {

constexpr double kH = 0.1;

// Node 0 and 1 on the boundary, node 2 inside.
SingularityGraph three_nodes() {
    SingularityGraph g;
    for (int i = 0; i < 3; ++i) {
        SingularNode n;
        n.id = i;
        n.boundary = i < 2;
        g.nodes.push_back(n);
    }
    return g;
}

// A straight curve along x of the given length between nodes a and b, in 4 segments.
void add_curve(SingularityGraph& g, double length, int a, int b, bool closed = false) {
    SingularCurve c;
    c.id = int(g.curves.size());
    c.kind = CurveKind::Valence5;
    c.points.resize(5, 3);
    for (int i = 0; i < 5; ++i) c.points.row(i) << length * i / 4, 0.1 * c.id, 0;
    c.ends[0] = closed ? -1 : a, c.ends[1] = closed ? -1 : b;
    c.closed = closed;
    g.curves.push_back(c);
}

TEST(BoundaryWisps, OnlyShortCurvesFromBoundaryToBoundary) {
    SingularityGraph g = three_nodes();
    add_curve(g, 0.65 * kH, 0, 1);         // 0: the groove's stub after snapping
    add_curve(g, 1.2 * kH, 0, 1);          // 1: long enough to keep its sheets
    add_curve(g, 0.4 * kH, 1, 2);          // 2: a stub at an interior node (rounded cubes' junctions)
    add_curve(g, 0.5 * kH, -1, -1, true);  // 3: a small closed loop
    add_curve(g, 0.9 * kH, 1, 0);          // 4: short, ends the other way round
    EXPECT_EQ(boundary_wisps(g, kH), (std::vector<int>{0, 4}));
}

TEST(BoundaryWisps, TheThresholdScalesWithTheMeshSize) {
    SingularityGraph g = three_nodes();
    add_curve(g, 0.15, 0, 1);
    EXPECT_EQ(boundary_wisps(g, 0.2), std::vector<int>{0});
    EXPECT_TRUE(boundary_wisps(g, 0.1).empty());
}

}  // namespace
}  // namespace framefix
