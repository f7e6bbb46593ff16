#pragma once
// The singular curves a node extrusion forces, and the frames of the field they imply around
// them (docs/algorithms.md#singular-node-extrusion). Internal to corrections/extrusion_nodes.cpp.
#include <vector>

#include <Eigen/Core>

#include "framefix/corrections/extrusion.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix::detail {

// Unit axes normal to the polyline at each of its points, carried from `reference` by
// projection (parallel transport without twist).
std::vector<Eigen::Vector3d> transported(const Points& p, const Eigen::Vector3d& reference);

class Winding {
public:
    // The used streamlines with a valence (3 or 5) of `lines`.
    explicit Winding(const std::vector<ExtrusionStreamline>& lines, double h);
    bool empty() const { return points_.empty(); }

    // Nearest forced-curve point within r of x: its index into points(), -1 if none.
    int nearest(const Eigen::Vector3d& x, double r) const { return grid_.nearest(x, r); }
    const Eigen::Vector3d& point(int k) const { return points_[size_t(k)]; }
    size_t line(int k) const { return at_[size_t(k)].line; }      // index into the streamlines
    Eigen::Index index(int k) const { return at_[size_t(k)].j; }  // point index along it
    const Eigen::Vector3d& e1(size_t line, Eigen::Index j) const { return e1_[line][size_t(j)]; }

    // The angle (radians) by which the field of all forced curves turns the cross about d at x,
    // sum of +-theta_k / 4 over the curves about roughly parallel axes (index +1/4 for valence 3,
    // -1/4 for valence 5); theta_k is measured about curve k from its own carried axis.
    double angle(const Eigen::Vector3d& x, const Eigen::Vector3d& d) const;

private:
    struct At { size_t line; Eigen::Index j; };
    struct Line { size_t line; int valence; const Points* points; };
    std::vector<Line> lines_;
    std::vector<std::vector<Eigen::Vector3d>> e1_;  // per streamline (empty for unused ones)
    std::vector<Eigen::Vector3d> points_;
    std::vector<At> at_;
    PointGrid grid_;
};

// The frame whose cross is turned by `angle` about d from e1 (made normal to d), axis 3 = d.
Eigen::Matrix3d turned_frame(const Eigen::Vector3d& d, const Eigen::Vector3d& e1, double angle);

}  // namespace framefix::detail
