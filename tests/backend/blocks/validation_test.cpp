// validate_block and check_conformity on blocks built in code: the cube grid of
// tests/backend/mesh/cube_fixture.h cut into blocks by the position of each tet's centroid, each
// block's boundary labelled the way build_blocks does (neighbour block, or -1 - cube face tag).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "backend/mesh/cube_fixture.h"
#include "framefix/blocks/validation.h"
#include "framefix/mesh/keys.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {
namespace {

struct Blocks {
    TetMesh mesh;
    std::vector<std::vector<BoundaryTriangle>> surface;  // per block
    double h = 0;
    std::vector<BlockInfo> info;
    std::vector<BlockFaces> faces;
};

Eigen::Vector3d point(const TetMesh& mesh, int v) { return mesh.points.row(v).transpose(); }

Eigen::Vector3d tet_centre(const TetMesh& mesh, int t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += point(mesh, mesh.tets(t, k)) / 4;
    return c;
}

// Splits `mesh` (boundary tagged) into blocks block_of(tet centre) = 0, 1, ... and validates each.
Blocks split(TetMesh mesh, const std::function<int(const Eigen::Vector3d&)>& block_of) {
    Blocks out;
    const TetTopology topo = build_topology(mesh);
    std::vector<int> block(mesh.num_tets());
    int count = 0;
    for (int t = 0; t < mesh.num_tets(); ++t) block[t] = block_of(tet_centre(mesh, t)), count = std::max(count, block[t] + 1);
    std::unordered_map<TriangleKey, int, TriangleKeyHash> tag_of;
    for (int b = 0; b < int(mesh.boundary_faces.rows()); ++b)
        tag_of[triangle_key(mesh.boundary_faces(b, 0), mesh.boundary_faces(b, 1), mesh.boundary_faces(b, 2))] = mesh.face_tags(b);
    out.surface.resize(count);
    for (int f = 0; f < int(topo.faces.rows()); ++f) {
        const int ta = topo.face_tets(f, 0), tb = topo.face_tets(f, 1);
        const int la = block[ta], lb = tb >= 0 ? block[tb] : -1;
        if (la == lb) continue;
        for (auto [t, b, other] : {std::array<int, 3>{ta, la, lb}, std::array<int, 3>{tb, lb, la}}) {
            if (b < 0) continue;
            BoundaryTriangle tri;
            tri.verts = topo.faces.row(f).transpose();
            tri.label = other >= 0 ? other : -1 - tag_of.at(triangle_key(tri.verts[0], tri.verts[1], tri.verts[2]));
            const Eigen::Vector3d p0 = point(mesh, tri.verts[0]);
            tri.normal = (point(mesh, tri.verts[1]) - p0).cross(point(mesh, tri.verts[2]) - p0);
            if (tri.normal.dot(p0 - tet_centre(mesh, t)) < 0) tri.normal = -tri.normal;
            out.surface[b].push_back(tri);
        }
    }
    out.h = mean_edge_length(mesh, topo, 1);
    out.info.resize(count);
    for (int b = 0; b < count; ++b) out.faces.push_back(validate_block(mesh, out.surface[b], out.h, BlockOptions{}, out.info[b]));
    out.mesh = std::move(mesh);
    return out;
}

// n = 12 keeps h ~ 0.11 well below the 1/2-wide faces used here (patch cleaning works in h).
constexpr int kCells = 12;

TetMesh tagged_l_prism(int n) {
    TetMesh mesh = testing::l_prism_tets(n);
    testing::tag_axis_faces(mesh);
    return mesh;
}

std::vector<BlockPair> conformity(const Blocks& b) { return check_conformity(b.faces, BlockOptions{}.conform_tolerance * b.h); }

TEST(ValidateBlock, CubeIsAHexahedron) {
    const Blocks b = split(testing::cube_tets(kCells).mesh, [](const Eigen::Vector3d&) { return 0; });
    const BlockInfo& info = b.info[0];
    EXPECT_TRUE(info.valid) << info.reason;
    EXPECT_TRUE(info.reason.empty());
    EXPECT_TRUE(info.manifold);
    EXPECT_EQ(info.euler, 2);
    EXPECT_EQ(info.faces, 6);
    EXPECT_EQ(info.edges, 12);
    EXPECT_EQ(info.corners, 8);
    EXPECT_EQ(info.flat_edges, 0);
    EXPECT_EQ(info.flat_corners, 0);
    ASSERT_EQ(b.faces[0].label.size(), 6u);
    for (size_t p = 0; p < 6; ++p) {
        EXPECT_LT(b.faces[0].label[p], 0) << "every face lies on the CAD boundary";
        EXPECT_EQ(b.faces[0].corners[p].size(), 4u);
    }
    EXPECT_TRUE(conformity(b).empty()) << "a single block has no neighbour";
}

TEST(ValidateBlock, LShapedBlockIsNotAHexahedron) {
    const Blocks b = split(tagged_l_prism(kCells), [](const Eigen::Vector3d&) { return 0; });
    const BlockInfo& info = b.info[0];
    EXPECT_FALSE(info.valid);
    EXPECT_EQ(info.reason, "faces 8");
    EXPECT_EQ(info.euler, 2);
    EXPECT_EQ(info.faces, 8);
    EXPECT_EQ(info.edges, 18);
    EXPECT_EQ(info.corners, 12);
}

// build_blocks validates a block again after dissolving a one-sided contact: a block that then
// passes must not keep the reason of its first validation.
TEST(ValidateBlock, AValidationAgainForgetsTheOldReason) {
    const Blocks l = split(tagged_l_prism(kCells), [](const Eigen::Vector3d&) { return 0; });
    const Blocks cube = split(testing::cube_tets(kCells).mesh, [](const Eigen::Vector3d&) { return 0; });
    BlockInfo info = l.info[0];
    ASSERT_FALSE(info.valid);
    validate_block(cube.mesh, cube.surface[0], cube.h, BlockOptions{}, info);
    EXPECT_TRUE(info.valid);
    EXPECT_EQ(info.reason, "");
}

// The chamfer_top sample with its x chamfers folded both ways: one face wraps the x sides and the
// top (8 corners), and the y sides' top strips are faces of 2 corners. Faces, edges, corners,
// their degrees and Euler's formula all match a hexahedron's; the faces' corners do not.
TEST(ValidateBlock, AFaceWrappingThreeSidesIsNoHexahedronFace) {
    TetMesh mesh = testing::cube_tets(kCells).mesh;
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) c += point(mesh, mesh.boundary_faces(f, k)) / 3;
        int& tag = mesh.face_tags(f);
        if (tag == 2 || tag == 6) tag = 1;                           // x-, x+ and the top: one face
        else if ((tag == 3 || tag == 4) && c.z() > 0.75) tag += 4;   // the y sides' top strips
    }
    const Blocks b = split(std::move(mesh), [](const Eigen::Vector3d&) { return 0; });
    const BlockInfo& info = b.info[0];
    EXPECT_EQ(info.faces, 6);
    EXPECT_EQ(info.edges, 12);
    EXPECT_EQ(info.corners, 8);
    EXPECT_EQ(info.euler, 2);
    EXPECT_FALSE(info.valid);
    EXPECT_EQ(info.reason, "a face has 2 corners");
}

