#include "framefix/singularities/cube_group.h"

#include <algorithm>

#include <Eigen/LU>

#include "framefix/core/error.h"

namespace framefix::cube {
namespace {

struct Tables {
    std::array<Element, kOrder> el;
    std::array<Eigen::Matrix3d, kOrder> mat;
    int mul[kOrder][kOrder];
    int inv[kOrder];
};

int find(const Tables& t, const Eigen::Matrix3d& m) {
    for (int g = 0; g < kOrder; ++g)
        if ((t.mat[g] - m).cwiseAbs().maxCoeff() < 1e-9) return g;
    FF_ASSERT(false);
    return -1;
}

Tables build() {
    Tables t{};
    std::array<int, 3> perm = {0, 1, 2};
    int n = 0;
    // Identity first: the permutations come in lexicographic order starting from (0,1,2) and the
    // sign patterns start from (+,+,+).
    do {
        for (int s = 0; s < 8; ++s) {
            Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
            Element e{};
            for (int j = 0; j < 3; ++j) {
                e.col_row[j] = perm[j];
                e.col_sign[j] = (s >> j) & 1 ? -1 : 1;
                m(perm[j], j) = e.col_sign[j];
            }
            if (m.determinant() < 0) continue;
            FF_ASSERT(n < kOrder);
            t.el[n] = e;
            t.mat[n] = m;
            ++n;
        }
    } while (std::next_permutation(perm.begin(), perm.end()));
    FF_ASSERT(n == kOrder);
    for (int a = 0; a < kOrder; ++a) {
        for (int b = 0; b < kOrder; ++b) t.mul[a][b] = find(t, t.mat[a] * t.mat[b]);
        t.inv[a] = find(t, t.mat[a].transpose());
    }
    return t;
}

const Tables& tables() {
    static const Tables t = build();
    return t;
}

}  // namespace

const std::array<Element, kOrder>& elements() { return tables().el; }
Eigen::Matrix3d matrix(int g) { return tables().mat[g]; }
int multiply(int a, int b) { return tables().mul[a][b]; }
int inverse(int g) { return tables().inv[g]; }
int trace(int g) { return int(tables().mat[g].trace()); }

Eigen::Vector3d axis(int g) {
    const Eigen::Matrix3d& m = tables().mat[g];
    const int tr = trace(g);
    if (tr == 3) return Eigen::Vector3d::Zero();
    if (tr == -1) {
        // 180 deg: m = 2 a a^T - I, so a column of (m + I) is along a; take the longest one.
        Eigen::Matrix3d p = m + Eigen::Matrix3d::Identity();
        int best = 0;
        for (int j = 1; j < 3; ++j)
            if (p.col(j).norm() > p.col(best).norm()) best = j;
        return p.col(best).normalized();
    }
    // 90 and 120 deg: the antisymmetric part is sin(angle) [a]_x with sin > 0.
    Eigen::Vector3d v(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
    return v.normalized();
}

int match(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb, double* cos_angle) {
    const Eigen::Matrix3d M = Ra.transpose() * Rb;
    const auto& el = tables().el;
    // trace(M g) = sum_j M(j, row_j) * sign_j for the column pattern of g.
    int best = 0;
    double best_tr = -1e300;
    for (int g = 0; g < kOrder; ++g) {
        const Element& e = el[g];
        const double tr = M(0, e.col_row[0]) * e.col_sign[0] + M(1, e.col_row[1]) * e.col_sign[1] +
                          M(2, e.col_row[2]) * e.col_sign[2];
        if (tr > best_tr) {
            best_tr = tr;
            best = g;
        }
    }
    if (cos_angle) *cos_angle = std::clamp((best_tr - 1) / 2, -1.0, 1.0);
    return best;
}

}  // namespace framefix::cube
