#pragma once
// Point location in a tet mesh (docs/algorithms.md#point-location): a visibility walk from the last tet, and a
// uniform grid of tet bounding boxes for the first location. Immutable after construction, so
// one locator serves all threads.
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

struct TetLocation {
    int tet = -1;                          // -1: the point is outside the mesh
    Eigen::Vector4d bary = Eigen::Vector4d::Zero();  // barycentric coordinates of the point in `tet`
};

class TetLocator {
public:
    TetLocator(const TetMesh& mesh, const TetTopology& topo);

    // Barycentric coordinates of p in tet (local vertex order of mesh.tets).
    Eigen::Vector4d barycentric(int tet, const Eigen::Vector3d& p) const;
    // Walk from `start` (a tet id, or -1 to use the grid). Stepping through a boundary face means
    // "outside" (tet -1). A walk that cycles falls back to the grid.
    TetLocation locate(const Eigen::Vector3d& p, int start = -1) const;
    // Neighbour of tet across its local face lf (opposite local vertex lf); -1 on the boundary.
    int neighbour(int tet, int lf) const { return neighbours_[4 * tet + lf]; }
    double mean_edge() const { return mean_edge_; }
    double bbox_diagonal() const { return (hi_ - lo_).norm(); }

private:
    TetLocation locate_in_grid(const Eigen::Vector3d& p) const;

    const TetMesh& mesh_;
    std::vector<int> neighbours_;          // #T*4, tet across local face lf, -1 boundary
    std::vector<Eigen::Matrix3d> inverse_; // #T, inverse of [p1-p0, p2-p0, p3-p0]
    Eigen::Vector3d lo_, hi_;              // bounding box of the mesh, model units
    double cell_ = 1;                      // grid cell size, model units
    Eigen::Vector3i dims_ = Eigen::Vector3i::Ones();
    std::vector<int> cell_start_, cell_tets_;  // CSR: tets whose bounding box meets each cell
    double mean_edge_ = 0;                 // mean mesh edge length, model units
};

}  // namespace framefix
