// --mesher hxt on a PLC built in code: gmsh's HXT, in the framefix-hxt worker, fills the cube
// and keeps its surface, tags and corners exactly; a missing worker is a failed try, not a crash.
#include <cstdlib>
#include <set>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "framefix/hxt/hxt_tetrahedralize.h"
#include "framefix/mesh/keys.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {
namespace {

// Unit cube, each face split into 2 x 2 x 2 = 8 triangles around its centre point (HXT, as any
// Delaunay mesher, needs a surface fine enough for the size): tags 1..6 by face.
SurfaceMesh cube() {
    SurfaceMesh s;
    s.points.resize(8 + 6, 3);
    for (int i = 0; i < 8; ++i) s.points.row(i) = Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    // Each face: its 4 corners in outward counter-clockwise order.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    s.triangles.resize(24, 3);
    s.face_tags.resize(24);
    for (int f = 0; f < 6; ++f) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) c += s.points.row(faces[f][k]).transpose() / 4;
        s.points.row(8 + f) = c;
        for (int k = 0; k < 4; ++k) {
            s.triangles.row(4 * f + k) << faces[f][k], faces[f][(k + 1) % 4], 8 + f;
            s.face_tags(4 * f + k) = f + 1;
        }
    }
    s.feature_segments.resize(12, 2);
    s.feature_segments << 0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7;
    s.segment_tags = Eigen::VectorXi::LinSpaced(12, 1, 12);
    s.corner_points = Eigen::VectorXi::LinSpaced(8, 0, 7);
    return s;
}

MeshOptions hxt_options(double h) {
    MeshOptions o;
    o.size = h;
    o.mesher = Mesher::hxt;
    o.threads = 1;
    return o;
}

TEST(Hxt, FillsTheCubeWithPositiveTets) {
    const SurfaceMesh s = cube();
    const TetgenRun run = try_hxt(s, hxt_options(0.25));
    ASSERT_EQ(run.status, TetgenStatus::meshed) << run.message;
    const TetMesh& mesh = run.mesh;
    ASSERT_GT(mesh.num_tets(), 100);  // a cube of side 4 h
    double volume = 0;
    for (int t = 0; t < mesh.num_tets(); ++t) {
        EXPECT_GT(tet_volume(mesh, t), 0) << "tet " << t;
        volume += tet_volume(mesh, t);
    }
    EXPECT_NEAR(volume, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(mesh.size, 0.25);
    const double mean = mean_edge_length(mesh, build_topology(mesh));
    // The interior follows h, not the 0.5-0.7 surface edges alone (on a surface refined to h,
    // the samples get 0.98 h: tests/cli/test_mesher.py).
    EXPECT_GT(mean, 0.5 * 0.25);
    EXPECT_LT(mean, 1.3 * 0.25);
}

TEST(Hxt, KeepsTheSurfaceItsTagsAndCorners) {
    const SurfaceMesh s = cube();
    const TetgenRun run = try_hxt(s, hxt_options(0.25));
    ASSERT_EQ(run.status, TetgenStatus::meshed) << run.message;
    const TetMesh& mesh = run.mesh;
    ASSERT_TRUE(mesh.points.topRows(s.points.rows()).isApprox(s.points, 0.0));
    EXPECT_EQ(mesh.boundary_faces, s.triangles);
    EXPECT_EQ(mesh.face_tags, s.face_tags);
    EXPECT_EQ(mesh.feature_edges, s.feature_segments);
    EXPECT_EQ(mesh.corner_vertices, s.corner_points);
    // The tets' own boundary is exactly the surface.
    const TetTopology topo = build_topology(mesh);
    std::set<TriangleKey> tet_boundary, surface;
    for (int f = 0; f < int(topo.faces.rows()); ++f)
        if (topo.face_tets(f, 1) < 0) tet_boundary.insert(triangle_key(topo.faces(f, 0), topo.faces(f, 1), topo.faces(f, 2)));
    for (int t = 0; t < int(s.triangles.rows()); ++t)
        surface.insert(triangle_key(s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)));
    EXPECT_EQ(tet_boundary, surface);
}

TEST(Hxt, OneThreadGivesTheSameMeshTwice) {
    const SurfaceMesh s = cube();
    const TetgenRun a = try_hxt(s, hxt_options(0.3)), b = try_hxt(s, hxt_options(0.3));
    ASSERT_EQ(a.status, TetgenStatus::meshed);
    ASSERT_EQ(b.status, TetgenStatus::meshed);
    EXPECT_EQ(a.mesh.tets, b.mesh.tets);
    EXPECT_EQ(a.mesh.points, b.mesh.points);
}

TEST(Hxt, AMissingWorkerIsAFailedTryNamingIt) {
    setenv("FRAMEFIX_HXT_WORKER", "/nonexistent/framefix-hxt", 1);
    const TetgenRun run = try_hxt(cube(), hxt_options(0.25));
    unsetenv("FRAMEFIX_HXT_WORKER");
    EXPECT_EQ(run.status, TetgenStatus::crashed);
    EXPECT_NE(run.message.find("cannot run /nonexistent/framefix-hxt"), std::string::npos) << run.message;
}

TEST(Hxt, AnOpenSurfaceIsAFailedTry) {
    SurfaceMesh s = cube();
    s.triangles.conservativeResize(20, 3);  // the last face removed: not closed
    s.face_tags.conservativeResize(20);
    const TetgenRun run = try_hxt(s, hxt_options(0.25));
    EXPECT_NE(run.status, TetgenStatus::meshed);
    EXPECT_FALSE(run.message.empty());
}

}  // namespace
}  // namespace framefix