TEST(CheckConformity, HalvesOfTheCubeShareOneFace) {
    const Blocks b = split(testing::cube_tets(kCells).mesh, [](const Eigen::Vector3d& c) { return c.x() < 0.5 ? 0 : 1; });
    for (const BlockInfo& info : b.info) EXPECT_TRUE(info.valid) << info.reason;
    const std::vector<BlockPair> pairs = conformity(b);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].a, 0);
    EXPECT_EQ(pairs[0].b, 1);
    EXPECT_TRUE(pairs[0].conforming) << pairs[0].reason;
    // The shared patch's corners are the four corners of the x = 1/2 square.
    for (const BlockFaces& f : b.faces)
        for (size_t p = 0; p < f.label.size(); ++p) {
            if (f.label[p] < 0) continue;
            ASSERT_EQ(f.corners[p].size(), 4u);
            for (const Eigen::Vector3d& c : f.corners[p]) {
                EXPECT_NEAR(c.x(), 0.5, 1e-9);
                EXPECT_TRUE(testing::on_01(c.y()) && testing::on_01(c.z())) << c.transpose();
            }
        }
}

TEST(CheckConformity, TJunctionLeavesTheLargeBlockInvalid) {
    // Block 0 is the left half; the right half is cut again at y = 1/2, so block 0's x = 1/2 face
    // is split in two: 7 faces (2 T corners more, 3 edges more), each pair still matching.
    const Blocks b = split(testing::cube_tets(kCells).mesh, [](const Eigen::Vector3d& c) {
        return c.x() < 0.5 ? 0 : c.y() < 0.5 ? 1 : 2;
    });
    EXPECT_FALSE(b.info[0].valid);
    EXPECT_EQ(b.info[0].reason, "faces 7");
    EXPECT_EQ(b.info[0].corners, 10);
    EXPECT_EQ(b.info[0].edges, 15);
    EXPECT_TRUE(b.info[1].valid) << b.info[1].reason;
    EXPECT_TRUE(b.info[2].valid) << b.info[2].reason;
    const std::vector<BlockPair> pairs = conformity(b);
    ASSERT_EQ(pairs.size(), 3u);
    for (const BlockPair& p : pairs) EXPECT_TRUE(p.conforming) << p.a << "-" << p.b << ": " << p.reason;
}

