// Blocks thinner than the mesh resolves (pipeline/thin_blocks.h): which faces get a finer mesh,
// and how fine, for singular curves and sheets placed by hand in the unit cube.
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

// The B-rep face whose triangles lie in the plane coordinate `axis` = `value`.
int face_at(const TetMesh& m, int axis, double value) {
    for (Eigen::Index b = 0; b < m.boundary_faces.rows(); ++b) {
        bool on = true;
        for (int k = 0; k < 3; ++k) on = on && std::abs(m.points(m.boundary_faces(b, k), axis) - value) < 1e-9;
        if (on) return m.face_tags[b];
    }
    return -1;
}

const SheetSoup kNoSheets;

// An interior curve (no end nodes) along y from `a` to `b`, points every 0.05.
SingularCurve curve_along_y(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    SingularCurve c;
    const int n = int(std::round((b - a).norm() / 0.05)) + 1;
    c.points.resize(n, 3);
    for (int i = 0; i < n; ++i) c.points.row(i) = (a + (b - a) * double(i) / (n - 1)).transpose();
    for (int i = 0; i + 2 < n; ++i) c.faces.push_back(i);
    return c;
}

TEST(ThinBlocks, ACurveNearAWallRefinesTheWallsWithinThreeH) {
    // 0.2 from x = 0 (2 h): that wall gets 0.2 / 3; its ends 0.2 from y = 0 and y = 1 refine those
    // walls to 0.2 / 3 as well; z = 0, z = 1 (0.5 away) and x = 1 (0.8) are beyond 3 h.
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.2, 0.2, 0.5}, {0.2, 0.8, 0.5}));
    const ThinFaces t = thin_block_faces(m, g, kNoSheets, kH);
    ASSERT_EQ(t.face_size.size(), 3u);
    for (auto [axis, value] : {std::pair{0, 0.0}, {1, 0.0}, {1, 1.0}}) {
        const int f = face_at(m, axis, value);
        ASSERT_TRUE(t.face_size.count(f)) << "axis " << axis << " at " << value;
        EXPECT_NEAR(t.face_size.at(f), 0.2 / 3, 1e-9);
    }
    EXPECT_NEAR(t.thinnest, 0.2, 1e-9);
    EXPECT_GT(estimate_thin_tets(m, t), double(m.num_tets()));
}

TEST(ThinBlocks, SizesStopAtAThirdOfH) {
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.07, 0.4, 0.5}, {0.07, 0.6, 0.5}));  // 0.7 h from x = 0
    const ThinFaces t = thin_block_faces(m, g, kNoSheets, kH);
    ASSERT_EQ(t.face_size.size(), 1u);
    EXPECT_NEAR(t.face_size.at(face_at(m, 0, 0.0)), kH / 3, 1e-9);
}

TEST(ThinBlocks, CurvesOnTheWallCurvesFarFromItAndRejectedPointsCountForNothing) {
    const TetMesh& m = cube_mesh().tets;
    SingularityGraph g;
    g.curves.push_back(curve_along_y({0.03, 0.4, 0.5}, {0.03, 0.6, 0.5}));  // on the wall: a snapped path
    g.curves.push_back(curve_along_y({0.5, 0.4, 0.5}, {0.5, 0.6, 0.5}));    // 5 h from every wall
    EXPECT_TRUE(thin_block_faces(m, g, kNoSheets, kH).face_size.empty());
    SingularityGraph near;
    near.curves.push_back(curve_along_y({0.2, 0.2, 0.5}, {0.2, 0.8, 0.5}));
    EXPECT_TRUE(thin_block_faces(m, near, kNoSheets, kH, [](const Eigen::Vector3d& p) { return p.y() > 0.9; }).face_size.empty());
    // Its half below y = 0.5 reaches the walls x = 0 and y = 0, not y = 1.
    EXPECT_EQ(thin_block_faces(m, near, kNoSheets, kH, [](const Eigen::Vector3d& p) { return p.y() < 0.5; }).face_size.size(), 2u);
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
    const ThinFaces t = thin_block_faces(m, g, kNoSheets, kH);
    ASSERT_EQ(t.face_size.size(), 1u);
    EXPECT_NEAR(t.thinnest, 0.16, 1e-9);
    EXPECT_NEAR(t.face_size.at(face_at(m, 0, 0.0)), 0.16 / 3, 1e-9);
}

