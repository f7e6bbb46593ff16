// solve_frame_field: linear initialisation + projection, then MBO diffuse/project with the
// schedule of docs/algorithms.md#mbo-smoothing, then the optional relaxed step.
#include <chrono>
#include <cmath>
#include <string>

#include <omp.h>

#include "framefix/core/error.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/frame_field/extrapolation.h"
#include "framefix/frame_field/linear_solver.h"
#include "framefix/frame_field/projection.h"
#include "framefix/frame_field/reorder.h"

namespace framefix {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kRetryDistance = 0.3;  // |q/|q| - proj|: beyond it a warm projection is re-checked
constexpr int kFloorSearch = 100000;    // iterations searched for the first one at the tau floor
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Per-vertex projection onto the frames allowed by the vertex's constraint. Free vertices:
// multi-start (top-5 of 48) when cold; in MBO one Newton run from the previous rotation (the
// iterates move little), retried with the top-5 starts when the result is far from the manifold
// (a frame that jumped: the warm run may sit on a non-global maximum). Normal-aligned:
// rescale (a, b) to the circle of radius sqrt(5/12). Fixed: the constraint itself.
// `only`: project just these vertices (nullptr: all).
void project_field(const ConstrainedSpace& s, FrameCoefficients& q, std::vector<Eigen::Matrix3d>& R, bool warm,
                   int threads, const std::vector<int>* only = nullptr) {
    ProjectionOptions cold;
    cold.starts = 5;
    const ProjectionOptions hot;  // starts_with_warm = 0: the warm start only
    const int nv = only ? int(only->size()) : s.vertices();
    const double radius = std::sqrt(5.0 / 12.0);
#pragma omp parallel for schedule(dynamic, 512) num_threads(threads)
    for (int i = 0; i < nv; ++i) {
        const int v = only ? (*only)[i] : i;
        switch (s.kind[v]) {
            case ConstraintKind::Free: {
                const SH9 qv = q.row(v).transpose();
                ProjectedFrame f = warm ? project_frame_from(qv, R[v], hot) : project_frame(qv, cold);
                if (warm && f.distance > kRetryDistance) {
                    const ProjectedFrame g = project_frame(qv, cold);
                    if (g.distance < f.distance) f = g;
                }
                R[v] = f.rotation;
                q.row(v) = f.q.transpose();
                break;
            }
            case ConstraintKind::NormalAligned: {
                const NormalAligned& fam = s.families[s.family[v]];
                Eigen::Vector2d y = fam.P.transpose() * q.row(v).transpose();
                const double len = y.norm();
                y = len > 1e-12 ? Eigen::Vector2d(radius * y / len) : Eigen::Vector2d(0, radius);
                R[v] = normal_aligned_rotation(fam, y);
                q.row(v) = (fam.c + fam.P * y).transpose();
                break;
            }
            case ConstraintKind::Fixed:
                R[v] = s.fixed_rotation[v];
                q.row(v) = s.c.row(v);
                break;
        }
    }
}

void check_input(const TetMesh& mesh, const TetTopology& topo, const Constraints& cons) {
    const int nv = mesh.num_vertices();
    if (nv == 0 || mesh.num_tets() == 0) throw Error("field", "the tet mesh is empty");
    if (int(cons.kind.size()) != nv)
        throw Error("field", "constraints have " + std::to_string(cons.kind.size()) + " vertices, the mesh " +
                                 std::to_string(nv) + "; recompute boundary_constraints for this mesh");
    if (int(topo.vert_tets_start.size()) != nv + 1)
        throw Error("field", "the topology was built for another mesh; call build_topology(mesh) again");
    bool any_constraint = false;
    for (ConstraintKind k : cons.kind) any_constraint |= k != ConstraintKind::Free;
    if (!any_constraint) throw Error("field", "no vertex is constrained; the field is undetermined");
}

}  // namespace

