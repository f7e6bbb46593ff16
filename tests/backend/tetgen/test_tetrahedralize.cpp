// TetGen wrapper on PLCs built in code: a unit cube with tagged faces and feature edges.
#include <cstdlib>
#include <algorithm>
#include <set>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "framefix/core/error.h"
#include "framefix/mesh/boundary_surface.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

// Unit cube [0,1]^3 + offset: 8 corners, 12 outward triangles (face tags 1..6), 12 edges tagged 1..12.
SurfaceMesh cube(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
    SurfaceMesh s;
    s.points.resize(8, 3);
    for (int i = 0; i < 8; ++i) s.points.row(i) = Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1) + offset;
    s.triangles.resize(12, 3);
    s.triangles << 0, 2, 3, 0, 3, 1,  // z = 0
        4, 5, 7, 4, 7, 6,             // z = 1
        0, 1, 5, 0, 5, 4,             // y = 0
        2, 6, 7, 2, 7, 3,             // y = 1
        0, 4, 6, 0, 6, 2,             // x = 0
        1, 3, 7, 1, 7, 5;             // x = 1
    s.face_tags.resize(12);
    for (int t = 0; t < 12; ++t) s.face_tags(t) = t / 2 + 1;
    s.feature_segments.resize(12, 2);
    s.feature_segments << 0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7;
    s.segment_tags = Eigen::VectorXi::LinSpaced(12, 1, 12);
    s.corner_points = Eigen::VectorXi::LinSpaced(8, 0, 7);
    return s;
}

MeshOptions sized(double h) {
    MeshOptions o;
    o.size = h;
    return o;
}

TEST(Tetrahedralize, CubeTetsArePositiveAndFillTheCube) {
    const TetMesh mesh = tetrahedralize(cube(), sized(0.2));
    ASSERT_GT(mesh.num_tets(), 0);
    double volume = 0;
    for (int t = 0; t < mesh.num_tets(); ++t) {
        EXPECT_GT(tet_volume(mesh, t), 0) << "tet " << t;
        volume += tet_volume(mesh, t);
    }
    EXPECT_NEAR(volume, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(mesh.size, 0.2);
}

TEST(Tetrahedralize, BoundaryKeepsTagsAndPointsOutward) {
    const TetMesh mesh = tetrahedralize(cube(), sized(0.3));
    ASSERT_EQ(mesh.boundary_faces.rows(), 12);  // -Y: the input surface is kept as is
    const Eigen::Vector3d centre(0.5, 0.5, 0.5);
    for (int f = 0; f < 12; ++f) {
        const Eigen::Vector3d a = mesh.points.row(mesh.boundary_faces(f, 0)), b = mesh.points.row(mesh.boundary_faces(f, 1)),
                              c = mesh.points.row(mesh.boundary_faces(f, 2));
        const Eigen::Vector3d n = (b - a).cross(c - a);
        EXPECT_GT(n.dot((a + b + c) / 3 - centre), 0) << "face " << f;
        const int tag = mesh.face_tags(f);
        const int axis = (tag - 1) / 2;  // tags 1,2: z; 3,4: y; 5,6: x
        EXPECT_NEAR(std::abs(n.normalized()(2 - axis)), 1.0, 1e-12) << "face " << f << " tag " << tag;
    }
}

TEST(Tetrahedralize, FeatureEdgesAndCornersKept) {
    const SurfaceMesh s = cube();
    const TetMesh mesh = tetrahedralize(s, sized(0.3));
    ASSERT_EQ(mesh.feature_edges.rows(), 12);
    std::set<int> tags;
    for (int e = 0; e < 12; ++e) {
        tags.insert(mesh.edge_tags(e));
        const int i = mesh.edge_tags(e) - 1;
        const std::set<int> got = {mesh.feature_edges(e, 0), mesh.feature_edges(e, 1)};
        const std::set<int> want = {s.feature_segments(i, 0), s.feature_segments(i, 1)};
        EXPECT_EQ(got, want) << "Edge" << i + 1;
    }
    EXPECT_EQ(tags.size(), 12u);
    ASSERT_EQ(mesh.corner_vertices.rows(), 8);
    for (int c = 0; c < 8; ++c) EXPECT_EQ(mesh.points.row(mesh.corner_vertices(c)), s.points.row(c));
}

TEST(Tetrahedralize, DefaultSizeFromTargetTets) {
    MeshOptions o;
    o.target_tets = 2000;
    const TetMesh mesh = tetrahedralize(cube(), o);
    EXPECT_NEAR(mesh.size, size_for_tets(1.0, 2000), 1e-12);
}

TEST(Tetrahedralize, RefusesSizesBeyondMemory) {
    MeshOptions o = sized(0.001);
    o.max_memory_mb = 1000;
    try {
        tetrahedralize(cube(), o);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "mesh");
        EXPECT_NE(e.message().find("size 0.001 needs about 1.2e+10 tets (~4596 GB, limit 1000 MB)"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("use --size 0.018 or larger"), std::string::npos) << e.what();
    }
}

TEST(Tetrahedralize, SuggestedSizeIsAccepted) {
    MeshOptions o = sized(0.018);
    o.max_memory_mb = 1000;
    EXPECT_NO_THROW(check_memory(1.0, o.size, o));
}

TEST(Tetrahedralize, OpenSurfaceIsRefused) {
    SurfaceMesh s = cube();
    s.triangles.conservativeResize(10, 3);  // drop the x = 1 side
    s.face_tags.conservativeResize(10);
    EXPECT_THROW(tetrahedralize(s, sized(0.3)), Error);
}

TEST(Tetrahedralize, SelfIntersectingSurfaceIsReported) {
    // Two overlapping cubes given as one surface.
    const SurfaceMesh a = cube(), b = cube(Eigen::Vector3d(0.5, 0.3, 0.2));
    SurfaceMesh s;
    s.points.resize(16, 3);
    s.points << a.points, b.points;
    s.triangles.resize(24, 3);
    s.triangles << a.triangles, (b.triangles.array() + 8).matrix();
    s.face_tags.resize(24);
    s.face_tags << a.face_tags, b.face_tags;
    s.corner_points = Eigen::VectorXi::LinSpaced(16, 0, 15);
    try {
        tetrahedralize(s, sized(0.3));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "mesh");
        EXPECT_NE(e.message().find("self-intersects"), std::string::npos) << e.what();
    }
    const TetgenRun run = try_tetrahedralize(s, sized(0.3), true);
    EXPECT_EQ(run.status, TetgenStatus::self_intersecting);
    EXPECT_NE(run.message.find("on Face"), std::string::npos) << run.message;  // where to look
    EXPECT_NE(run.message.find("near ("), std::string::npos) << run.message;
}

