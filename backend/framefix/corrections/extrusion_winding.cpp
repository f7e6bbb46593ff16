#include "framefix/corrections/extrusion_winding.h"

#include <cmath>

#include <Eigen/Geometry>

#include "framefix/corrections/extrusion_trace.h"

namespace framefix::detail {
namespace {

constexpr double kParallel = 0.5;  // |cos|: curves about axes further apart do not turn the cross about d

Points stacked(const std::vector<Eigen::Vector3d>& pts) {
    Points p(Eigen::Index(pts.size()), 3);
    for (size_t k = 0; k < pts.size(); ++k) p.row(Eigen::Index(k)) = pts[k].transpose();
    return p;
}

bool forced(const ExtrusionStreamline& l) { return l.used && (l.valence == 3 || l.valence == 5); }

std::vector<Eigen::Vector3d> forced_points(const std::vector<ExtrusionStreamline>& lines) {
    std::vector<Eigen::Vector3d> out;
    for (const auto& l : lines)
        for (Eigen::Index j = 0; forced(l) && j < l.line.points.rows(); ++j) out.push_back(l.line.points.row(j).transpose());
    return out;
}

}  // namespace

std::vector<Eigen::Vector3d> transported(const Points& p, const Eigen::Vector3d& reference) {
    std::vector<Eigen::Vector3d> e(size_t(p.rows()));
    Eigen::Vector3d cur = reference;
    for (Eigen::Index j = 0; j < p.rows(); ++j) {
        const Eigen::Vector3d d = along(p, j);
        const Eigen::Vector3d q = cur - cur.dot(d) * d;
        cur = q.norm() > 1e-9 ? Eigen::Vector3d(q.normalized()) : cur;
        e[size_t(j)] = cur;
    }
    return e;
}

Winding::Winding(const std::vector<ExtrusionStreamline>& lines, double h)
    : e1_(lines.size()), points_(forced_points(lines)), grid_(stacked(points_), h) {
    for (size_t i = 0; i < lines.size(); ++i) {
        if (!forced(lines[i])) continue;
        lines_.push_back({i, lines[i].valence, &lines[i].line.points});
        e1_[i] = transported(lines[i].line.points, lines[i].reference);
        for (Eigen::Index j = 0; j < lines[i].line.points.rows(); ++j) at_.push_back({i, j});
    }
}

double Winding::angle(const Eigen::Vector3d& x, const Eigen::Vector3d& d) const {
    double sum = 0;
    for (const Line& l : lines_) {
        const Points& p = *l.points;
        Eigen::Index j = 0;
        for (Eigen::Index k = 1; k < p.rows(); ++k)
            if ((p.row(k).transpose() - x).squaredNorm() < (p.row(j).transpose() - x).squaredNorm()) j = k;
        const Eigen::Vector3d t = along(p, j);
        if (std::abs(t.dot(d)) < kParallel) continue;
        const Eigen::Vector3d e1 = e1_[l.line][size_t(j)], e2 = t.cross(e1), r = x - p.row(j).transpose();
        const double theta = std::atan2(r.dot(e2), r.dot(e1));
        sum += (l.valence == 5 ? -0.25 : 0.25) * (t.dot(d) > 0 ? 1 : -1) * theta;
    }
    return sum;
}

Eigen::Matrix3d turned_frame(const Eigen::Vector3d& d, const Eigen::Vector3d& e1_in, double angle) {
    const Eigen::Vector3d e1 = (e1_in - e1_in.dot(d) * d).normalized(), e2 = d.cross(e1);
    const Eigen::Vector3d a1 = std::cos(angle) * e1 + std::sin(angle) * e2;
    Eigen::Matrix3d R;
    R << a1, d.cross(a1), d;
    return R;
}

}  // namespace framefix::detail
