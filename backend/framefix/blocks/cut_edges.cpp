#include <algorithm>
#include <cmath>
#include <omp.h>

#include "framefix/blocks/partition.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {

namespace {

// Segment o + s d (s in [0,1]) against a triangle, Moller-Trumbore with a tolerance so that touches
// at end points and triangle edges count.
bool segment_hits(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& t0,
                  const Eigen::Vector3d& t1, const Eigen::Vector3d& t2) {
    constexpr double tol = 1e-7;
    const Eigen::Vector3d e1 = t1 - t0, e2 = t2 - t0;
    const Eigen::Vector3d pv = d.cross(e2);
    const double det = e1.dot(pv);
    if (std::abs(det) < 1e-14) return false;
    const double inv = 1 / det;
    const Eigen::Vector3d tv = o - t0;
    const double u = tv.dot(pv) * inv;
    if (u < -tol || u > 1 + tol) return false;
    const Eigen::Vector3d qv = tv.cross(e1);
    const double v = d.dot(qv) * inv;
    if (v < -tol || u + v > 1 + tol) return false;
    const double s = e2.dot(qv) * inv;
    return s >= -tol && s <= 1 + tol;
}

}  // namespace

std::vector<char> cut_by_sheets(const TetMesh& mesh, const TetTopology& topo, const SheetSoup& sheets, int threads) {
    const int ne = int(topo.edges.rows());
    std::vector<char> cut(ne, 0);
    if (sheets.triangles.rows() == 0 || ne == 0) return cut;
    Points mid(ne, 3);
    double half = 0;
    for (int e = 0; e < ne; ++e) {
        const Eigen::RowVector3d a = mesh.points.row(topo.edges(e, 0)), b = mesh.points.row(topo.edges(e, 1));
        mid.row(e) = 0.5 * (a + b);
        half = std::max(half, 0.5 * (b - a).norm());
    }
    const PointGrid grid(mid, 2 * half);
    const int nt = int(sheets.triangles.rows());
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
    {
        std::vector<int> near;
#pragma omp for schedule(dynamic, 256)
        for (int t = 0; t < nt; ++t) {
            const Eigen::Vector3d p0 = sheets.points.row(sheets.triangles(t, 0)).transpose();
            const Eigen::Vector3d p1 = sheets.points.row(sheets.triangles(t, 1)).transpose();
            const Eigen::Vector3d p2 = sheets.points.row(sheets.triangles(t, 2)).transpose();
            const Eigen::Vector3d c = (p0 + p1 + p2) / 3;
            const double r = std::max({(p0 - c).norm(), (p1 - c).norm(), (p2 - c).norm()}) + half + 1e-9;
            grid.within(c, r, near);
            for (int e : near) {
                const Eigen::Vector3d o = mesh.points.row(topo.edges(e, 0)).transpose();
                const Eigen::Vector3d d = mesh.points.row(topo.edges(e, 1)).transpose() - o;
                if (segment_hits(o, d, p0, p1, p2)) {
#pragma omp atomic write
                    cut[e] = 1;
                }
            }
        }
    }
    return cut;
}

void cut_near_polylines(const TetMesh& mesh, const TetTopology& topo, const Points& polyline_points, double radius,
                        std::vector<char>& cut) {
    if (polyline_points.rows() < 1 || radius <= 0) return;
    // Resample consecutive points every radius/4 so that the point set stands for the polyline.
    std::vector<Eigen::Vector3d> samples;
    for (int i = 0; i < int(polyline_points.rows()); ++i) {
        const Eigen::Vector3d a = polyline_points.row(i).transpose();
        samples.push_back(a);
        if (i + 1 == int(polyline_points.rows())) break;
        const Eigen::Vector3d b = polyline_points.row(i + 1).transpose();
        if ((b - a).norm() > 4 * radius) continue;  // a jump between two curves of the stack
        const int n = int(std::ceil((b - a).norm() / (0.25 * radius)));
        for (int k = 1; k < n; ++k) samples.push_back(a + (b - a) * double(k) / n);
    }
    Points S(Eigen::Index(samples.size()), 3);
    for (size_t i = 0; i < samples.size(); ++i) S.row(Eigen::Index(i)) = samples[i].transpose();
    const PointGrid grid(S, radius);
    for (int e = 0; e < int(topo.edges.rows()); ++e) {
        if (cut[e]) continue;
        const Eigen::Vector3d a = mesh.points.row(topo.edges(e, 0)).transpose();
        const Eigen::Vector3d b = mesh.points.row(topo.edges(e, 1)).transpose();
        for (int k = 0; k <= 6 && !cut[e]; ++k)
            if (grid.nearest(a + (b - a) * (k / 6.0), radius) >= 0) cut[e] = 1;
    }
}

}  // namespace framefix