// Without -Y TetGen may split boundary triangles and segments; every piece keeps its tag.
TEST(Tetrahedralize, BoundarySteinerPointsKeepTags) {
    const SurfaceMesh s = cube();
    const TetgenRun run = try_tetrahedralize(s, sized(0.15), false);
    ASSERT_EQ(run.status, TetgenStatus::meshed) << run.message;
    const TetMesh& mesh = run.mesh;
    EXPECT_GT(mesh.boundary_faces.rows(), 12);  // split: the cube's faces are longer than 0.15
    double area = 0;
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d a = mesh.points.row(mesh.boundary_faces(f, 0)), b = mesh.points.row(mesh.boundary_faces(f, 1)),
                              c = mesh.points.row(mesh.boundary_faces(f, 2));
        const int tag = mesh.face_tags(f), axis = 2 - (tag - 1) / 2;  // tags 1,2: z; 3,4: y; 5,6: x
        const double side = (tag - 1) % 2;                             // the first of each pair is at 0
        for (const Eigen::Vector3d& p : {a, b, c}) EXPECT_NEAR(p(axis), side, 1e-12) << "face " << f << " tag " << tag;
        area += 0.5 * (b - a).cross(c - a).norm();
    }
    EXPECT_NEAR(area, 6.0, 1e-9);
    std::vector<double> length(13, 0.0);  // per edge tag: the pieces add up to the cube's edge
    for (int e = 0; e < mesh.feature_edges.rows(); ++e)
        length[size_t(mesh.edge_tags(e))] += (mesh.points.row(mesh.feature_edges(e, 0)) - mesh.points.row(mesh.feature_edges(e, 1))).norm();
    for (int tag = 1; tag <= 12; ++tag) EXPECT_NEAR(length[size_t(tag)], 1.0, 1e-9) << "Edge" << tag;
    for (int c = 0; c < 8; ++c) EXPECT_EQ(mesh.points.row(mesh.corner_vertices(c)), s.points.row(c));
}

// FRAMEFIX_FAULT makes the -Y run crash in its worker: reported as a crash, this process lives.
TEST(Tetrahedralize, CrashInTheWorkerIsAStatus) {
    ::setenv("FRAMEFIX_FAULT", "tetgen-keep-boundary", 1);
    const TetgenRun crashed = try_tetrahedralize(cube(), sized(0.3), true);
    const TetgenRun steiner = try_tetrahedralize(cube(), sized(0.3), false);
    ::unsetenv("FRAMEFIX_FAULT");
    EXPECT_EQ(crashed.status, TetgenStatus::crashed);
    EXPECT_NE(crashed.message.find("TetGen crashed (Segmentation fault)"), std::string::npos) << crashed.message;
    EXPECT_EQ(steiner.status, TetgenStatus::meshed) << steiner.message;
}

// The extrusions mesh the solid again from its own boundary with points inserted: the boundary
// comes back triangle for triangle with its tags, and every inserted point is a vertex.
TEST(Tetrahedralize, RemeshFromTheBoundaryKeepsItAndInsertsThePoints) {
    const TetMesh first = tetrahedralize(cube(), sized(0.25));
    const BoundarySurface b = boundary_surface(first);
    Points inserted(3, 3);
    inserted << 0.5, 0.5, 0.5, 0.31, 0.62, 0.47, 0.7, 0.2, 0.55;
    const TetMesh again = tetrahedralize(b.surface, sized(0.25), inserted);
    ASSERT_EQ(again.boundary_faces.rows(), first.boundary_faces.rows());
    std::multiset<int> tags_first(first.face_tags.data(), first.face_tags.data() + first.face_tags.size()),
        tags_again(again.face_tags.data(), again.face_tags.data() + again.face_tags.size());
    EXPECT_EQ(tags_first, tags_again);
    EXPECT_EQ(again.feature_edges.rows(), first.feature_edges.rows());
    for (int c = 0; c < 8; ++c) EXPECT_EQ(again.points.row(again.corner_vertices(c)), first.points.row(first.corner_vertices(c)));
    for (int i = 0; i < 3; ++i) {
        double nearest = 1e9;
        for (int v = 0; v < again.num_vertices(); ++v) nearest = std::min(nearest, (again.points.row(v) - inserted.row(i)).norm());
        EXPECT_EQ(nearest, 0.0) << "inserted point " << i;
    }
}

}  // namespace
}  // namespace framefix
