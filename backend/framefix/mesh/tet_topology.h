#pragma once
// Connectivity derived once from a TetMesh and passed explicitly to the stages that need it.
// Index spaces: vert (mesh vertex), tet, face (unique triangle), edge (unique mesh edge).
#include <vector>

#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct TetTopology {
    Triangles faces;               // #F x 3 sorted vertex indices of every unique triangle
    Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> face_tets;  // #F x 2 tets, -1 if boundary
    Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> tet_faces;  // #T x 4 face of local face lf
    Segments edges;                // #Ed x 2 sorted vertex indices of every unique edge
    std::vector<char> on_boundary; // #V, 1 if the vertex lies on a boundary face
    std::vector<int> vert_tets_start, vert_tets;  // CSR: tets around each vertex
};

TetTopology build_topology(const TetMesh& mesh);

// The tet across face f from tet t; -1 beyond the boundary.
inline int tet_across(const TetTopology& topo, int f, int t) {
    return topo.face_tets(f, 0) == t ? topo.face_tets(f, 1) : topo.face_tets(f, 0);
}

// Mean length of the unique edges, model units (the mesh size h); `if_no_edges` when there are none.
double mean_edge_length(const TetMesh& mesh, const TetTopology& topo, double if_no_edges = 0.0);

}  // namespace framefix
