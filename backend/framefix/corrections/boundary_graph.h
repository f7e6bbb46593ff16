#pragma once
// The boundary edge graph that snapped curves live on (internal to corrections): boundary mesh
// edges with their lengths, which vertices are on feature curves, outward vertex normals, and the
// Dijkstra shortest path between two boundary vertices (docs/algorithms.md#boundary-paths).
#include <vector>

#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

struct BoundaryGraph {
    std::vector<int> adjacency_start;      // #V + 1, CSR over mesh vertices (interior ones: empty)
    std::vector<int> adjacency;            // boundary-edge neighbours of each vertex
    std::vector<double> adjacency_length;  // parallel to adjacency, model units
    std::vector<char> is_boundary;         // #V, 1 on a boundary triangle
    std::vector<char> is_feature;          // #V, 1 on a feature edge (valence > 0) or a corner of one
    std::vector<char> is_blocked;          // #V, feature vertices and other Dirichlet boundary
                                           // vertices (e.g. earlier snapped paths): paths avoid them
    std::vector<int> boundary_vertices;    // ascending vertex ids with is_boundary
    std::vector<int> feature_vertices;     // ascending vertex ids with is_feature
    Points normal;                         // #V x 3 unit area-weighted outward normal, 0 inside
    double hb = 0;                         // mean boundary edge length, model units
    double h_mean = 0;                     // mean tet edge length, model units

    int num_vertices() const { return int(is_boundary.size()); }
};

// `constraints` marks the extra blocked vertices (Fixed boundary vertices that are not features).
BoundaryGraph build_boundary_graph(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features,
                                   const Constraints& constraints);

struct BoundaryPath {
    std::vector<int> vertices;     // from `from` to `to`, consecutive vertices share a boundary edge
    double length = 0;             // model units
    bool crosses_features = false; // blocked vertices had to be used
};

// Shortest path on boundary edges. Blocked vertices are only allowed as the two endpoints; if no
// such path exists, the search is repeated with every boundary edge allowed. from == to gives a
// one-vertex path. Throws framefix::Error("snap") when the two vertices are not connected.
BoundaryPath shortest_boundary_path(const BoundaryGraph& graph, int from, int to);

// Nearest vertex of `candidates` to p (Euclidean); -1 if candidates is empty.
int nearest_vertex(const Points& points, const std::vector<int>& candidates, const Eigen::Vector3d& p);

}  // namespace framefix
