#include <algorithm>

#include "framefix/hexmesh/hex_grid.h"

namespace framefix {

namespace {

// Smallest scaled Jacobian of the 8 hexes around interior vertex (i, j, k).
double worst_around(const HexGrid& g, const HexGrid::BlockGrid& b, int i, int j, int k) {
    double worst = 1;
    for (int dk = -1; dk <= 0; ++dk)
        for (int dj = -1; dj <= 0; ++dj)
            for (int di = -1; di <= 0; ++di) {
                const std::array<int, 8> h = hex_of(b, i + di, j + dj, k + dk);
                std::array<Eigen::Vector3d, 8> p;
                for (int c = 0; c < 8; ++c) p[c] = g.points[size_t(h[c])];
                worst = std::min(worst, hex_scaled_jacobian(p));
            }
    return worst;
}

}  // namespace

void smooth_hex_grid(int rounds, HexGrid& g) {
    for (int round = 0; round < rounds; ++round) {
        int moved = 0;
        for (const HexGrid::BlockGrid& b : g.block_ids)
            for (int k = 1; k < b.n[2]; ++k)
                for (int j = 1; j < b.n[1]; ++j)
                    for (int i = 1; i < b.n[0]; ++i) {
                        Eigen::Vector3d& x = g.points[size_t(b.at(i, j, k))];
                        const Eigen::Vector3d mean = (g.points[size_t(b.at(i - 1, j, k))] + g.points[size_t(b.at(i + 1, j, k))] +
                                                      g.points[size_t(b.at(i, j - 1, k))] + g.points[size_t(b.at(i, j + 1, k))] +
                                                      g.points[size_t(b.at(i, j, k - 1))] + g.points[size_t(b.at(i, j, k + 1))]) / 6;
                        if ((mean - x).squaredNorm() == 0) continue;
                        const double before = worst_around(g, b, i, j, k);
                        const Eigen::Vector3d old = x;
                        x = mean;
                        if (worst_around(g, b, i, j, k) < before) x = old;
                        else ++moved;
                    }
        if (!moved) break;
    }
}

}  // namespace framefix
