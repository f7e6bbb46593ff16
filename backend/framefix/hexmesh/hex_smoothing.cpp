#include <algorithm>

#include "framefix/hexmesh/hex_grid.h"

namespace framefix {

namespace {

double worst_of(const HexMesh& m, const std::vector<int>& hexes) {
    double worst = 1;
    for (int h : hexes) {
        std::array<Eigen::Vector3d, 8> p;
        for (int c = 0; c < 8; ++c) p[c] = m.points.row(m.hexes[size_t(h)][c]).transpose();
        worst = std::min(worst, hex_scaled_jacobian(p));
    }
    return worst;
}

}  // namespace

void smooth_hex_mesh(int rounds, HexMesh& m) {
    const int nv = int(m.points.rows());
    std::vector<char> fixed(static_cast<size_t>(nv), 0);
    for (const auto& q : m.boundary_quads)
        for (int v : q) fixed[size_t(v)] = 1;
    std::vector<std::vector<int>> nb(static_cast<size_t>(nv)), around(static_cast<size_t>(nv));
    for (size_t h = 0; h < m.hexes.size(); ++h) {
        const auto& x = m.hexes[h];
        for (int c = 0; c < 8; ++c) around[size_t(x[c])].push_back(int(h));
        for (const auto& e : kHexEdges) nb[size_t(x[e[0]])].push_back(x[e[1]]), nb[size_t(x[e[1]])].push_back(x[e[0]]);
    }
    for (auto& n : nb) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    for (int round = 0; round < rounds; ++round) {
        int moved = 0;
        for (int v = 0; v < nv; ++v) {
            if (fixed[size_t(v)] || nb[size_t(v)].empty()) continue;
            Eigen::Vector3d mean = Eigen::Vector3d::Zero();
            for (int w : nb[size_t(v)]) mean += m.points.row(w).transpose();
            mean /= double(nb[size_t(v)].size());
            const Eigen::Vector3d old = m.points.row(v).transpose();
            if ((mean - old).squaredNorm() == 0) continue;
            const double before = worst_of(m, around[size_t(v)]);
            m.points.row(v) = mean.transpose();
            if (worst_of(m, around[size_t(v)]) < before) m.points.row(v) = old.transpose();
            else ++moved;
        }
        if (!moved) break;
    }
}

}  // namespace framefix
