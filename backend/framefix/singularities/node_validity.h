#pragma once
// Hex-meshability of singular nodes (docs/algorithms.md#node-validity). Internal to singularities/, exposed for
// the tests.
//
// Interior node: the link of a hex-mesh vertex is a sphere triangulation whose vertex degrees are
// the valences of the incident edges; with valences in {3,4,5} exactly 11 exist (sphtri.py), one
// per (n3, n4, n5) with 3 n3 + 2 n4 + n5 = 12. A node is valid iff its (n3, n5) curve-end counts
// are those of one of them.
// Boundary node on a smooth face [OURS, from the disk-link Euler identity with m surface edges,
// 3 n3 + 2 n4 + n5 = 6 - m, m in {3,4,5}]: (n3, n5) in {(1,0), (0,1), (0,2), (0,3)}; a singular
// boundary triangle must also have its holonomy axis along the face normal (the curve meets a
// surface cross singularity of index (4 - k)/4). Nodes touching a feature curve are not checked
// (their link needs the dihedral valences) [UNCERTAIN].
#include <array>
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

const std::array<std::array<int, 3>, 11>& hex_node_types();  // (n3, n4, n5), sphtri.py order
bool is_valid_interior_node(int n3, int n5);
bool is_valid_smooth_boundary_node(int n3, int n5);

// #V flags: vertex on a feature edge or a corner of the mesh.
std::vector<char> feature_vertices(const TetMesh& mesh);

// Whether every listed boundary triangle has its holonomy axis within 45 deg of its normal.
// face_axis: #F x 3 world holonomy axes.
bool axes_along_normals(const TetMesh& mesh, const TetTopology& topo,
                        const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& face_axis,
                        const std::vector<int>& boundary_faces);

}  // namespace framefix
