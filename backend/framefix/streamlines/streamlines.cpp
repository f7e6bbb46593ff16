#include "framefix/streamlines/streamlines.h"

#include <cmath>
#include <memory>

#include <omp.h>

#include "framefix/core/error.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {

const char* to_string(StopReason reason) {
    switch (reason) {
        case StopReason::LeftSolid: return "left_solid";
        case StopReason::ReachedSingularity: return "singularity";
        case StopReason::SharpTurn: return "sharp_turn";
        case StopReason::LimitCycle: return "limit_cycle";
        case StopReason::MaxSteps: return "max_steps";
        case StopReason::StartOutside: return "start_outside";
    }
    return "?";
}

Eigen::Vector3d closest_direction_at(const TetMesh& mesh, const FrameField& field, const TetLocation& where,
                                     const Eigen::Vector3d& v) {
    Eigen::Vector4d w = where.bary.cwiseMax(0.0);
    w /= std::max(w.sum(), 1e-300);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int lv = 0; lv < 4; ++lv) {
        const auto row = field.axes.row(mesh.tets(where.tet, lv));
        Eigen::Vector3d best = Eigen::Vector3d::Zero();
        double best_dot = -1;
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d a(row[3 * k], row[3 * k + 1], row[3 * k + 2]);
            const double d = a.dot(v);
            if (std::abs(d) > best_dot) best_dot = std::abs(d), best = d < 0 ? Eigen::Vector3d(-a) : a;
        }
        sum += w[lv] * best;
    }
    const double n = sum.norm();
    return n > 1e-30 ? Eigen::Vector3d(sum / n) : v;
}

namespace {

struct Resolved {  // TraceOptions with the defaults filled in
    double step, max_length, stop_distance, cos_turn;
};

Resolved resolve(const TetLocator& locator, const TraceOptions& o) {
    Resolved r;
    r.step = o.step > 0 ? o.step : 0.4 * locator.mean_edge();
    r.max_length = o.max_length > 0 ? o.max_length : 3 * locator.bbox_diagonal();
    r.stop_distance = o.stop_distance > 0 ? o.stop_distance : 1.5 * locator.mean_edge();
    r.cos_turn = std::cos(o.max_turn_deg * M_PI / 180);
    return r;
}

// Last inside point a, first outside point b: bisect onto the boundary (16 halvings ~ 1e-5 step).
Eigen::Vector3d clip_to_boundary(const TetLocator& locator, Eigen::Vector3d a, int tet, Eigen::Vector3d b) {
    for (int it = 0; it < 16; ++it) {
        const Eigen::Vector3d m = 0.5 * (a + b);
        const TetLocation l = locator.locate(m, tet);
        if (l.tet >= 0) a = m, tet = l.tet;
        else b = m;
    }
    return a;
}

Streamline trace_one(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                     const Eigen::Vector3d& seed, const Eigen::Vector3d& direction, const TraceOptions& o,
                     const Resolved& r, const PointGrid* singular) {
    std::vector<Eigen::Vector3d> pts{seed};
    Streamline s;
    TetLocation at = locator.locate(seed, -1);
    Eigen::Vector3d v = direction.normalized();
    if (at.tet < 0) {
        s.reason = StopReason::StartOutside;
    } else {
        const double h = r.step;
        s.reason = StopReason::MaxSteps;
        for (int step = 0; step < o.max_steps; ++step) {
            const Eigen::Vector3d p = pts.back();
            const Eigen::Vector3d v1 = closest_direction_at(mesh, field, at, v);
            if (step == 0 && o.start_picks_axis) v = v1;
            TetLocation l2 = locator.locate(p + 0.5 * h * v1, at.tet);
            const Eigen::Vector3d v2 = l2.tet >= 0 ? closest_direction_at(mesh, field, l2, v1) : v1;
            TetLocation l3 = locator.locate(p + 0.5 * h * v2, l2.tet >= 0 ? l2.tet : at.tet);
            const Eigen::Vector3d v3 = l3.tet >= 0 ? closest_direction_at(mesh, field, l3, v2) : v2;
            TetLocation l4 = locator.locate(p + h * v3, l3.tet >= 0 ? l3.tet : at.tet);
            const Eigen::Vector3d v4 = l4.tet >= 0 ? closest_direction_at(mesh, field, l4, v3) : v3;
            const Eigen::Vector3d pn = p + h / 6 * (v1 + 2 * v2 + 2 * v3 + v4);
            const TetLocation ln = locator.locate(pn, l4.tet >= 0 ? l4.tet : at.tet);
            if (ln.tet < 0 || l2.tet < 0 || l3.tet < 0 || l4.tet < 0) {
                // Leave along the first-stage direction: the stages outside the solid have no field.
                const Eigen::Vector3d out = p + h * v1;
                const TetLocation lo = locator.locate(out, at.tet);
                if (lo.tet < 0) {
                    pts.push_back(clip_to_boundary(locator, p, at.tet, out));
                    s.length += (pts.back() - p).norm();
                    s.reason = StopReason::LeftSolid;
                    break;
                }
                pts.push_back(out), s.length += h, at = lo, v = v1;
                continue;
            }
            pts.push_back(pn);
            s.length += (pn - p).norm();
            if (v.dot(v4) < r.cos_turn) { s.reason = StopReason::SharpTurn; break; }
            v = v4, at = ln;
            if (singular && s.length > 2 * r.stop_distance) {
                const int near = singular->nearest(pn, r.stop_distance);
                if (near >= 0) {
                    if (o.append_singular_point) pts.push_back(o.singular_points.row(near).transpose());
                    s.reason = StopReason::ReachedSingularity;
                    break;
                }
            }
            if (s.length > r.max_length) { s.reason = StopReason::LimitCycle; break; }
        }
    }
    s.points.resize(Eigen::Index(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) s.points.row(Eigen::Index(i)) = pts[i].transpose();
    return s;
}

void check_inputs(const TetMesh& mesh, const FrameField& field) {
    if (field.axes.rows() != mesh.num_vertices())
        throw Error("streamlines", "frame field has " + std::to_string(field.axes.rows()) + " axis rows for " +
                                       std::to_string(mesh.num_vertices()) + " vertices; solve the field on this mesh");
}

}  // namespace

Streamline trace_streamline(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                            const Eigen::Vector3d& seed, const Eigen::Vector3d& direction, const TraceOptions& options) {
    check_inputs(mesh, field);
    const Resolved r = resolve(locator, options);
    std::unique_ptr<PointGrid> grid;
    if (options.singular_points.rows()) grid = std::make_unique<PointGrid>(options.singular_points, r.stop_distance);
    return trace_one(mesh, field, locator, seed, direction, options, r, grid.get());
}

std::vector<Streamline> trace_streamlines(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                          const Points& seeds, const Points& directions, const TraceOptions& options) {
    check_inputs(mesh, field);
    if (seeds.rows() != directions.rows())
        throw Error("streamlines", "seeds and directions differ in rows (" + std::to_string(seeds.rows()) + " vs " +
                                       std::to_string(directions.rows()) + ")");
    const Resolved r = resolve(locator, options);
    std::unique_ptr<PointGrid> grid;
    if (options.singular_points.rows()) grid = std::make_unique<PointGrid>(options.singular_points, r.stop_distance);
    std::vector<Streamline> out(seeds.rows());
    const int n = int(seeds.rows());
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int i = 0; i < n; ++i)
        out[i] = trace_one(mesh, field, locator, seeds.row(i).transpose(), directions.row(i).transpose(), options, r,
                           grid.get());
    return out;
}

}  // namespace framefix