// A square sheet 0.15 above the floor z = 0 and parallel to it is a cushion's top: the floor gets
// 0.15 / 3, and only the floor. The same square standing upright (across the floor) is no cushion.
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
    const ThinFaces flat = thin_block_faces(m, none, square(true), kH);
    ASSERT_EQ(flat.face_size.size(), 1u);
    EXPECT_NEAR(flat.face_size.at(face_at(m, 2, 0.0)), 0.05, 1e-9);
    EXPECT_EQ(flat.places, 2);
    EXPECT_TRUE(thin_block_faces(m, none, square(false), kH).face_size.empty());
}

// The cube's tets cut at x = cut: block 0 below (invalid, 4 faces: an under-faced slab), block 1
// above; block 0's boundary triangles as the blocks stage lists them.
BlockDecomposition slab_and_rest(const MeshStage& m, double cut) {
    BlockDecomposition b;
    b.count = 2;
    b.blocks.resize(2);
    b.boundary.resize(2);
    b.tet_block = Eigen::VectorXi::Ones(m.tets.num_tets());
    for (int t = 0; t < m.tets.num_tets(); ++t) {
        double x = 0;
        for (int k = 0; k < 4; ++k) x += m.tets.points(m.tets.tets(t, k), 0) / 4;
        if (x < cut) b.tet_block[t] = 0, b.blocks[0].tets.push_back(t);
        else b.blocks[1].tets.push_back(t);
    }
    b.blocks[0].faces = 4;
    b.blocks[1].faces = 6, b.blocks[1].valid = true;
    for (int t : b.blocks[0].tets)
        for (int k = 0; k < 4; ++k) {
            const int f = m.topology.tet_faces(t, k), a = tet_across(m.topology, f, t);
            if (a >= 0 && b.tet_block[a] == 0) continue;
            BoundaryTriangle tri;
            tri.verts = m.topology.faces.row(f).transpose();
            tri.label = a >= 0 ? 1 : -1;
            b.boundary[0].push_back(tri);
        }
    return b;
}

// A slab of tets against x = 0 about 1.5 h thick: every wall it touches (x = 0 and the four
// sides, not x = 1) gets edges of a third of its thickness. A slab 5 h thick is resolved.
TEST(ThinBlocks, AThinUnderFacedBlockRefinesTheWallsItTouches) {
    const MeshStage& m = cube_mesh();
    ThinFaces thin;
    add_thin_blocks(m.tets, m.topology, slab_and_rest(m, 0.15), kH, thin);
    ASSERT_EQ(thin.face_size.size(), 5u);
    EXPECT_FALSE(thin.face_size.count(face_at(m.tets, 0, 1.0)));
    for (const auto& [face, size] : thin.face_size) {
        EXPECT_GE(size, kH / 3 - 1e-12);
        EXPECT_LT(size, kResolvedThicknessH * kH / 3);
    }
    EXPECT_EQ(thin.places, 1);
    EXPECT_GT(thin.thinnest, 0);
    EXPECT_LT(thin.thinnest, 0.5 * kResolvedThicknessH * kH);
    ThinFaces none;
    add_thin_blocks(m.tets, m.topology, slab_and_rest(m, 0.5), kH, none);
    EXPECT_TRUE(none.face_size.empty());
}

// A run holding only what the choice between a first and a finer run reads.
RunResult scored_run(int curves_3_5, int count, int valid, int pairs, int conforming) {
    RunResult r;
    r.singularities.emplace();
    r.singularities->summary.curves_3_5 = curves_3_5;
    r.blocks.emplace();
    r.blocks->count = count, r.blocks->valid = valid, r.blocks->pairs = pairs, r.blocks->conforming_pairs = conforming;
    return r;
}

TEST(ThinBlocks, AFinerRunIsKeptForBetterBlocksButNeverWithA35CurveTheFirstRunHasNot) {
    const RunResult first = scored_run(0, 7, 7, 9, 8);
    EXPECT_TRUE(finer_run_better(scored_run(0, 7, 7, 9, 9), first));
    EXPECT_FALSE(finer_run_better(scored_run(0, 7, 6, 9, 9), first));
    EXPECT_FALSE(finer_run_better(scored_run(1, 6, 6, 8, 8), first)) << "all valid and conforming, round a 3-5 curve";
    EXPECT_TRUE(finer_run_better(scored_run(0, 8, 6, 9, 6), scored_run(1, 6, 6, 8, 8)));
}

}  // namespace
}  // namespace framefix
