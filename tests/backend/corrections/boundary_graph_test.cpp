// Boundary edge graph and Dijkstra paths on the cube fixture.
#include <gtest/gtest.h>

#include <algorithm>

#include "framefix/corrections/boundary_graph.h"
#include "backend/corrections/cube_frames.h"

namespace framefix {
namespace {

bool shares_boundary_edge(const BoundaryGraph& g, int a, int b) {
    for (int i = g.adjacency_start[a]; i < g.adjacency_start[a + 1]; ++i)
        if (g.adjacency[i] == b) return true;
    return false;
}

TEST(BoundaryGraph, MarksCubeEdgesAsFeaturesAndMeasuresEdges) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    EXPECT_EQ(int(g.feature_vertices.size()), 8 + 12 * 3);  // corners + 3 inner vertices per edge
    EXPECT_EQ(int(g.boundary_vertices.size()), 5 * 5 * 5 - 3 * 3 * 3);
    EXPECT_GT(g.hb, 0.25 - 1e-9);           // axis edges 0.25, face diagonals 0.35
    EXPECT_LT(g.hb, 0.36);
    for (int v : g.boundary_vertices) EXPECT_NEAR(g.normal.row(v).norm(), 1.0, 1e-12);
    // Face-interior vertex on z = 0: the outward normal is -z.
    EXPECT_NEAR(g.normal(c.vertex(2, 2, 0), 2), -1.0, 1e-12);
}

TEST(BoundaryGraph, PathAvoidsFeaturesExceptAtItsEnds) {
    const test::Cube c = test::cube_tets(6);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    // Both ends on feature edges of face z = 0 (y = 0 and y = 1); the straight line along x = 0.5
    // is feature-free, but going along the features would be just as short elsewhere.
    const int from = c.vertex(3, 0, 0), to = c.vertex(3, 6, 0);
    const BoundaryPath p = shortest_boundary_path(g, from, to);
    ASSERT_GE(p.vertices.size(), 3u);
    EXPECT_EQ(p.vertices.front(), from);
    EXPECT_EQ(p.vertices.back(), to);
    EXPECT_FALSE(p.crosses_features);
    for (size_t k = 1; k + 1 < p.vertices.size(); ++k) EXPECT_FALSE(g.is_feature[p.vertices[k]]) << "vertex " << k;
    for (size_t k = 0; k + 1 < p.vertices.size(); ++k) EXPECT_TRUE(shares_boundary_edge(g, p.vertices[k], p.vertices[k + 1]));
    EXPECT_NEAR(p.length, 1.0, 1e-9);  // the grid line x = 0.5 on z = 0
    for (int v : p.vertices) EXPECT_NEAR(c.point(v).z(), 0.0, 1e-12);
}

TEST(BoundaryGraph, PathBetweenAdjacentFeatureVerticesLeavesTheFeatureEdge) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    const BoundaryPath p = shortest_boundary_path(g, c.vertex(1, 0, 0), c.vertex(2, 0, 0));
    EXPECT_FALSE(p.crosses_features);
    EXPECT_GE(p.vertices.size(), 3u);  // not the feature edge itself
}

TEST(BoundaryGraph, FallsBackToCrossingFeaturesBetweenSeparatedFaces) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    // Face interiors of z = 0 and z = 1 are separated by the cube's feature edges.
    const BoundaryPath p = shortest_boundary_path(g, c.vertex(2, 2, 0), c.vertex(2, 2, 4));
    EXPECT_TRUE(p.crosses_features);
    EXPECT_EQ(p.vertices.front(), c.vertex(2, 2, 0));
    EXPECT_EQ(p.vertices.back(), c.vertex(2, 2, 4));
}

TEST(BoundaryGraph, OneVertexPathWhenEndsCoincide) {
    const test::Cube c = test::cube_tets(3);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    const BoundaryPath p = shortest_boundary_path(g, c.vertex(1, 1, 0), c.vertex(1, 1, 0));
    EXPECT_EQ(p.vertices, std::vector<int>{c.vertex(1, 1, 0)});
}

TEST(BoundaryGraph, NearestVertexIsTheClosestCandidate) {
    const test::Cube c = test::cube_tets(4);
    const BoundaryGraph g = build_boundary_graph(c.mesh, c.topo, c.features, c.constraints);
    EXPECT_EQ(nearest_vertex(c.mesh.points, g.feature_vertices, Eigen::Vector3d(0.52, 0.1, 0.05)), c.vertex(2, 0, 0));
    EXPECT_EQ(nearest_vertex(c.mesh.points, {}, Eigen::Vector3d::Zero()), -1);
}

}  // namespace
}  // namespace framefix
