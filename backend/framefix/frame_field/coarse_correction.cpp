// Aggregation and the coarse solve of the two-level preconditioner (coarse_correction.h).
#include "framefix/frame_field/coarse_correction.h"

#include <algorithm>

#include <Eigen/SparseCholesky>

#include "framefix/core/error.h"

namespace framefix {
namespace {

using Graph = std::vector<std::vector<int>>;  // adjacency lists, sorted, no self loops

// Greedy aggregation (Vanek et al.'s first two passes): a node whose neighbours are all free
// starts an aggregate with them; the rest join a neighbour's aggregate; isolated nodes stand
// alone. Visiting nodes in index order makes it deterministic.
std::vector<int> aggregate(const Graph& g, int& count) {
    const int n = int(g.size());
    std::vector<int> of(n, -1);
    count = 0;
    for (int v = 0; v < n; ++v) {
        if (of[v] >= 0) continue;
        bool free = true;
        for (int u : g[v]) free &= of[u] < 0;
        if (!free) continue;
        of[v] = count;
        for (int u : g[v]) of[u] = count;
        ++count;
    }
    std::vector<int> joined = of;
    for (int v = 0; v < n; ++v) {
        if (of[v] >= 0) continue;
        for (int u : g[v])
            if (of[u] >= 0) {
                joined[v] = of[u];
                break;
            }
        if (joined[v] < 0) joined[v] = count++;
    }
    return joined;
}

// The graph of the aggregates: two are adjacent when a node of one neighbours a node of the other.
Graph coarse_graph(const Graph& g, const std::vector<int>& of, int count) {
    Graph c(count);
    for (int v = 0; v < int(g.size()); ++v)
        for (int u : g[v])
            if (of[u] != of[v]) c[of[v]].push_back(of[u]);
    for (auto& row : c) {
        std::sort(row.begin(), row.end());
        row.erase(std::unique(row.begin(), row.end()), row.end());
    }
    return c;
}

}  // namespace

struct CoarseCorrection::Factor {
    Eigen::SparseMatrix<double> K, M, A;  // R K R^T, R M R^T, the current weighted sum
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
    Eigen::MatrixXd Rr, y;                // #aggregates x 9, column-major for the solve
};

CoarseCorrection::~CoarseCorrection() = default;

CoarseCorrection::CoarseCorrection(const P1System& sys, const ConstrainedSpace& space)
    : factor_(std::make_unique<Factor>()) {
    const int nv = sys.rows();
    // Free vertices and the mesh edges between them.
    std::vector<int> index(nv, -1), vertex;
    for (int v = 0; v < nv; ++v)
        if (space.kind[v] == ConstraintKind::Free) index[v] = int(vertex.size()), vertex.push_back(v);
    Graph g(vertex.size());
    for (int i = 0; i < int(vertex.size()); ++i)
        for (int k = sys.row_start[vertex[i]]; k < sys.row_start[vertex[i] + 1]; ++k) {
            const int j = index[sys.col[k]];
            if (j >= 0 && j != i) g[i].push_back(j);
        }
    // Two rounds: one round gives aggregates of about 15 vertices, too many for a cheap coarse
    // factorisation at 1M tets; two give a few hundred vertices each.
    int first = 0;
    const std::vector<int> of1 = aggregate(g, first);
    const std::vector<int> of2 = aggregate(coarse_graph(g, of1, first), aggregates_);
    aggregate_of_.assign(nv, -1);
    for (int i = 0; i < int(vertex.size()); ++i) aggregate_of_[vertex[i]] = of2[of1[i]];

    std::vector<Eigen::Triplet<double>> k, m;
    for (int v : vertex) {
        const int a = aggregate_of_[v];
        m.emplace_back(a, a, sys.mass(v));
        for (int e = sys.row_start[v]; e < sys.row_start[v + 1]; ++e) {
            const int b = aggregate_of_[sys.col[e]];
            if (b >= 0) k.emplace_back(a, b, sys.K[e]);
        }
    }
    Factor& f = *factor_;
    f.K.resize(aggregates_, aggregates_);
    f.M.resize(aggregates_, aggregates_);
    f.K.setFromTriplets(k.begin(), k.end());
    f.M.setFromTriplets(m.begin(), m.end());
    f.A = f.K + f.M;  // the union pattern (M is diagonal, K has the diagonal)
    f.ldlt.analyzePattern(f.A);
}

void CoarseCorrection::factorize(double mw, double sw) {
    Factor& f = *factor_;
    f.A = sw * f.K + mw * f.M;
    f.ldlt.factorize(f.A);
    if (f.ldlt.info() != Eigen::Success) throw Error("field", "the coarse correction matrix is not positive definite");
}

double CoarseCorrection::solve(const FrameCoefficients& r, FrameCoefficients& y) {
    Factor& f = *factor_;
    f.Rr.setZero(aggregates_, 9);
    for (int v = 0; v < int(aggregate_of_.size()); ++v)  // serial: the sums do not depend on threads
        if (aggregate_of_[v] >= 0) f.Rr.row(aggregate_of_[v]) += r.row(v);
    f.y = f.ldlt.solve(f.Rr);
    y = f.y;
    return (f.Rr.array() * f.y.array()).sum();
}

}  // namespace framefix
