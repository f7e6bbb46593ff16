// extract_singularities on fields from the real solver, on meshes built in code: a cube (and a
// rotated one) has no singular triangle; a cylinder has four valence-3 curves along its axis.
#include <gtest/gtest.h>

#include "backend/singularities/fixtures.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {
namespace {

SingularityGraph solve_and_extract(const TetMesh& mesh, const FeatureSet& features) {
    const TetTopology topo = build_topology(mesh);
    const FrameField field = solve_frame_field(mesh, topo, boundary_constraints(mesh, features));
    return extract_singularities(mesh, topo, field);
}

TEST(SolvedFields, CubeHasNoSingularTriangle) {
    const testing::Fixture fx = testing::cube_tets(6);
    const SingularityGraph g = solve_and_extract(fx.mesh, fx.features);
    EXPECT_EQ(g.summary.singular_faces, 0);
    EXPECT_EQ(g.summary.curves, 0);
    EXPECT_TRUE(g.summary.meshable);
}

TEST(SolvedFields, RotatedCubeHasNoSingularTriangle) {
    const testing::Fixture fx =
        testing::rotated(testing::cube_tets(5), testing::rot(Eigen::Vector3d(0.3, -1, 0.6), 0.9));
    EXPECT_EQ(solve_and_extract(fx.mesh, fx.features).summary.singular_faces, 0);
}

// Cylinder of radius 0.5 and the given height around the z axis: the m^3 grid stretched to
// [-1,1]^2 x [0,height], its cross-section squares |p|_inf = r mapped radially onto circles of radius r/2.
TetMesh cylinder_tets(int m, double height) {
    const TetMesh grid = testing::grid_tets(m, [](int, int, int) { return true; });
    Points P = grid.points;
    for (int v = 0; v < P.rows(); ++v) {
        const double x = 2 * P(v, 0) - 1, y = 2 * P(v, 1) - 1, r = std::hypot(x, y);
        const double s = r > 0 ? std::max(std::abs(x), std::abs(y)) / r : 1;
        P.row(v) << 0.5 * s * x, 0.5 * s * y, P(v, 2) * height;
    }
    TetMesh mesh = grid;
    mesh.points = P;
    return mesh;
}

TEST(SolvedFields, CylinderHasFourValence3CurvesAlongItsAxis) {
    const CreaseFeatures cf = detect_crease_features(cylinder_tets(10, 0.8));
    for (int t = 0; t < cf.mesh.num_tets(); ++t) ASSERT_GT(tet_volume(cf.mesh, t), 0);
    EXPECT_EQ(cf.features.curves(), 2);  // the two circles
    const SingularityGraph g = solve_and_extract(cf.mesh, cf.features);
    EXPECT_EQ(g.summary.curves, 4);
    EXPECT_EQ(g.summary.valence3, 4);
    EXPECT_EQ(g.summary.curves_3_5, 0);
    EXPECT_EQ(g.summary.invalid_nodes, 0);
    for (const SingularCurve& c : g.curves) {
        EXPECT_GT(std::abs(c.stable_direction.z()), 0.9);
        EXPECT_NEAR(c.length, 0.8, 0.15);
    }
}

}  // namespace
}  // namespace framefix
