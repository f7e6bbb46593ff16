// bench_field MESH.msh [threads] [cg|ldlt|cholmod] [max_iterations]   (env FF_REORDER=0: input numbering,
// FF_EXTRAPOLATE=1: extrapolation at the MBO floor, FF_LARGE_MESH_VERTICES=N: large-mesh settings from N vertices)
// Reads a gmsh/Medit tet mesh, finds its crease features, solves the frame field, prints one
// line of figures. Peer reference (Ray et al. initialisation alone, 2 cores, HexMe notch):
// 59k tets 0.79 s, 233k tets 4.4 s, 1.07M tets 40 s.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/resource.h>

#include "framefix/core/error.h"
#include "framefix/core/memory.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/mesh/mesh_io.h"

using namespace framefix;

// User + system time of the process (all threads): the 2 cores are shared, so wall time is noisy.
static double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_field MESH.msh [threads] [cg|ldlt|cholmod] [max_iterations]\n");
        return 2;
    }
    try {
        using Clock = std::chrono::steady_clock;
        auto t0 = Clock::now();
        auto seconds = [](Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); };
        CreaseFeatures cf = detect_crease_features(read_tet_mesh(argv[1]));
        const double t_load = seconds(t0);
        auto t1 = Clock::now();
        const TetTopology topo = build_topology(cf.mesh);
        const Constraints cons = boundary_constraints(cf.mesh, cf.features);
        const double t_prep = seconds(t1);
        FieldOptions o;
        o.threads = argc > 2 ? std::atoi(argv[2]) : 0;
        const std::string solver = argc > 3 ? argv[3] : "cg";
        o.solver = solver == "ldlt" ? SparseSolver::SimplicialLDLT
                   : solver == "cholmod" ? SparseSolver::Cholmod : SparseSolver::ConjugateGradient;
        if (argc > 4) {  // an explicit cap is a hard cap
            o.max_iterations = std::atoi(argv[4]);
            o.floor_iterations = 0;
        }
        if (const char* r = std::getenv("FF_REORDER")) o.reorder = std::atoi(r) != 0;
        if (const char* e = std::getenv("FF_EXTRAPOLATE")) o.extrapolate = std::atoi(e) != 0;
        if (const char* c = std::getenv("FF_LARGE_MESH_VERTICES")) o.large_mesh_vertices = std::atoi(c);
        const double cpu0 = cpu_seconds();
        const FrameField f = solve_frame_field(cf.mesh, topo, cons, o);
        const double cpu_solve = cpu_seconds() - cpu0;
        int fixed = 0, aligned = 0;
        for (ConstraintKind k : cons.kind) {
            fixed += k == ConstraintKind::Fixed;
            aligned += k == ConstraintKind::NormalAligned;
        }
        std::printf("mesh %s\nvertices %d tets %d curves %d fixed %d aligned %d\n", argv[1], cf.mesh.num_vertices(),
                    cf.mesh.num_tets(), cf.features.curves(), fixed, aligned);
        std::printf("solver %s\n", f.solver.c_str());
        std::printf("load %.3f s  topology+constraints %.3f s\n", t_load, t_prep);
        std::printf("init %.3f s  smoothing %.3f s  total(init+smoothing) %.3f s\n", f.seconds_init, f.seconds_smooth,
                    f.seconds_init + f.seconds_smooth);
        std::printf("cpu(init+smoothing, all threads) %.3f s\n", cpu_solve);
        std::printf("iterations %d (tau at its floor from %d, cap %d) converged %d extrapolations %d "
                    "linear_iterations %d\nper solve:",
                    f.iterations, f.floor_iteration, f.iteration_cap, int(f.converged), f.extrapolations,
                    f.linear_iterations);
        for (int it : f.solve_iterations) std::printf(" %d", it);
        std::printf("\nchange per MBO iteration:");
        for (double c : f.change_history) std::printf(" %.2g", c);
        std::printf("\n");
        std::printf("energy init %.6g final %.6g\n", f.initial_energy, f.energy);
        std::printf("peak_memory_mb %.1f\n", peak_memory_mb());
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_field: error [%s]: %s\n", e.stage().c_str(), e.message().c_str());
        return 2;
    }
}
