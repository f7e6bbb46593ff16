// fold_triangle_prisms on the cube grid of tests/backend/mesh/cube_fixture.h cut along a diagonal
// plane into two triangular prisms (a wedge each): its caps and two of its sides on the cube's
// boundary, the diagonal shared.
#include <gtest/gtest.h>

#include <unordered_map>
#include <vector>

#include "backend/mesh/cube_fixture.h"
#include "framefix/blocks/triangle_prisms.h"
#include "framefix/mesh/keys.h"

namespace framefix {
namespace {

constexpr int kCells = 12;  // h ~ 0.1, the wedges' sides 1 and 1.4 long

struct Wedges {
    TetMesh mesh;
    TetTopology topo;
    std::vector<int> group;  // per topology face: the cube face tag on the boundary, -1 inside
    double h = 0;
    BlockDecomposition blocks;
    Validated v;
};

Wedges diagonal_wedges() {
    Wedges w;
    w.mesh = testing::cube_tets(kCells).mesh;
    w.topo = build_topology(w.mesh);
    std::unordered_map<TriangleKey, int, TriangleKeyHash> tag_of;
    for (int b = 0; b < int(w.mesh.boundary_faces.rows()); ++b)
        tag_of[triangle_key(w.mesh.boundary_faces(b, 0), w.mesh.boundary_faces(b, 1), w.mesh.boundary_faces(b, 2))] =
            w.mesh.face_tags(b);
    w.group.assign(size_t(w.topo.faces.rows()), -1);
    for (int f = 0; f < int(w.topo.faces.rows()); ++f)
        if (w.topo.face_tets(f, 1) < 0)
            w.group[size_t(f)] = tag_of.at(triangle_key(w.topo.faces(f, 0), w.topo.faces(f, 1), w.topo.faces(f, 2)));
    w.h = mean_edge_length(w.mesh, w.topo, 1);
    w.blocks.count = 2;
    w.blocks.tet_block.resize(w.mesh.num_tets());
    for (int t = 0; t < w.mesh.num_tets(); ++t) {
        const Eigen::Vector3d c = tet_centroid(w.mesh, t);
        w.blocks.tet_block[t] = c.x() > c.y() ? 0 : 1;  // x = y runs along tet faces of the grid
    }
    w.v = validate_blocks(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks);
    count_conformity(w.v, w.h, BlockOptions{}, w.blocks);
    return w;
}

TEST(TrianglePrisms, EachWedgeSplitsABoundarySideAndBecomesAHexahedron) {
    Wedges w = diagonal_wedges();
    for (const BlockInfo& b : w.blocks.blocks) {
        ASSERT_FALSE(b.valid);
        ASSERT_EQ(b.reason, "faces 5");
        ASSERT_EQ(b.corners, 6);
    }
    fold_triangle_prisms(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks, w.v);
    EXPECT_EQ(w.blocks.triangle_folds, 2);
    EXPECT_EQ(w.blocks.valid, 2);
    EXPECT_EQ(w.blocks.conforming_pairs, 1) << "the diagonal keeps its 4 corners on both sides";
    for (int b = 0; b < 2; ++b) {
        const BlockInfo& info = w.blocks.blocks[size_t(b)];
        EXPECT_TRUE(info.valid) << info.reason;
        EXPECT_GE(info.flat_edges, 1) << "the split side meets itself at 180 degrees";
        const std::vector<int>& label = w.v.faces[size_t(b)].label;
        EXPECT_EQ(std::count(label.begin(), label.end(), 1 - b), 1) << "the shared diagonal is not split";
    }
}

TEST(TrianglePrisms, AHexahedronIsLeftAlone) {
    Wedges w = diagonal_wedges();
    w.blocks.tet_block.setZero();
    w.blocks.count = 1;
    w.v = validate_blocks(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks);
    count_conformity(w.v, w.h, BlockOptions{}, w.blocks);
    ASSERT_EQ(w.blocks.valid, 1);
    fold_triangle_prisms(w.mesh, w.topo, w.group, w.h, BlockOptions{}, w.blocks, w.v);
    EXPECT_EQ(w.blocks.triangle_folds, 0);
    EXPECT_EQ(w.v.faces[0].label.size(), 6u);
}

}  // namespace
}  // namespace framefix
