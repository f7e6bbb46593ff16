// 45 deg turned Dirichlet frames on the feature-curve vertices under valence-5 runs.
#include "framefix/corrections/flat_corners.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "framefix/corrections/free_boundary.h"
#include "framefix/corrections/split_curves.h"
#include "framefix/frame_field/projection.h"
#include "framefix/frame_field/sh.h"

namespace framefix {
namespace {

constexpr double kCoverSpacings = 0.5;  // a vertex is under a run within half its edge spacing

double distance_to_run(const Eigen::Vector3d& p, const EdgeRun& run) {
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i + 1 < run.points.rows(); ++i)
        d = std::min(d, point_segment_distance(p, run.points.row(i).transpose(), run.points.row(i + 1).transpose()));
    return d;
}

// The Dirichlet frame q turned by 45 deg about its axis nearest the tangent t.
SH9 turned_frame(const SH9& q, const Eigen::Vector3d& t) {
    const Eigen::Matrix3d R = project_frame(q).rotation;
    int k = 0;
    for (int j = 1; j < 3; ++j)
        if (std::abs(R.col(j).dot(t)) > std::abs(R.col(k).dot(t))) k = j;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI / 4, R.col(k).normalized()).toRotationMatrix();
    return frame_from_rotation(turn * R);
}

}  // namespace

FlatCorners flat_corner_constraints(const TetMesh& mesh, const FeatureSet& features, const Constraints& constraints,
                                    const std::vector<EdgeRun>& runs) {
    FlatCorners out{constraints, 0};
    if (runs.empty()) return out;
    const Points& x = mesh.points;
    for (const FeatureChain& chain : feature_chains(mesh, features)) {
        const std::vector<int>& v = chain.vertices;
        const int n = int(v.size());
        for (int k = 0; k < n; ++k) {
            const bool end = !chain.closed && (k == 0 || k == n - 1);
            if (end || (chain.closed && k == n - 1) || constraints.kind[v[k]] != ConstraintKind::Fixed) continue;
            const int prev = k > 0 ? v[k - 1] : v[n - 2], next = k + 1 < n ? v[k + 1] : v[1];
            const Eigen::Vector3d p = x.row(v[k]).transpose();
            const Eigen::Vector3d t = (x.row(next) - x.row(prev)).transpose();
            const double spacing = 0.5 * t.norm();
            const bool covered = std::any_of(runs.begin(), runs.end(), [&](const EdgeRun& r) {
                return r.edge == chain.tag && distance_to_run(p, r) <= kCoverSpacings * spacing;
            });
            if (!covered) continue;
            out.constraints.fixed.row(v[k]) = turned_frame(constraints.fixed.row(v[k]).transpose(), t.normalized()).transpose();
            ++out.turned_vertices;
        }
    }
    return out;
}

}  // namespace framefix
