#pragma once
// Distance from a point to the boundary triangles of a tet mesh (a hash grid of triangle
// centroids, exact point-triangle distances within the query radius).
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {

class BoundaryDistance {
public:
    explicit BoundaryDistance(const TetMesh& mesh);
    // True when p is closer than `radius` to a boundary triangle.
    bool within(const Eigen::Vector3d& p, double radius) const;
    // The closest point to p on the boundary triangles within `radius`; p itself when none.
    Eigen::Vector3d closest(const Eigen::Vector3d& p, double radius) const;
    // Every boundary triangle closer than `radius` to p, with its distance.
    std::vector<std::pair<int, double>> near(const Eigen::Vector3d& p, double radius) const;

private:
    const TetMesh& mesh_;
    PointGrid centroids_;
    double reach_ = 0;  // largest centroid-to-corner distance: a triangle within r has its centroid within r + reach_
};

// Closest point to p on triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

}  // namespace framefix
