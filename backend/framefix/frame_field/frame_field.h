#pragma once
// Boundary-aligned frame field on a tet mesh (ALGORITHMS.md §3): constraints per vertex from the
// boundary and the feature curves, linear initialisation, then MBO diffuse-project iterations.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framefix/core/progress.h"
#include "framefix/frame_field/sh.h"
#include "framefix/mesh/features.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

enum class ConstraintKind : int { Free = 0, NormalAligned = 1, Fixed = 2 };

struct Constraints {
    std::vector<ConstraintKind> kind;                        // #V
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> normal;  // #V x 3, NormalAligned rows
    Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> fixed;   // #V x 9, Fixed rows (unit frames)
};

// Fixed frames on feature-curve vertices and corners, normal-aligned on smooth boundary vertices,
// free inside. Feature valences come from `features` (keyed by the mesh's edge tags).
Constraints boundary_constraints(const TetMesh& mesh, const TetTopology& topo, const FeatureSet& features);

struct FieldOptions {
    int max_iterations = 60;     // MBO outer iterations
    double tolerance = 1e-4;     // relative change |q_k - q_k-1|_M / |q_k|_M once tau is at its floor
    bool relaxed_final_step = false;  // one last diffusion without projection (tau = 2 h_mean^2)
    int threads = 0;             // OpenMP threads, 0 = all
    ProgressSink progress;       // "field" stage
};

using FrameCoefficients = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;

struct FrameField {
    FrameCoefficients coefficients;  // #V x 9, SH band-4, unit norm on frames
    Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> axes;  // #V x 9: axes a1 a2 a3 (columns of R) row by row
    Eigen::VectorXd distance;        // #V distance to the frame manifold (non-zero only if relaxed)
    std::vector<ConstraintKind> kind;  // #V copy of the constraint kind
    double energy = 0;               // sum_c q_c^T K q_c of the final field
    double initial_energy = 0;       // after linear init + projection
    std::vector<double> energy_history;  // one entry per MBO iteration
    int iterations = 0;
    double seconds_init = 0, seconds_smooth = 0;
    std::string solver;              // which sparse solver ran
};

FrameField solve_frame_field(const TetMesh& mesh, const TetTopology& topo, const Constraints& constraints,
                             const FieldOptions& options = {});

}  // namespace framefix
