#include "framefix/streamlines/tet_locator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace framefix {

TetLocator::TetLocator(const TetMesh& mesh, const TetTopology& topo) : mesh_(mesh) {
    const int nt = mesh.num_tets();
    neighbours_.assign(4 * size_t(nt), -1);
    inverse_.resize(nt);
    for (int t = 0; t < nt; ++t) {
        for (int lf = 0; lf < 4; ++lf) {
            const int f = topo.tet_faces(t, lf);
            const int a = topo.face_tets(f, 0), b = topo.face_tets(f, 1);
            neighbours_[4 * t + lf] = a == t ? b : a;
        }
        Eigen::Matrix3d d;
        const Eigen::Vector3d p0 = mesh.points.row(mesh.tets(t, 0)).transpose();
        for (int k = 0; k < 3; ++k) d.col(k) = mesh.points.row(mesh.tets(t, k + 1)).transpose() - p0;
        inverse_[t] = d.inverse();
    }
    mean_edge_ = mean_edge_length(mesh, topo, 1);

    lo_ = mesh.points.colwise().minCoeff().transpose();
    hi_ = mesh.points.colwise().maxCoeff().transpose();
    // About one tet per cell on average keeps the lists short.
    const Eigen::Vector3d ext = (hi_ - lo_).cwiseMax(1e-12);
    cell_ = std::max(std::cbrt(ext.prod() / std::max(nt, 1)), 1e-12) * 1.5;
    for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, int(std::ceil(ext[k] / cell_)));
    const size_t ncell = size_t(dims_[0]) * dims_[1] * dims_[2];
    std::vector<int> count(ncell + 1, 0);
    auto cell_range = [&](int t, Eigen::Vector3i& a, Eigen::Vector3i& b) {
        Eigen::Vector3d tlo = mesh.points.row(mesh.tets(t, 0)).transpose(), thi = tlo;
        for (int k = 1; k < 4; ++k) {
            tlo = tlo.cwiseMin(mesh.points.row(mesh.tets(t, k)).transpose());
            thi = thi.cwiseMax(mesh.points.row(mesh.tets(t, k)).transpose());
        }
        for (int k = 0; k < 3; ++k) {
            a[k] = std::clamp(int((tlo[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
            b[k] = std::clamp(int((thi[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
        }
    };
    auto cell_id = [&](int i, int j, int k) { return (size_t(k) * dims_[1] + j) * dims_[0] + i; };
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            for (size_t c = 0; c < ncell; ++c) count[c + 1] += count[c];
            cell_start_ = count;
            cell_tets_.resize(count[ncell]);
        }
        for (int t = 0; t < nt; ++t) {
            Eigen::Vector3i a, b;
            cell_range(t, a, b);
            for (int k = a[2]; k <= b[2]; ++k)
                for (int j = a[1]; j <= b[1]; ++j)
                    for (int i = a[0]; i <= b[0]; ++i) {
                        if (pass == 0) count[cell_id(i, j, k) + 1] += 1;
                        else cell_tets_[count[cell_id(i, j, k)]++] = t;
                    }
        }
    }
}

Eigen::Vector4d TetLocator::barycentric(int tet, const Eigen::Vector3d& p) const {
    const Eigen::Vector3d l = inverse_[tet] * (p - mesh_.points.row(mesh_.tets(tet, 0)).transpose());
    return {1 - l.sum(), l[0], l[1], l[2]};
}

TetLocation TetLocator::locate_in_grid(const Eigen::Vector3d& p) const {
    TetLocation r;
    Eigen::Vector3i c;
    for (int k = 0; k < 3; ++k) {
        const double x = (p[k] - lo_[k]) / cell_;
        if (x < -1e-9 || x > dims_[k] + 1e-9) return r;
        c[k] = std::clamp(int(x), 0, dims_[k] - 1);
    }
    const size_t id = (size_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
    double best = -1e300;
    for (int i = cell_start_[id]; i < cell_start_[id + 1]; ++i) {
        const int t = cell_tets_[i];
        const Eigen::Vector4d l = barycentric(t, p);
        if (l.minCoeff() > best) best = l.minCoeff(), r.tet = t, r.bary = l;
    }
    // Points on a face or edge are inside up to round-off.
    if (best < -1e-9) r.tet = -1;
    return r;
}

TetLocation TetLocator::locate(const Eigen::Vector3d& p, int start) const {
    if (start < 0) return locate_in_grid(p);
    int t = start;
    // A walk visits O(distance / h) tets; the cap only catches cycles on degenerate tets.
    for (int it = 0; it < 500; ++it) {
        const Eigen::Vector4d l = barycentric(t, p);
        int lf = 0;
        const double m = l.minCoeff(&lf);
        if (m >= -1e-12) return {t, l};
        const int next = neighbours_[4 * t + lf];
        if (next < 0) {
            // Leaving through a boundary face is only final if p is outside that face's plane for
            // every direction of approach: confirm with the grid (concave parts).
            return locate_in_grid(p);
        }
        t = next;
    }
    return locate_in_grid(p);
}

}  // namespace framefix
