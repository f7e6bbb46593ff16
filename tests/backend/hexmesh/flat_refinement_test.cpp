// The flat-edge template (docs/algorithms.md#flat-edge-refinement) on hand-made block complexes:
// a unit cube has nothing flat; a triangular prism seen as a block with a 180-degree edge is
// split into three blocks with proper corners; a neighbour across a face the template splits is
// split by a sheet; a flat edge running on into a block stacked on it refines both; a refinement
// whose hexes are not better is left, with the reason.
#include <gtest/gtest.h>

#include <map>
#include <set>

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

// Blocks over 8 corner positions each, sharing corners, edges and faces by position; a face of
// one block is on the boundary. Every face has two triangles; mesh vertices: the corners, then
// the edges' inner points.
struct Blocks {
    TetMesh mesh;
    BlockComplex cx;
    std::vector<Eigen::Vector3d> pts;
    std::map<std::pair<int, int>, int> edge_of;
    std::map<std::array<int, 4>, int> face_of;

    int corner(const Eigen::Vector3d& p) {
        for (int c = 0; c < int(cx.corners.size()); ++c)
            if ((cx.corners[size_t(c)].position - p).norm() < 1e-12) return c;
        cx.corners.push_back({p, {int(pts.size())}});
        pts.push_back(p);
        return int(cx.corners.size()) - 1;
    }
    void add(const std::array<Eigen::Vector3d, 8>& p) {
        ComplexBlock b;
        b.id = int(cx.blocks.size());
        for (int l = 0; l < 8; ++l) b.corners[size_t(l)] = corner(p[size_t(l)]);
        for (int e = 0; e < 12; ++e) {
            const auto l = edge_local_corners(e);
            const int x = std::min(b.corners[size_t(l[0])], b.corners[size_t(l[1])]), y = std::max(b.corners[size_t(l[0])], b.corners[size_t(l[1])]);
            auto [it, fresh] = edge_of.try_emplace({x, y}, int(cx.edges.size()));
            b.edges[size_t(e)] = it->second;
            if (!fresh) continue;
            ComplexEdge edge;
            edge.a = x, edge.b = y;
            edge.polyline.resize(kSegments + 1, 3);
            for (int s = 0; s <= kSegments; ++s) {
                const double f = double(s) / kSegments;
                const Eigen::Vector3d q = (1 - f) * cx.corners[size_t(x)].position + f * cx.corners[size_t(y)].position;
                edge.polyline.row(s) = q.transpose();
                if (s == 0 || s == kSegments) continue;
                edge.chain.push_back(int(pts.size()));
                pts.push_back(q);
            }
            cx.edges.push_back(edge);
        }
        for (int f = 0; f < 6; ++f) {
            const auto l = face_local_corners(f);
            std::array<int, 4> c{};
            for (int n = 0; n < 4; ++n) c[size_t(n)] = b.corners[size_t(l[size_t(n)])];
            std::array<int, 4> key = c;
            std::sort(key.begin(), key.end());
            auto [it, fresh] = face_of.try_emplace(key, int(cx.faces.size()));
            b.faces[size_t(f)] = it->second;
            if (fresh) {
                auto v = [&](int n) { return cx.corners[size_t(c[size_t(n)])].vertices[0]; };
                cx.faces.push_back({c, {{v(0), v(1), v(2)}, {v(0), v(2), v(3)}}, true});
            } else {
                cx.faces[size_t(it->second)].boundary = false;  // its second block
            }
        }
        cx.blocks.push_back(b);
        mesh.points.resize(Eigen::Index(pts.size()), 3);
        for (size_t i = 0; i < pts.size(); ++i) mesh.points.row(Eigen::Index(i)) = pts[i].transpose();
    }
};

bool keep_all(const BlockComplex&) { return true; }

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
    const FlatRefinement r = refine_flat_edges(one.mesh, 0.25, 50, 90, one.cx, keep_all);
    EXPECT_EQ(r.refined, 0);
    EXPECT_EQ(one.cx.blocks.size(), 1u);
}