FrameField solve_frame_field(const TetMesh& mesh, const TetTopology& topo, const Constraints& constraints,
                             const FieldOptions& o) {
    check_input(mesh, topo, constraints);
    const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
    const auto t_start = Clock::now();
    report(o.progress, "field", 0.0);

    // The solve runs on a cache-friendly numbering (reorder.h); results are mapped back at the end.
    std::vector<int> order;
    P1System sys = assemble_p1(mesh, topo, threads);
    ConstrainedSpace space = make_space(constraints);
    if (o.reorder) {
        order = rcm_order(sys);
        sys = permute(sys, order);
        space = permute(space, order);
    }
    ConstrainedSolver solver(sys, space, o.solver, threads, o.large_mesh_vertices);
    const int nv = mesh.num_vertices();

    FrameField out;
    out.solver = solver.name();
    out.kind = constraints.kind;

    // Linear init: minimise E(c + x) over x in V, i.e. Pi K x = -Pi K c.
    FrameCoefficients Kc;
    apply_system(sys, 0.0, 1.0, space.c, Kc, threads);
    FrameCoefficients x = FrameCoefficients::Zero(nv, 9);
    const LinearSolveStats init = solver.solve(0.0, 1.0, -Kc, x, o.cg_tolerance);
    out.linear_iterations += init.iterations;
    out.solve_iterations.push_back(init.iterations);
    FrameCoefficients q = space.c + x;
    std::vector<Eigen::Matrix3d> R(nv, Eigen::Matrix3d::Identity());
    project_field(space, q, R, false, threads);
    out.initial_energy = dirichlet_energy(sys, q, threads);
    out.seconds_init = since(t_start);
    report(o.progress, "field", 0.1);

    // MBO. tau_k = max(tau_0 / k^p, h^2): the first steps smooth globally, the later ones at the
    // mesh scale. Stop on the relative change only once tau sits at its floor (MBO energy is not monotone).
    const auto t_smooth = Clock::now();
    const double lambda1 = std::pow(M_PI / sys.diameter, 2);
    const double tau0 = o.tau_factor / lambda1, tau_floor = sys.mean_edge * sys.mean_edge;
    FrameCoefficients rhs(nv, 9);
    // Before tau reaches its floor the diffusion result is projected and diffused again at a
    // smaller tau, so a rough solve suffices (measured on the notch: 1e-3 changes the final
    // energy by 4e-6 relative and saves 30 % of the CG iterations).
    const double coarse_tol = std::min(1e3 * o.cg_tolerance, std::max(o.cg_tolerance, 1e-3));
    // Warm start: the input plus the last diffusion increment scaled by tau / tau_prev (for small
    // tau the increment ~ -tau M^-1 K q, and q moves little between iterations). Measured on the
    // notch at 59k tets: 1301 -> 813 CG iterations, same MBO iterations, energy within 1e-5.
    FrameCoefficients increment;  // last diffusion output - input, in V
    double last_tau = 0;
    // All buffers live across iterations: at #V x 9 doubles each, fresh allocations were mmap'ed
    // and page-faulted every iteration (6 % of the time at 59k tets).
    auto diffuse = [&](const FrameCoefficients& from, double tau, FrameCoefficients& result) {
        // (M + tau K)(c + x) = M from  =>  (M + tau K) x = M (from - c) - tau K c
        const double scale = increment.rows() ? tau / last_tau : 0.0;
        if (!increment.rows()) increment.setZero(nv, 9);
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int v = 0; v < nv; ++v) {  // one parallel pass (these were 3 serial Eigen passes)
            const auto xv = from.row(v) - space.c.row(v);
            rhs.row(v) = sys.mass(v) * xv - tau * Kc.row(v);
            x.row(v) = xv + scale * increment.row(v);
        }
        const double tol = tau > tau_floor ? coarse_tol : o.cg_tolerance;
        const LinearSolveStats st = solver.solve(1.0, tau, rhs, x, tol);
        out.linear_iterations += st.iterations;
        out.solve_iterations.push_back(st.iterations);
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int v = 0; v < nv; ++v) {
            result.row(v) = space.c.row(v) + x.row(v);
            increment.row(v) = result.row(v) - from.row(v);
        }
        last_tau = tau;
    };
    FrameCoefficients next(nv, 9);
    FloorExtrapolation extrapolation(
        sys,
        [&](FrameCoefficients& f, std::vector<Eigen::Matrix3d>& rot, const std::vector<int>& only) {
            project_field(space, f, rot, true, threads, &only);
        },
        threads);
    const auto tau_at = [&](int k) { return std::max(tau0 / std::pow(double(k), o.tau_power), tau_floor); };
    out.floor_iteration = 1;  // bounded: a tau_power <= 0 never reaches the floor
    while (out.floor_iteration < kFloorSearch && tau_at(out.floor_iteration) > tau_floor) ++out.floor_iteration;
    const bool large = o.large_mesh_vertices > 0 && nv >= o.large_mesh_vertices;
    out.iteration_cap = large && o.floor_iterations > 0
                            ? std::max(o.max_iterations, out.floor_iteration - 1 + o.floor_iterations)
                            : o.max_iterations;
    for (int k = 1; k <= out.iteration_cap; ++k) {
        const double tau = tau_at(k);
        diffuse(q, tau, next);
        project_field(space, next, R, true, threads);
        const double change = mass_norm_diff(sys, next, q, threads) /
                              std::max(1e-300, mass_norm_diff(sys, next, FrameCoefficients(), threads));
        const bool done = tau <= tau_floor && change < o.tolerance;
        if (o.extrapolate && tau <= tau_floor && !done) out.extrapolations += extrapolation.after_step(q, next, R);
        q.swap(next);
        out.iterations = k;
        out.change_history.push_back(change);
        out.energy_history.push_back(dirichlet_energy(sys, q, threads));
        report(o.progress, "field", 0.1 + 0.85 * double(k) / out.iteration_cap);
        if (done) {
            out.converged = true;
            break;
        }
    }
    out.energy = dirichlet_energy(sys, q, threads);

    out.distance = Eigen::VectorXd::Zero(nv);
    if (o.relaxed_final_step) {
        // Ginzburg-Landau-like relaxation: |q| drops below 1 only near singular curves (docs/algorithms.md#relaxed-final-step).
        FrameCoefficients relaxed(nv, 9);
        diffuse(q, 2.0 * tau_floor, relaxed);
        out.relaxed_norm = relaxed.rowwise().norm();
        FrameCoefficients projected = relaxed;
        project_field(space, projected, R, true, threads);
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int v = 0; v < nv; ++v) {
            const double len = relaxed.row(v).norm();
            out.distance(v) = len > 1e-12 ? (relaxed.row(v) / len - projected.row(v)).norm() : std::sqrt(2.0);
        }
        q = relaxed;
    }
    out.coefficients.resize(nv, 9);
    out.axes.resize(nv, 9);
    const bool has_relaxed = out.relaxed_norm.size() == nv;
    const Eigen::VectorXd distance = out.distance, relaxed_norm = out.relaxed_norm;
    for (int v = 0; v < nv; ++v) {
        const int w = o.reorder ? order[v] : v;  // input vertex of solver row v
        out.coefficients.row(w) = q.row(v);
        for (int a = 0; a < 3; ++a) out.axes.block<1, 3>(w, 3 * a) = R[v].col(a).transpose();
        out.distance(w) = distance(v);
        if (has_relaxed) out.relaxed_norm(w) = relaxed_norm(v);
    }
    out.seconds_smooth = since(t_smooth);
    report(o.progress, "field", 1.0);
    return out;
}

}  // namespace framefix
