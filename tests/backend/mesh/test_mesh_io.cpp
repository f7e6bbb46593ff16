#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "backend/mesh/cube_fixture.h"
#include "framefix/core/error.h"
#include "framefix/mesh/mesh_io.h"

namespace framefix {
namespace {

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "framefix_mesh_io_" + name; }

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

void expect_load_error(const std::string& path) {
    try {
        read_tet_mesh(path);
        FAIL() << path << " was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "load");
        EXPECT_FALSE(e.message().empty());
    }
}

void expect_same(const TetMesh& a, const TetMesh& b) {
    ASSERT_EQ(a.num_vertices(), b.num_vertices());
    ASSERT_EQ(a.num_tets(), b.num_tets());
    EXPECT_LT((a.points - b.points).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_TRUE(a.tets == b.tets);
    EXPECT_TRUE(a.boundary_faces == b.boundary_faces);
    EXPECT_TRUE(a.face_tags == b.face_tags);
}

TEST(MeshIo, CubeFixtureIsPositiveAndClosed) {
    const TetMesh m = testing::cube_tets(3).mesh;
    EXPECT_EQ(m.num_tets(), 6 * 27);
    EXPECT_EQ(m.boundary_faces.rows(), 6 * 9 * 2);
    for (int t = 0; t < m.num_tets(); ++t) EXPECT_GT(tet_volume(m, t), 0);
    // Outward: the boundary triangles enclose the unit volume (divergence theorem on x).
    double vol = 0;
    for (int f = 0; f < m.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d a = m.points.row(m.boundary_faces(f, 0)), b = m.points.row(m.boundary_faces(f, 1)),
                              c = m.points.row(m.boundary_faces(f, 2));
        vol += (b - a).cross(c - a).x() / 2 * (a.x() + b.x() + c.x()) / 3;
    }
    EXPECT_NEAR(vol, 1.0, 1e-12);
}

TEST(MeshIo, MshRoundTrip) {
    const TetMesh m = testing::cube_tets(2).mesh;
    const std::string path = temp_path("cube.msh");
    write_msh(m, path);
    expect_same(m, read_tet_mesh(path));
}

TEST(MeshIo, MeditRoundTrip) {
    const TetMesh m = testing::cube_tets(2).mesh;
    const std::string path = temp_path("cube.mesh");
    write_medit(m, path);
    expect_same(m, read_tet_mesh(path));
}

TEST(MeshIo, NegativeTetIsReoriented) {
    const std::string path = temp_path("neg.mesh");
    write_text(path, "MeshVersionFormatted 1\nDimension 3\n# one tet, given clockwise\nVertices\n4\n0 0 0 0\n1 0 0 0\n"
                     "0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 3 2 4 7\nEnd\n");
    const TetMesh m = read_tet_mesh(path);
    ASSERT_EQ(m.num_tets(), 1);
    EXPECT_NEAR(tet_volume(m, 0), 1.0 / 6.0, 1e-15);
    EXPECT_EQ(m.boundary_faces.rows(), 4);
}

TEST(MeshIo, MshWithGapsInNodeTagsAndTaggedTriangles) {
    const std::string path = temp_path("gaps.msh");
    write_text(path, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 5 10 50\n3 1 0 5\n10\n20\n30\n40\n50\n"
                     "0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n$EndNodes\n$Elements\n2 2 1 2\n2 7 2 1\n1 10 30 20\n"
                     "3 1 4 1\n2 10 20 30 40\n$EndElements\n");
    const TetMesh m = read_tet_mesh(path);
    EXPECT_EQ(m.num_vertices(), 4);  // node 50 is used by no tet
    EXPECT_EQ(m.boundary_faces.rows(), 4);
    int tagged = 0;
    for (int f = 0; f < 4; ++f) tagged += m.face_tags(f) == 7;
    EXPECT_EQ(tagged, 1);
}

// Node tags 1..4 (a dense table) and 10..40 in steps of 10 (a sorted list): either way an
// element naming a tag no node has is a load error, not a wrong vertex.
TEST(MeshIo, MshElementOnAnUnknownNodeTagIsALoadError) {
    for (const std::string tags : {"1\n2\n3\n4\n", "10\n20\n30\n40\n"}) {
        const std::string path = temp_path("unknown_tag.msh");
        write_text(path, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 40\n3 1 0 4\n" + tags +
                             "0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 5\n"
                             "$EndElements\n");
        expect_load_error(path);
    }
}

TEST(MeshIo, BadFilesAreLoadErrors) {
    expect_load_error(temp_path("does_not_exist.msh"));
    expect_load_error(temp_path("unknown.stl"));
    const std::string empty = temp_path("empty.msh");
    write_text(empty, "");
    expect_load_error(empty);
    const std::string garbage = temp_path("garbage.mesh");
    write_text(garbage, "hello world\n");
    expect_load_error(garbage);
    const std::string v2 = temp_path("v2.msh");
    write_text(v2, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
    expect_load_error(v2);
    const std::string binary = temp_path("binary.msh");
    write_text(binary, "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
    expect_load_error(binary);
    const std::string hexes = temp_path("hex.msh");
    write_text(hexes, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 0 0\n$EndNodes\n"
                      "$Elements\n1 1 1 1\n3 1 5 1\n1 1 1 1 1 1 1 1 1\n$EndElements\n");
    expect_load_error(hexes);
    const std::string truncated = temp_path("truncated.mesh");
    write_text(truncated, "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n");
    expect_load_error(truncated);
    const std::string out_of_range = temp_path("range.mesh");
    write_text(out_of_range, "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                             "Tetrahedra\n1\n1 2 3 9 0\nEnd\n");
    expect_load_error(out_of_range);
    const std::string flat = temp_path("flat.mesh");
    write_text(flat, "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n"
                     "Tetrahedra\n1\n1 2 3 4 0\nEnd\n");
    expect_load_error(flat);
    const std::string no_tets = temp_path("notets.mesh");
    write_text(no_tets, "MeshVersionFormatted 1\nDimension 3\nVertices\n1\n0 0 0 0\nEnd\n");
    expect_load_error(no_tets);
}

}  // namespace
}  // namespace framefix
