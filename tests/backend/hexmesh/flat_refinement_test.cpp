// The flat-edge template (docs/algorithms.md#flat-edge-refinement) on hand-made block complexes:
// a unit cube has nothing flat; a triangular prism seen as a block with a 180-degree edge is
// split into three blocks with proper corners; a block whose flat edge would need a sheet
// through a neighbour is left, with the reason.
#include <gtest/gtest.h>

#include <map>

#include "framefix/hexmesh/flat_refinement.h"
#include "framefix/hexmesh/hexmesh.h"

namespace framefix {
namespace {

constexpr int kSegments = 4;  // mesh edges along each block edge

// One block over 8 corner positions (local order i + 2 j + 4 k), straight edges of mesh
// vertices, boundary faces of two triangles each.
struct OneBlock {
    TetMesh mesh;
    BlockComplex cx;

    explicit OneBlock(const std::array<Eigen::Vector3d, 8>& p) {
        std::vector<Eigen::Vector3d> pts(p.begin(), p.end());
        for (int c = 0; c < 8; ++c) cx.corners.push_back({p[c], {c}});
        ComplexBlock b;
        b.id = 0;
        for (int c = 0; c < 8; ++c) b.corners[c] = c;
        for (int e = 0; e < 12; ++e) {
            const auto l = edge_local_corners(e);
            ComplexEdge edge;
            edge.a = std::min(l[0], l[1]), edge.b = std::max(l[0], l[1]);
            edge.polyline.resize(kSegments + 1, 3);
            for (int s = 0; s <= kSegments; ++s) {
                const double f = double(s) / kSegments;
                const Eigen::Vector3d x = (1 - f) * p[edge.a] + f * p[edge.b];
                edge.polyline.row(s) = x.transpose();
                if (s == 0 || s == kSegments) continue;
                edge.chain.push_back(int(pts.size()));
                pts.push_back(x);
            }
            b.edges[e] = int(cx.edges.size());
            cx.edges.push_back(edge);
        }
        for (int f = 0; f < 6; ++f) {
            const auto l = face_local_corners(f);
            ComplexFace face;
            face.corners = l;
            face.triangles = {{l[0], l[1], l[2]}, {l[0], l[2], l[3]}};
            face.boundary = true;
            b.faces[f] = int(cx.faces.size());
            cx.faces.push_back(face);
        }
        cx.blocks.push_back(b);
        mesh.points.resize(Eigen::Index(pts.size()), 3);
        for (size_t i = 0; i < pts.size(); ++i) mesh.points.row(Eigen::Index(i)) = pts[i].transpose();
    }
};

Eigen::Vector3d at(const BlockComplex& cx, const ComplexBlock& b, int l) { return cx.corners[b.corners[l]].position; }

// Corners of a complex block in VTK hex order, for hex_scaled_jacobian.
std::array<Eigen::Vector3d, 8> vtk_corners(const BlockComplex& cx, const ComplexBlock& b) {
    const int order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    std::array<Eigen::Vector3d, 8> out;
    for (int n = 0; n < 8; ++n) out[n] = at(cx, b, order[n]);
    return out;
}

// The prism x, y >= 0 side of the triangle (1,0), (0,1), (-1,0), z in [0, 1], as a block whose
// corner B = (0,0) sits flat on its long side: local (i, j) = B (0,0), A (1,0), C (0,1), D (1,1).
std::array<Eigen::Vector3d, 8> prism() {
    const Eigen::Vector3d B(0, 0, 0), A(1, 0, 0), C(-1, 0, 0), D(0, 1, 0), up(0, 0, 1);
    return {B, A, C, D, B + up, A + up, C + up, D + up};
}

TEST(FlatRefinement, AUnitCubeHasNoFlatEdgeAndStaysOneBlock) {
    std::array<Eigen::Vector3d, 8> p;
    for (int c = 0; c < 8; ++c) p[c] = Eigen::Vector3d(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    OneBlock one(p);
    const FlatCount n = count_flat(one.cx, 0.25, 35);
    EXPECT_EQ(n.edges, 0);
    EXPECT_EQ(n.corners, 0);
    const FlatRefinement r = refine_flat_edges(one.mesh, 0.25, 50, 90, one.cx);
    EXPECT_EQ(r.refined, 0);
    EXPECT_EQ(one.cx.blocks.size(), 1u);
}

TEST(FlatRefinement, APrismWithAFlatEdgeBecomesThreeProperBlocks) {
    OneBlock one(prism());
    const FlatCount before = count_flat(one.cx, 0.25, 35);
    EXPECT_EQ(before.edges, 1);    // the edge through B
    EXPECT_EQ(before.corners, 2);  // B at both ends
    const FlatRefinement r = refine_flat_edges(one.mesh, 0.25, 50, 90, one.cx);
    ASSERT_EQ(r.refined, 1) << (r.skipped.empty() ? "" : r.skipped[0]);
    ASSERT_EQ(one.cx.blocks.size(), 3u);
    EXPECT_EQ(r.after.edges, 0);
    EXPECT_EQ(r.after.corners, 0);
    double volume = 0;
    for (const ComplexBlock& b : one.cx.blocks) {
        const auto c = vtk_corners(one.cx, b);
        EXPECT_GT(hex_scaled_jacobian(c), 0.3) << "block " << b.id;  // right-handed, no flat corner
        volume += hex_volume(c);
    }
    EXPECT_NEAR(volume, 1.0, 1e-9);  // the three blocks tile the prism (area 1, height 1)
    // Every edge and face is used, each face by one block or two, and interfaces carry no triangles.
    std::map<int, int> face_users;
    for (const ComplexBlock& b : one.cx.blocks)
        for (int f : b.faces) face_users[f] += 1;
    EXPECT_EQ(face_users.size(), one.cx.faces.size());
    for (const auto& [f, users] : face_users) {
        EXPECT_EQ(users, one.cx.faces[size_t(f)].boundary ? 1 : 2);
        EXPECT_EQ(one.cx.faces[size_t(f)].boundary, !one.cx.faces[size_t(f)].triangles.empty());
    }
    // The new corners on the two split edges sit at their middle chain vertices.
    for (const Eigen::Vector3d m : {Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d(-0.5, 0.5, 1)}) {
        int found = 0;
        for (const ComplexCorner& c : one.cx.corners)
            found += (c.position - m).norm() < 1e-12 && c.vertices.size() == 1 &&
                     (one.mesh.points.row(c.vertices[0]).transpose() - m).norm() < 1e-12;
        EXPECT_EQ(found, 1) << m.transpose();
    }
}

TEST(FlatRefinement, AFlatEdgeWhoseOppositeFaceIsSharedIsLeftWithTheReason) {
    OneBlock one(prism());
    one.cx.faces[size_t(one.cx.blocks[0].faces[1])].boundary = false;  // i = 1: the face through A and D
    const FlatRefinement r = refine_flat_edges(one.mesh, 0.25, 50, 90, one.cx);
    EXPECT_EQ(r.refined, 0);
    ASSERT_EQ(r.skipped.size(), 1u);
    EXPECT_NE(r.skipped[0].find("shared with another block"), std::string::npos);
    EXPECT_EQ(one.cx.blocks.size(), 1u);
    EXPECT_EQ(r.after.edges, 1);
}

}  // namespace
}  // namespace framefix
