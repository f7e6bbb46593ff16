#pragma once
// P1 finite elements on a tet mesh (docs/algorithms.md#p1-system): the scalar stiffness matrix K and the
// lumped mass M, shared by the nine SH channels. Internal to frame_field.
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

// Symmetric matrix with its full pattern in CSR, rows = mesh vertices, columns sorted.
struct P1System {
    std::vector<int> row_start;   // #V + 1
    std::vector<int> col;         // nnz, vertex index
    std::vector<double> K;        // nnz, K_ij = sum_tets |t| grad phi_i . grad phi_j, model units
    std::vector<int> diag;        // #V, position of (i, i) in col/K
    Eigen::VectorXd mass;         // #V, lumped mass M_ii = sum_{tets at i} |t| / 4, model units^3
    double mean_edge = 0;         // h_mean over the unique mesh edges
    double diameter = 0;          // bounding-box diagonal

    int rows() const { return int(row_start.size()) - 1; }
};

// Row-parallel: each row sums its own tets' contributions, so the result does not depend on
// the thread count. Throws Error("field") on a flat or inverted tet.
P1System assemble_p1(const TetMesh& mesh, const TetTopology& topo, int threads);

}  // namespace framefix