TEST(CheckConformity, TwoSeparateContactsDoNotConform) {
    // Block 0 is the two outer thirds (x < 1/3, x > 2/3), block 1 the middle slab: they share two
    // faces, which is not one hexahedron face on each side. n = 15 keeps the slabs 5 cells thick.
    const Blocks b = split(testing::cube_tets(15).mesh, [](const Eigen::Vector3d& c) {
        return c.x() < 1.0 / 3 || c.x() > 2.0 / 3 ? 0 : 1;
    });
    EXPECT_FALSE(b.info[0].valid);
    EXPECT_EQ(b.info[0].euler, 4) << "two spheres";
    EXPECT_TRUE(b.info[1].valid) << b.info[1].reason;
    const std::vector<BlockPair> pairs = conformity(b);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_FALSE(pairs[0].conforming);
    EXPECT_EQ(pairs[0].reason, "patches 2|2");
}

// Hand-made patches: check_conformity compares the corner sets of the one shared patch per side.
BlockFaces one_shared_patch(int neighbour, const std::vector<Eigen::Vector3d>& corners) {
    BlockFaces f;
    f.label = {-1, neighbour};
    f.corners = {{}, corners};
    return f;
}

std::vector<Eigen::Vector3d> unit_square(double z) {
    return {Eigen::Vector3d(0, 0, z), Eigen::Vector3d(1, 0, z), Eigen::Vector3d(1, 1, z), Eigen::Vector3d(0, 1, z)};
}

TEST(CheckConformity, CornersMustMatchWithinTheTolerance) {
    const std::vector<BlockFaces> faces = {one_shared_patch(1, unit_square(0)), one_shared_patch(0, unit_square(0.1))};
    const std::vector<BlockPair> close = check_conformity(faces, 0.15);
    ASSERT_EQ(close.size(), 1u);
    EXPECT_TRUE(close[0].conforming) << close[0].reason;
    const std::vector<BlockPair> far = check_conformity(faces, 0.05);
    ASSERT_EQ(far.size(), 1u);
    EXPECT_FALSE(far[0].conforming);
    EXPECT_EQ(far[0].reason.rfind("corner mismatch", 0), 0u) << far[0].reason;
}

TEST(CheckConformity, SharedPatchNeedsFourCornersOnEachSide) {
    std::vector<Eigen::Vector3d> triangle = unit_square(0);
    triangle.pop_back();
    const std::vector<BlockFaces> faces = {one_shared_patch(1, triangle), one_shared_patch(0, unit_square(0))};
    const std::vector<BlockPair> pairs = check_conformity(faces, 1.0);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_FALSE(pairs[0].conforming);
    EXPECT_EQ(pairs[0].reason, "corners 3|4");
}

TEST(CheckConformity, BlocksWithoutSharedPatchAreNoPair) {
    BlockFaces alone;
    alone.label = {-1, -2};
    alone.corners = {unit_square(0), unit_square(1)};
    EXPECT_TRUE(check_conformity({alone, alone}, 1.0).empty());
}

}  // namespace
}  // namespace framefix
