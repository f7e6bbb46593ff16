#include "framefix/singularities/node_validity.h"

#include <cmath>

#include <Eigen/Geometry>

namespace framefix {

const std::array<std::array<int, 3>, 11>& hex_node_types() {
    static const std::array<std::array<int, 3>, 11> table = {{
        {4, 0, 0},   // 4 valence-3 curves (tetrahedron)
        {2, 3, 0},   // point on a valence-3 curve
        {0, 6, 0},   // regular point (octahedron)
        {2, 2, 2},
        {1, 3, 3},   // the filleted notch node
        {0, 5, 2},   // point on a valence-5 curve
        {2, 0, 6},
        {0, 4, 4},
        {0, 3, 6},
        {0, 2, 8},
        {0, 0, 12},  // icosahedron
    }};
    return table;
}

bool is_valid_interior_node(int n3, int n5) {
    for (const auto& t : hex_node_types())
        if (t[0] == n3 && t[2] == n5) return true;
    return false;
}

bool is_valid_smooth_boundary_node(int n3, int n5) {
    return (n3 == 1 && n5 == 0) || (n3 == 0 && n5 >= 1 && n5 <= 3);
}

std::vector<char> feature_vertices(const TetMesh& mesh) {
    std::vector<char> f(mesh.num_vertices(), 0);
    for (int e = 0; e < mesh.feature_edges.rows(); ++e)
        for (int k = 0; k < 2; ++k) f[mesh.feature_edges(e, k)] = 1;
    for (int i = 0; i < mesh.corner_vertices.size(); ++i) f[mesh.corner_vertices(i)] = 1;
    return f;
}

bool axes_along_normals(const TetMesh& mesh, const TetTopology& topo,
                        const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& face_axis,
                        const std::vector<int>& boundary_faces) {
    const double cos45 = std::sqrt(0.5);
    for (int f : boundary_faces) {
        const Eigen::Vector3d x0 = mesh.points.row(topo.faces(f, 0)).transpose();
        const Eigen::Vector3d n = (mesh.points.row(topo.faces(f, 1)).transpose() - x0)
                                      .cross(mesh.points.row(topo.faces(f, 2)).transpose() - x0)
                                      .normalized();
        if (std::abs(n.dot(face_axis.row(f).transpose())) < cos45) return false;
    }
    return true;
}

}  // namespace framefix
