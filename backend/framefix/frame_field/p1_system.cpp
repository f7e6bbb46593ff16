#include "framefix/frame_field/p1_system.h"

#include <algorithm>
#include <string>

#include <Eigen/LU>

#include "framefix/core/error.h"

namespace framefix {
namespace {

// Gradients of the four barycentric coordinates (columns) and the volume of tet t.
bool tet_gradients(const TetMesh& mesh, int t, Eigen::Matrix<double, 3, 4>& G, double& volume) {
    const Eigen::Vector3d p0 = mesh.points.row(mesh.tets(t, 0));
    Eigen::Matrix3d E;  // rows: edges from vertex 0
    for (int k = 0; k < 3; ++k) E.row(k) = mesh.points.row(mesh.tets(t, k + 1)) - p0.transpose();
    const double det = E.determinant();
    volume = det / 6.0;
    if (!(det > 0)) return false;
    const Eigen::Matrix3d Einv = E.inverse();  // column k = grad of barycentric k+1
    G.rightCols<3>() = Einv;
    G.col(0) = -Einv.rowwise().sum();
    return true;
}

}  // namespace

P1System assemble_p1(const TetMesh& mesh, const TetTopology& topo, int threads) {
    const int nv = mesh.num_vertices();
    P1System s;
    s.row_start.assign(nv + 1, 0);
    for (int e = 0; e < topo.edges.rows(); ++e) {
        s.row_start[topo.edges(e, 0) + 1] += 1;
        s.row_start[topo.edges(e, 1) + 1] += 1;
    }
    for (int v = 0; v < nv; ++v) s.row_start[v + 1] += s.row_start[v] + 1;  // + diagonal
    s.col.resize(s.row_start[nv]);
    std::vector<int> fill(s.row_start.begin(), s.row_start.end() - 1);
    for (int v = 0; v < nv; ++v) s.col[fill[v]++] = v;
    for (int e = 0; e < topo.edges.rows(); ++e) {
        const int a = topo.edges(e, 0), b = topo.edges(e, 1);
        s.col[fill[a]++] = b;
        s.col[fill[b]++] = a;
    }
    s.diag.resize(nv);
    s.K.assign(s.col.size(), 0.0);
    s.mass = Eigen::VectorXd::Zero(nv);
    int bad_tet = -1;

#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
    for (int v = 0; v < nv; ++v) {
        int* first = s.col.data() + s.row_start[v];
        int* last = s.col.data() + s.row_start[v + 1];
        std::sort(first, last);
        s.diag[v] = int(std::lower_bound(first, last, v) - s.col.data());
        for (int k = topo.vert_tets_start[v]; k < topo.vert_tets_start[v + 1]; ++k) {
            const int t = topo.vert_tets[k];
            Eigen::Matrix<double, 3, 4> G;
            double vol;
            if (!tet_gradients(mesh, t, G, vol)) {
#pragma omp critical(ff_bad_tet)
                bad_tet = std::max(bad_tet, t);
                continue;
            }
            int lv = 0;
            while (mesh.tets(t, lv) != v) ++lv;
            s.mass(v) += vol / 4.0;
            for (int j = 0; j < 4; ++j) {
                const int u = mesh.tets(t, j);
                const int pos = int(std::lower_bound(first, last, u) - s.col.data());
                s.K[pos] += vol * G.col(lv).dot(G.col(j));
            }
        }
    }
    if (bad_tet >= 0)
        throw Error("field", "tet " + std::to_string(bad_tet) +
                                 " is flat or inverted (volume <= 0); re-mesh or orient the tets positively");

    s.mean_edge = mean_edge_length(mesh, topo);
    s.diameter = nv ? (mesh.points.colwise().maxCoeff() - mesh.points.colwise().minCoeff()).norm() : 0.0;
    return s;
}

}  // namespace framefix
