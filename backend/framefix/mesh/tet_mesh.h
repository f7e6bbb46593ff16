#pragma once
// The tet mesh of a solid and its tags. Every tet is positively oriented:
//
//          3
//         /|\          det[p1-p0, p2-p0, p3-p0] > 0
//        / | \         local face lf is opposite local vertex lv = lf:
//       /  |  \          f0 = (1,2,3), f1 = (0,3,2), f2 = (0,1,3), f3 = (0,2,1)
//      0---|---2         (each seen counter-clockwise from outside the tet)
//       \  |  /
//        \ | /
//          1
//
// Boundary triangles are oriented outward and tagged with their B-rep face; mesh edges lying on
// feature curves are tagged with their B-rep edge; B-rep vertices are mesh vertices.
#include <string>

#include <Eigen/Core>

#include "framefix/mesh/types.h"

namespace framefix {

constexpr int kTetFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct TetMesh {
    Points points;                 // #V x 3, model units
    Tets tets;                     // #T x 4 vertex indices, positive orientation
    Triangles boundary_faces;      // #B x 3 vertex indices, outward
    Eigen::VectorXi face_tags;     // #B, B-rep face index (1-based) of each boundary triangle
    Segments feature_edges;        // #E x 2 vertex indices, mesh edges on feature curves
    Eigen::VectorXi edge_tags;     // #E, B-rep edge index (1-based) of each feature edge
    Eigen::VectorXi corner_vertices;  // #C vertex indices of B-rep vertices (corner_vertices[i] = Vertex<i+1>)
    double size = 0;               // target edge length h it was built for, model units

    int num_vertices() const { return int(points.rows()); }
    int num_tets() const { return int(tets.rows()); }
};

double tet_volume(const TetMesh& mesh, int tet);  // signed, model units^3
Eigen::Vector3d tet_centroid(const TetMesh& mesh, int tet);  // mean of its 4 vertices, model units

// The mesh as bytes and back (exact), for a mesh made in a worker process.
std::string tet_mesh_bytes(const TetMesh& mesh);
TetMesh tet_mesh_from_bytes(const std::string& bytes);

struct MeshQuality {
    double min_volume = 0;         // smallest signed tet volume
    double edge_fraction_in_range = 0;  // fraction of edges with length in [0.5h, 1.6h]
    double median_edge = 0, min_edge = 0, max_edge = 0;
    int edges = 0;
};
MeshQuality mesh_quality(const TetMesh& mesh);

}  // namespace framefix
