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
    const int ne = int(topo.edges.rows()), nt = int(sheets.triangles.rows());
    std::vector<char> cut(ne, 0);
    if (nt == 0 || ne == 0) return cut;
    // Dense grid over the mesh's bounding box, cells of about one edge length; each sheet triangle
    // is listed in the cells its bounding box meets, each mesh edge tests the triangles of the
    // cells its own box meets (edges are short: 1-8 cells).
    double mean = 0;
    for (int e = 0; e < ne; ++e) mean += (mesh.points.row(topo.edges(e, 0)) - mesh.points.row(topo.edges(e, 1))).norm() / ne;
    const Eigen::Vector3d lo = mesh.points.colwise().minCoeff().transpose().array() - 1e-9;
    const Eigen::Vector3d hi = mesh.points.colwise().maxCoeff().transpose().array() + 1e-9;
    double cell = std::max(mean, 1e-12);
    while (((hi - lo) / cell).array().ceil().prod() > 8e6) cell *= 2;
    Eigen::Vector3i dims;
    for (int k = 0; k < 3; ++k) dims[k] = std::max(1, int(std::ceil((hi[k] - lo[k]) / cell)));
    auto range = [&](Eigen::Vector3d a, Eigen::Vector3d b, Eigen::Vector3i& i0, Eigen::Vector3i& i1) {
        for (int k = 0; k < 3; ++k) {
            if (b[k] < lo[k] || a[k] > hi[k]) return false;
            i0[k] = std::clamp(int((a[k] - lo[k]) / cell), 0, dims[k] - 1);
            i1[k] = std::clamp(int((b[k] - lo[k]) / cell), 0, dims[k] - 1);
        }
        return true;
    };
    auto id = [&](int i, int j, int k) { return (size_t(k) * dims[1] + j) * dims[0] + i; };
    const size_t ncell = size_t(dims[0]) * dims[1] * dims[2];
    std::vector<size_t> start(ncell + 1, 0);  // 64 bits: long ribbon triangles span many cells
    std::vector<int> items;
    auto corner = [&](int t, int k) { return Eigen::Vector3d(sheets.points.row(sheets.triangles(t, k)).transpose()); };
    const double pad = 1e-7;
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            for (size_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
            items.resize(start[ncell]);
        }
        std::vector<size_t> fill(start.begin(), start.end() - 1);
        for (int t = 0; t < nt; ++t) {
            Eigen::Vector3i i0, i1;
            const Eigen::Vector3d a = corner(t, 0).cwiseMin(corner(t, 1)).cwiseMin(corner(t, 2)).array() - pad;
            const Eigen::Vector3d b = corner(t, 0).cwiseMax(corner(t, 1)).cwiseMax(corner(t, 2)).array() + pad;
            if (!range(a, b, i0, i1)) continue;
            for (int k = i0[2]; k <= i1[2]; ++k)
                for (int j = i0[1]; j <= i1[1]; ++j)
                    for (int i = i0[0]; i <= i1[0]; ++i) {
                        if (pass == 0) start[id(i, j, k) + 1] += 1;
                        else items[fill[id(i, j, k)]++] = t;
                    }
        }
    }
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads > 0 ? threads : omp_get_max_threads())
    for (int e = 0; e < ne; ++e) {
        const Eigen::Vector3d o = mesh.points.row(topo.edges(e, 0)).transpose();
        const Eigen::Vector3d d = mesh.points.row(topo.edges(e, 1)).transpose() - o;
        Eigen::Vector3i i0, i1;
        if (!range(o.cwiseMin(o + d), o.cwiseMax(o + d), i0, i1)) continue;
        for (int k = i0[2]; k <= i1[2] && !cut[e]; ++k)
            for (int j = i0[1]; j <= i1[1] && !cut[e]; ++j)
                for (int i = i0[0]; i <= i1[0] && !cut[e]; ++i) {
                    const size_t c = id(i, j, k);
                    for (size_t s = start[c]; s < start[c + 1]; ++s) {
                        const int t = items[s];
                        if (segment_hits(o, d, corner(t, 0), corner(t, 1), corner(t, 2))) { cut[e] = 1; break; }
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
