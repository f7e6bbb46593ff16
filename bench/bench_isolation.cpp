// bench_isolation [--tets N]... SAMPLE: what running OCCT's reader and TetGen in a worker process
// costs (core/isolation.h). For each tet count: the mesh stage's time, and the isolation's own
// cost on that mesh (fork + packing + pipe + unpacking, best of 3) as a fraction of the stage.
// For the load: load_shape with and without the worker, best of 10.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/brep/brep_model.h"
#include "framefix/core/isolation.h"
#include "framefix/pipeline/pipeline.h"

#include "bench_common.h"

using namespace framefix;
using bench::Clock;
using bench::since;

namespace {

template <class F>
double best_of(int n, F&& f) {
    double best = 1e300;
    for (int i = 0; i < n; ++i) {
        const auto t = Clock::now();
        f();
        best = std::min(best, since(t));
    }
    return best;
}

void bench_load(const std::string& path) {
    const double isolated = best_of(10, [&] { load_shape(path); });
    setenv("FRAMEFIX_ISOLATION", "0", 1);
    const double in_process = best_of(10, [&] { load_shape(path); });
    unsetenv("FRAMEFIX_ISOLATION");
    std::printf("load: %.4f s in a worker, %.4f s in process: +%.4f s (%.1f%%)\n", isolated, in_process,
                isolated - in_process, 100 * (isolated - in_process) / in_process);
}

void bench_mesh(const std::string& path, int tets) {
    RunOptions o;
    o.stop_after = Stage::mesh;
    o.mesh.target_tets = tets;
    const RunResult r = run(RunInput::file(path), o);
    const TetMesh& mesh = r.mesh->tets;
    const IsolatedTask task{"mesh", "bench", ""};
    const double cost = best_of(3, [&] { tet_mesh_from_bytes(run_isolated(task, [&] { return tet_mesh_bytes(mesh); })); });
    std::printf("mesh: %d tets %d vertices, stage %.2f s, isolation %.4f s (%.2f%% of the stage)\n", mesh.num_tets(),
                mesh.num_vertices(), r.timings.mesh, cost, 100 * cost / r.timings.mesh);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts;
    std::string sample;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--tets" && i + 1 < argc) counts.push_back(std::atoi(argv[++i]));
        else sample = a;
    }
    if (sample.empty()) {
        std::fprintf(stderr, "usage: bench_isolation [--tets N]... SAMPLE\n");
        return 2;
    }
    if (counts.empty()) counts = {50000, 1000000};
    const std::string path = bench::resolve(sample);
    bench_load(path);
    for (int n : counts) bench_mesh(path, n);
    return 0;
}
