#include "framefix/corrections/boundary_distance.h"

#include <algorithm>
#include <vector>

namespace framefix {
namespace {

Points centroids_of(const TetMesh& mesh) {
    Points c(mesh.boundary_faces.rows(), 3);
    for (Eigen::Index f = 0; f < mesh.boundary_faces.rows(); ++f)
        c.row(f) = (mesh.points.row(mesh.boundary_faces(f, 0)) + mesh.points.row(mesh.boundary_faces(f, 1)) +
                    mesh.points.row(mesh.boundary_faces(f, 2))) / 3.0;
    return c;
}

double mean_edge(const TetMesh& mesh) {
    double sum = 0;
    for (Eigen::Index f = 0; f < mesh.boundary_faces.rows(); ++f)
        sum += (mesh.points.row(mesh.boundary_faces(f, 0)) - mesh.points.row(mesh.boundary_faces(f, 1))).norm();
    return mesh.boundary_faces.rows() ? sum / double(mesh.boundary_faces.rows()) : 1.0;
}

}  // namespace

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = 1 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

BoundaryDistance::BoundaryDistance(const TetMesh& mesh) : mesh_(mesh), centroids_(centroids_of(mesh), mean_edge(mesh)) {
    const Points c = centroids_of(mesh);
    for (Eigen::Index f = 0; f < c.rows(); ++f)
        for (int k = 0; k < 3; ++k) reach_ = std::max(reach_, (mesh.points.row(mesh.boundary_faces(f, k)) - c.row(f)).norm());
}

bool BoundaryDistance::within(const Eigen::Vector3d& p, double radius) const {
    std::vector<int> candidates;
    centroids_.within(p, radius + reach_, candidates);
    for (int f : candidates) {
        const Eigen::Vector3d a = mesh_.points.row(mesh_.boundary_faces(f, 0)), b = mesh_.points.row(mesh_.boundary_faces(f, 1)),
                              c = mesh_.points.row(mesh_.boundary_faces(f, 2));
        if ((closest_on_triangle(p, a, b, c) - p).norm() < radius) return true;
    }
    return false;
}

std::vector<std::pair<int, double>> BoundaryDistance::near(const Eigen::Vector3d& p, double radius) const {
    std::vector<int> candidates;
    centroids_.within(p, radius + reach_, candidates);
    std::vector<std::pair<int, double>> out;
    for (int f : candidates) {
        const double d = (closest_on_triangle(p, mesh_.points.row(mesh_.boundary_faces(f, 0)).transpose(),
                                              mesh_.points.row(mesh_.boundary_faces(f, 1)).transpose(),
                                              mesh_.points.row(mesh_.boundary_faces(f, 2)).transpose()) - p).norm();
        if (d < radius) out.emplace_back(f, d);
    }
    return out;
}

Eigen::Vector3d BoundaryDistance::closest(const Eigen::Vector3d& p, double radius) const {
    std::vector<int> candidates;
    centroids_.within(p, radius + reach_, candidates);
    Eigen::Vector3d best = p;
    double d = radius;
    for (int f : candidates) {
        const Eigen::Vector3d q = closest_on_triangle(p, mesh_.points.row(mesh_.boundary_faces(f, 0)).transpose(),
                                                      mesh_.points.row(mesh_.boundary_faces(f, 1)).transpose(),
                                                      mesh_.points.row(mesh_.boundary_faces(f, 2)).transpose());
        if ((q - p).norm() < d) d = (q - p).norm(), best = q;
    }
    return best;
}

}  // namespace framefix
