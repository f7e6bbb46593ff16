#include <gtest/gtest.h>

#include "framefix/mesh/tet_mesh.h"

namespace framefix {
namespace {

TEST(TetMeshBytes, EveryArrayComesBackExactly) {
    TetMesh m;
    m.points.resize(4, 3);
    m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.0 / 3;
    m.tets.resize(1, 4);
    m.tets << 0, 1, 2, 3;
    m.boundary_faces.resize(4, 3);
    m.boundary_faces << 1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1;
    m.face_tags = Eigen::VectorXi::LinSpaced(4, 1, 4);
    m.feature_edges.resize(1, 2);
    m.feature_edges << 0, 1;
    m.edge_tags = Eigen::VectorXi::Constant(1, 7);
    m.corner_vertices = Eigen::VectorXi::LinSpaced(4, 0, 3);
    m.size = 0.125;
    const TetMesh back = tet_mesh_from_bytes(tet_mesh_bytes(m));
    EXPECT_EQ(back.points, m.points);
    EXPECT_EQ(back.tets, m.tets);
    EXPECT_EQ(back.boundary_faces, m.boundary_faces);
    EXPECT_EQ(back.face_tags, m.face_tags);
    EXPECT_EQ(back.feature_edges, m.feature_edges);
    EXPECT_EQ(back.edge_tags, m.edge_tags);
    EXPECT_EQ(back.corner_vertices, m.corner_vertices);
    EXPECT_EQ(back.size, m.size);
}

}  // namespace
}  // namespace framefix
