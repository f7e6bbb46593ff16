// Blocks thinner than the mesh resolves (pipeline/thin_blocks.h): where the surface gets shorter
// edges, and how short, for singular curves and sheets placed by hand in the unit cube.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/thin_blocks.h"

namespace framefix {
namespace {

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

constexpr double kH = 0.1;  // tet size of the cube's mesh

const MeshStage& cube_mesh() {
    static const RunResult r = [] {
        RunOptions o;
        o.stop_after = Stage::mesh;
        o.mesh.size = kH;
        return run(RunInput::file(sample("cube")), o);
    }();
    return *r.mesh;
}

// An interior curve (no end nodes) along y from `a` to `b`, points every 0.05.
SingularCurve curve_along_y(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int first_face = 0) {
    SingularCurve c;
    const int n = int(std::round((b - a).norm() / 0.05)) + 1;
    c.points.resize(n, 3);
    for (int i = 0; i < n; ++i) c.points.row(i) = (a + (b - a) * double(i) / (n - 1)).transpose();
    for (int i = 0; i + 2 < n; ++i) c.faces.push_back(first_face + i);
    return c;
}

const SheetSoup kNoSheets;

// The size the spots ask for at p (0: none).
double size_at(const ThinSpots& t, const Eigen::Vector3d& p) { return SizeField(t.spots).at(p); }

TEST(ThinBlocks, ACurveNearAWallRefinesTheWallUnderIt) {
    // 0.2 from x = 0 (2 h): the wall under it gets 0.2 / 3 within about h of the foot of each
    // curve point; z = 0, z = 1 (0.5 away) and x = 1 (0.8) get nothing.
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.2, 0.3, 0.5}, {0.2, 0.7, 0.5}));
    const ThinSpots t = thin_block_spots(m, g, kNoSheets, kH);
    ASSERT_EQ(t.spots.size(), 9u);
    EXPECT_NEAR(t.thinnest, 0.2, 1e-9);
    EXPECT_NEAR(size_at(t, {0, 0.5, 0.5}), 0.2 / 3, 1e-9);
    EXPECT_NEAR(size_at(t, {0, 0.5, 0.6}), 0.2 / 3, 1e-9);  // within d + h of a curve point
    EXPECT_EQ(size_at(t, {0, 0.5, 0.9}), 0);                 // beyond
    EXPECT_EQ(size_at(t, {0.5, 0.5, 0}), 0);
    EXPECT_EQ(size_at(t, {1, 0.5, 0.5}), 0);
    EXPECT_GT(estimate_thin_tets(m, SizeField(t.spots)), double(m.num_tets()));
}

TEST(ThinBlocks, SizesStopAtAThirdOfH) {
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.07, 0.4, 0.5}, {0.07, 0.6, 0.5}));  // 0.7 h from x = 0
    const ThinSpots t = thin_block_spots(m, g, kNoSheets, kH);
    ASSERT_FALSE(t.spots.empty());
    EXPECT_NEAR(size_at(t, {0, 0.5, 0.5}), kH / 3, 1e-9);
}

TEST(ThinBlocks, CurvesOnTheWallCurvesFarFromItAndRejectedPointsCountForNothing) {
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.03, 0.4, 0.5}, {0.03, 0.6, 0.5}));  // on the wall: a snapped path
    g.curves.push_back(curve_along_y({0.5, 0.4, 0.5}, {0.5, 0.6, 0.5}));    // 4 h from every wall
    EXPECT_TRUE(thin_block_spots(m, g, kNoSheets, kH).spots.empty());
    SingularityGraph near;
    near.curves.push_back(curve_along_y({0.2, 0.3, 0.5}, {0.2, 0.7, 0.5}));
    EXPECT_TRUE(thin_block_spots(m, near, kNoSheets, kH, [](const Eigen::Vector3d& p) { return p.y() > 0.8; }).spots.empty());
    EXPECT_EQ(thin_block_spots(m, near, kNoSheets, kH, [](const Eigen::Vector3d& p) { return p.y() < 0.5; }).spots.size(), 4u);
}

TEST(ThinBlocks, ACurveEnteringTheWallIsNotThinWhereItEnters) {
    // From x = 0.48 straight into the wall x = 0, points every 0.04: the last 1.5 h are where it
    // enters, not a thin block; the point 0.16 from its end is the nearest that counts.
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    SingularCurve c;
    c.points.resize(13, 3);
    for (int i = 0; i <= 12; ++i) c.points.row(i) << 0.48 - 0.04 * i, 0.5, 0.5;
    for (int i = 0; i < 11; ++i) c.faces.push_back(i);
    g.nodes.resize(2);
    g.nodes[1].boundary = true;
    c.ends[0] = 0, c.ends[1] = 1;
    g.curves.push_back(c);
    const ThinSpots t = thin_block_spots(m, g, kNoSheets, kH);
    EXPECT_NEAR(t.thinnest, 0.16, 1e-9);
    EXPECT_NEAR(size_at(t, {0, 0.5, 0.5}), 0.16 / 3, 1e-9);
}

// A square sheet 0.15 above the floor z = 0 and parallel to it is a cushion's top: the floor
// under it is refined. The same square standing upright (across the floor) is not.
TEST(ThinBlocks, OnlySheetsParallelToTheWallMakeACushion) {
    const TetMesh& m = cube_mesh().tets;
    auto square = [](bool flat) {
        SheetSoup s;
        s.points.resize(4, 3);
        if (flat) s.points << 0.3, 0.3, 0.15, 0.7, 0.3, 0.15, 0.7, 0.7, 0.15, 0.3, 0.7, 0.15;
        else s.points << 0.3, 0.5, 0.12, 0.7, 0.5, 0.12, 0.7, 0.5, 0.28, 0.3, 0.5, 0.28;
        s.triangles.resize(2, 3);
        s.triangles << 0, 1, 2, 0, 2, 3;
        return s;
    };
    const SingularityGraph none;
    const ThinSpots flat = thin_block_spots(m, none, square(true), kH);
    ASSERT_EQ(flat.spots.size(), 2u);
    EXPECT_NEAR(size_at(flat, {0.5, 0.5, 0}), 0.05, 1e-9);
    EXPECT_TRUE(thin_block_spots(m, none, square(false), kH).spots.empty());
}

}  // namespace
}  // namespace framefix
