// The internal constraints of the extrusions on the new mesh: tangency at the inserted points
// (curves), singular frames and the forced field's tube around the forced curves (nodes).
#include <algorithm>

#include "framefix/corrections/extrusion.h"
#include "framefix/corrections/extrusion_trace.h"
#include "framefix/corrections/extrusion_winding.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {
namespace {

constexpr double kMatchRadius = 1e-6;  // inserted point found at a mesh vertex, in h
constexpr double kHeadOn = 0.9;        // cosine: a streamline this close to the normal meets the boundary head-on

// Node extrusion: vertices near a forced curve (free ones, and boundary ones it meets head-on)
// get the frames of the forced field (or, on its core, the singular frame). Returns how many.
int constrain_tubes(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& cons, const ExtrusionOptions& o) {
    const double h = std::max(mesh.size, 1e-12);
    const detail::Winding winding(plan.streamlines, h);
    if (winding.empty()) return 0;
    int n = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const ConstraintKind kind = cons.kind[size_t(v)];
        if (kind == ConstraintKind::Fixed) continue;
        const Eigen::Vector3d x = mesh.points.row(v).transpose();
        const int k = winding.nearest(x, o.tube_radius_h * h);
        if (k < 0) continue;
        const ExtrusionStreamline& l = plan.streamlines[winding.line(k)];
        const Eigen::Index j = winding.index(k);
        Eigen::Vector3d d = detail::along(l.line.points, j);
        if (kind == ConstraintKind::NormalAligned) {  // the surface singularity where it ends is forced too
            const Eigen::Vector3d nrm = cons.normal.row(v).transpose();
            if (std::abs(nrm.dot(d)) < kHeadOn) continue;
            d = nrm.dot(d) > 0 ? nrm : Eigen::Vector3d(-nrm);
        }
        const Eigen::Vector3d r = x - winding.point(k) - (x - winding.point(k)).dot(d) * d;
        if (r.norm() < o.core_radius_h * h) {
            set_singular(cons, v, d);
        } else {
            const double angle = l.phase[size_t(j)] + winding.angle(x, d);
            cons.kind[size_t(v)] = ConstraintKind::Fixed;
            cons.fixed.row(v) = frame_from_rotation(detail::turned_frame(d, winding.e1(winding.line(k), j), angle)).transpose();
        }
        ++n;
    }
    return n;
}

}  // namespace

int add_internal_constraints(const TetMesh& mesh, const ExtrusionPlan& plan, Constraints& cons, const ExtrusionOptions& o) {
    if (plan.points.rows() == 0) return 0;
    const double r = kMatchRadius * std::max(mesh.size, 1e-12);
    const PointGrid grid(mesh.points, std::max(mesh.size, 1e-12));
    int n = 0;
    for (Eigen::Index i = 0; i < plan.points.rows(); ++i) {
        const int v = grid.nearest(plan.points.row(i).transpose(), r);
        if (v < 0 || cons.kind[size_t(v)] != ConstraintKind::Free) continue;
        const Eigen::Vector3d axis = plan.axes.row(i).transpose();
        if (plan.singular) {
            set_singular(cons, v, axis);
        } else {
            cons.kind[size_t(v)] = ConstraintKind::NormalAligned;
            cons.normal.row(v) = axis.transpose();
        }
        ++n;
    }
    return n + (plan.singular ? constrain_tubes(mesh, plan, cons, o) : 0);
}

}  // namespace framefix