TEST(FlatRefinement, APrismWithAFlatEdgeBecomesThreeProperBlocks) {
    OneBlock one(prism());
    const FlatCount before = count_flat(one.cx, 0.25, 35);
    EXPECT_EQ(before.edges, 1);    // the edge through B
    EXPECT_EQ(before.corners, 2);  // B at both ends
    const FlatRefinement r = refine_flat_edges(one.mesh, 0.25, 50, 90, one.cx, keep_all);
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

// Every block right-handed with no flat corner, the blocks tiling `volume`, every face used by
// one block (on the boundary) or two.
void expect_sound(const BlockComplex& cx, double volume) {
    double sum = 0;
    for (const ComplexBlock& b : cx.blocks) {
        const auto c = vtk_corners(cx, b);
        EXPECT_GT(hex_scaled_jacobian(c), 0.3) << "block " << b.id;
        sum += hex_volume(c);
    }
    EXPECT_NEAR(sum, volume, 1e-9);
    std::map<int, int> users;
    for (const ComplexBlock& b : cx.blocks)
        for (int f : b.faces) users[f] += 1;
    for (const auto& [f, n] : users) EXPECT_EQ(n, cx.faces[size_t(f)].boundary ? 1 : 2) << "face " << f;
}

// The prism and, across its face through A and D, a unit-thick box.
Blocks prism_and_box() {
    Blocks b;
    const std::array<Eigen::Vector3d, 8> p = prism();
    b.add(p);
    const Eigen::Vector3d n = Eigen::Vector3d(1, 1, 0).normalized(), A = p[1], D = p[3], up(0, 0, 1);
    b.add({A, A + n, D, D + n, A + up, A + n + up, D + up, D + n + up});
    return b;
}

TEST(FlatRefinement, ANeighbourAcrossASplitFaceIsSplitByASheet) {
    Blocks b = prism_and_box();
    const FlatRefinement r = refine_flat_edges(b.mesh, 0.25, 50, 90, b.cx, keep_all);
    ASSERT_EQ(r.refined, 1) << (r.skipped.empty() ? "" : r.skipped[0]);
    EXPECT_EQ(b.cx.blocks.size(), 5u) << "the template's three and the box's two halves";
    expect_sound(b.cx, 1.0 + std::sqrt(2.0));
    EXPECT_EQ(r.after.edges, 0);
}

TEST(FlatRefinement, AFlatEdgeRunningOnIntoABlockAboveRefinesBoth) {
    Blocks b;
    std::array<Eigen::Vector3d, 8> p = prism();
    b.add(p);
    for (Eigen::Vector3d& x : p) x.z() += 1;
    b.add(p);
    const FlatRefinement r = refine_flat_edges(b.mesh, 0.25, 50, 90, b.cx, keep_all);
    ASSERT_EQ(r.refined, 1) << (r.skipped.empty() ? "" : r.skipped[0]);
    EXPECT_EQ(b.cx.blocks.size(), 6u);
    expect_sound(b.cx, 2.0);
    EXPECT_EQ(r.after.edges, 0);
}

TEST(FlatRefinement, ARefinementWhoseHexesAreNotBetterIsLeftWithTheReason) {
    Blocks b = prism_and_box();
    const FlatRefinement r = refine_flat_edges(b.mesh, 0.25, 50, 90, b.cx, [](const BlockComplex&) { return false; });
    EXPECT_EQ(r.refined, 0);
    ASSERT_EQ(r.skipped.size(), 1u);
    EXPECT_NE(r.skipped[0].find("not better"), std::string::npos);
    EXPECT_EQ(b.cx.blocks.size(), 2u);
    EXPECT_EQ(r.after.edges, 1);
}

}  // namespace
}  // namespace framefix
