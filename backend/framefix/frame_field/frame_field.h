#pragma once
// Boundary-aligned frame field on a tet mesh (docs/algorithms.md#frame-field): constraints per vertex from the
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
    // #V or empty. A Fixed vertex flagged here holds a singular frame with one imposed axis,
    // normal.row(v): the axisymmetric element sqrt(7/12) D(R_n) e4 of that axis's tangency family,
    // where a cross about the axis vanishes (the singular-node extrusion's constraint). Its fixed
    // row is ignored.
    std::vector<char> singular;
};

// Makes vertex v a singular frame about `axis` (Constraints::singular), sizing the flags first.
void set_singular(Constraints& cons, int v, const Eigen::Vector3d& axis);

// Fixed frames on feature-curve vertices and corners, normal-aligned on smooth boundary vertices,
// free inside. Feature valences come from `features` (keyed by the mesh's edge tags).
Constraints boundary_constraints(const TetMesh& mesh, const FeatureSet& features);

// Sparse solver of the diffusion systems (linear_solver.h). ConjugateGradient won the
// measurement in bench/bench_field.cpp (see the commit message / report); the direct ones stay
// selectable for comparison.
enum class SparseSolver : int { ConjugateGradient = 0, SimplicialLDLT = 1, Cholmod = 2 };

struct FieldOptions {
    int max_iterations = 60;     // MBO outer iterations (0: linear init + projection only)
    double tolerance = 1e-4;     // relative change |q_k - q_k-1|_M / |q_k|_M once tau is at its floor
    bool relaxed_final_step = false;  // one last diffusion without projection (tau = 2 h_mean^2)
    int threads = 0;             // OpenMP threads, 0 = all
    ProgressSink progress;       // "field" stage
    SparseSolver solver = SparseSolver::ConjugateGradient;
    double tau_factor = 50;      // tau_0 = tau_factor / lambda_1, lambda_1 ~ (pi / bbox diagonal)^2
    double tau_power = 3;        // tau_k = max(tau_0 / k^tau_power, h_mean^2)
    double cg_tolerance = 1e-6;  // relative residual of each MBO diffusion solve (init: x 1e-2)
    bool reorder = true;         // solve on a reverse Cuthill-McKee vertex numbering (cache locality)
    // Large meshes, from this many vertices on (0: never; docs/algorithms.md#large-meshes):
    // projected CG adds a two-level coarse correction, and the MBO cap is raised to leave at
    // least floor_iterations iterations at the tau floor, which a finer mesh reaches later
    // (k_floor ~ (tau_0 / h^2)^(1/3): about 17 at the default size, 32 at 1M tets).
    int large_mesh_vertices = 100000;
    int floor_iterations = 43;   // what the cap of 60 leaves at the default size (0: max_iterations is a hard cap)
    bool extrapolate = false;    // at the tau floor, jump along a drifting slow mode (Aitken; evaluated, off)
};

using FrameCoefficients = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;

struct FrameField {
    FrameCoefficients coefficients;  // #V x 9, SH band-4, unit norm on frames; the relaxed field
                                     // (|q| < 1 near singularities) if relaxed_final_step
    Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> axes;  // #V x 9: axes a1 a2 a3 (columns of R) row by row;
                                     // normal-aligned vertices: a3 = n; fixed: the constraint's rotation
    Eigen::VectorXd distance;        // #V |q/|q| - proj(q)|, 0..~1.3 (non-zero only if relaxed)
    std::vector<ConstraintKind> kind;  // #V copy of the constraint kind
    double energy = 0;               // sum_c q_c^T K q_c of the final field
    double initial_energy = 0;       // after linear init + projection
    std::vector<double> energy_history;  // one entry per MBO iteration
    std::vector<double> change_history;  // one entry per MBO iteration: |q_k - q_k-1|_M / |q_k|_M
    int iterations = 0;              // MBO iterations run
    int floor_iteration = 0;         // first MBO iteration with tau at its floor h_mean^2
    int iteration_cap = 0;           // MBO iterations allowed: max_iterations, raised on large meshes
    int linear_iterations = 0;       // CG iterations summed over all solves (direct: number of solves)
    std::vector<int> solve_iterations;  // per solve: linear init, then one per diffusion
    bool converged = false;          // stopped on the change test (not on max_iterations)
    int extrapolations = 0;          // jumps kept at the tau floor (FieldOptions::extrapolate)
    double seconds_init = 0;         // assembly + constraints + linear solve + projection, wall clock
    double seconds_smooth = 0;       // MBO (+ relaxed step), wall clock
    std::string solver;              // which sparse solver ran
    Eigen::VectorXd relaxed_norm;    // #V |q| of the relaxed field (empty unless relaxed_final_step)
};

FrameField solve_frame_field(const TetMesh& mesh, const TetTopology& topo, const Constraints& constraints,
                             const FieldOptions& options = {});

}  // namespace framefix
