// Mesh invariants on every sample: tessellate + tetrahedralize at about 20k tets.
#include <algorithm>
#include <map>
#include <set>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fixtures.h"
#include "framefix/brep/brep_model.h"
#include "framefix/core/error.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

struct Meshed {
    BrepModel model;
    FeatureSet features;
    TetMesh mesh;
};

Meshed mesh_sample(const std::string& name) {
    Meshed m{load_shape(test::sample(name)), {}, {}};
    m.features = classify_features(m.model);
    MeshOptions options;
    options.target_tets = 20000;
    m.mesh = tetrahedralize(tessellate(m.model, m.features, options), options);
    return m;
}

class SampleMesh : public testing::TestWithParam<const char*> {
protected:
    static std::map<std::string, Meshed>& cache() {
        static std::map<std::string, Meshed> meshes;
        return meshes;
    }
    const Meshed& meshed() {
        auto it = cache().find(GetParam());
        if (it == cache().end()) it = cache().emplace(GetParam(), mesh_sample(GetParam())).first;
        return it->second;
    }
};

TEST_P(SampleMesh, EveryTetIsPositive) {
    const MeshQuality q = mesh_quality(meshed().mesh);
    EXPECT_GT(q.min_volume, 0);
}

TEST_P(SampleMesh, NinetyPercentOfEdgesNearSize) {
    const MeshQuality q = mesh_quality(meshed().mesh);
    EXPECT_GE(q.edge_fraction_in_range, 0.9) << "median " << q.median_edge << " h " << meshed().mesh.size;
}

TEST_P(SampleMesh, TetCountNearTarget) {
    EXPECT_GT(meshed().mesh.num_tets(), 10000);
    EXPECT_LT(meshed().mesh.num_tets(), 40000);
}

TEST_P(SampleMesh, EveryBrepFaceHasBoundaryTriangles) {
    const TetMesh& mesh = meshed().mesh;
    const std::set<int> tags(mesh.face_tags.data(), mesh.face_tags.data() + mesh.face_tags.size());
    EXPECT_EQ(int(tags.size()), meshed().model.num_faces);
    EXPECT_EQ(*tags.begin(), 1);
    EXPECT_EQ(*tags.rbegin(), meshed().model.num_faces);
}

TEST_P(SampleMesh, BoundaryIsOutwardAndEnclosesTheMesh) {
    const TetMesh& mesh = meshed().mesh;
    double divergence = 0, volume = 0;
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d a = mesh.points.row(mesh.boundary_faces(f, 0)), b = mesh.points.row(mesh.boundary_faces(f, 1)),
                              c = mesh.points.row(mesh.boundary_faces(f, 2));
        divergence += a.dot(b.cross(c)) / 6;
    }
    for (int t = 0; t < mesh.num_tets(); ++t) volume += tet_volume(mesh, t);
    EXPECT_NEAR(divergence, volume, 1e-9 * volume);
    EXPECT_NEAR(volume, meshed().model.volume, 0.01 * meshed().model.volume);
}

TEST_P(SampleMesh, BoundaryTrianglesLieOnTheirFace) {
    const Meshed& m = meshed();
    for (int f = 0; f < m.mesh.boundary_faces.rows(); f += std::max(1, int(m.mesh.boundary_faces.rows() / 50))) {
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d p = m.mesh.points.row(m.mesh.boundary_faces(f, k));
            EXPECT_LT(distance_to_face(m.model, m.mesh.face_tags(f), p), 1e-6);
        }
    }
}

TEST_P(SampleMesh, FeatureEdgesLieOnTheirBrepEdge) {
    const Meshed& m = meshed();
    for (int e = 0; e < m.mesh.feature_edges.rows(); ++e) {
        const int tag = m.mesh.edge_tags(e);
        EXPECT_GT(m.features.valence_of(tag), 0) << "Edge" << tag;
        for (int k = 0; k < 2; ++k) {
            const Eigen::Vector3d p = m.mesh.points.row(m.mesh.feature_edges(e, k));
            EXPECT_LT(distance_to_edge(m.model, tag, p), 1e-6) << "Edge" << tag;
        }
    }
}

TEST_P(SampleMesh, FeatureCurvesAreFullyCovered) {
    const Meshed& m = meshed();
    std::map<int, double> length;
    for (int e = 0; e < m.mesh.feature_edges.rows(); ++e)
        length[m.mesh.edge_tags(e)] +=
            (m.mesh.points.row(m.mesh.feature_edges(e, 0)) - m.mesh.points.row(m.mesh.feature_edges(e, 1))).norm();
    for (const auto& f : m.features.edges) {
        if (f.valence == 0) continue;
        EXPECT_NEAR(length[f.edge], f.length, 0.01 * f.length) << "Edge" << f.edge;
    }
}

TEST_P(SampleMesh, CornerVerticesAreBrepVertices) {
    const Meshed& m = meshed();
    const Points corners = vertex_points(m.model);
    ASSERT_EQ(m.mesh.corner_vertices.rows(), corners.rows());
    for (int i = 0; i < corners.rows(); ++i)
        EXPECT_LT((m.mesh.points.row(m.mesh.corner_vertices(i)) - corners.row(i)).norm(), 1e-9) << "Vertex" << i + 1;
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleMesh,
                         testing::Values("cube", "cylinder", "l_prism", "notch", "box_arc", "box_arc_curved",
                                         "half_sphere_box", "groove", "two_cylinders"));

TEST(Tessellate, RefusesSizesBeyondMemoryBeforeMeshing) {
    const BrepModel model = load_shape(test::sample("cube"));
    MeshOptions options;
    options.size = 0.001;
    options.max_memory_mb = 4096;
    try {
        tessellate(model, classify_features(model), options);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "mesh");
        EXPECT_NE(e.message().find("size 0.001 needs about 1.2e+10 tets"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("use --size"), std::string::npos) << e.what();
    }
}

// Longest boundary triangle edge on each B-rep face.
std::map<int, double> longest_edge_by_face(const SurfaceMesh& s) {
    std::map<int, double> out;
    for (int t = 0; t < s.triangles.rows(); ++t)
        for (int k = 0; k < 3; ++k) {
            const double len = (s.points.row(s.triangles(t, k)) - s.points.row(s.triangles(t, (k + 1) % 3))).norm();
            out[s.face_tags(t)] = std::max(out[s.face_tags(t)], len);
        }
    return out;
}

TEST(Tessellate, AFaceGivenASmallerSizeIsMeshedFinerAndTheOthersAsBefore) {
    // A face next to the notch's concave arc at a third of the size; TetGen grades the tets from it.
    const BrepModel model = load_shape(test::sample("notch"));
    const FeatureSet fs = classify_features(model);
    MeshOptions options;
    options.size = 0.1;
    const std::map<int, double> plain = longest_edge_by_face(tessellate(model, fs, options));
    int wall = 0;
    for (const EdgeFeature& e : fs.edges)
        if (e.valence == 3) wall = e.faces.at(0);
    ASSERT_GT(wall, 0);
    options.face_size[wall] = options.size / 3;
    const SurfaceMesh fine = tessellate(model, fs, options);
    const std::map<int, double> refined = longest_edge_by_face(fine);
    EXPECT_LE(refined.at(wall), 1.3 * options.size / 3 + 1e-9);
    EXPECT_GT(plain.at(wall), 1.3 * options.size / 3);
    for (const auto& [face, len] : refined) EXPECT_LE(len, 1.3 * options.size + 1e-9) << "Face" << face;
    const TetMesh tets = tetrahedralize(fine, options);
    EXPECT_GT(tets.tets.rows(), 0);
    options.face_size[model.num_faces + 1] = 0.01;
    EXPECT_THROW(tessellate(model, fs, options), Error);
}

TEST(Tessellate, DefaultSizeGivesAboutTheTarget) {
    const BrepModel model = load_shape(test::sample("notch"));
    EXPECT_NEAR(estimate_tets(model.volume, default_size(model)), kDefaultTargetTets, 1);
}

}  // namespace
}  // namespace framefix
