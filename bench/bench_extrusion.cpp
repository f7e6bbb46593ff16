// bench_extrusion [--size-factor F] [--threads T] SAMPLE...
// framefix correct --method extrude-curves and extrude-nodes through the pipeline, for each
// sample (a path, or a name in samples/ such as "notch"): the tracing and the remesh with the
// streamline points next to the mesh and field stages, and the graph before and after.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/pipeline/pipeline.h"

#include "bench_common.h"

using namespace framefix;

namespace {

void row(const std::string& sample, const std::string& method, RunOptions options) {
    options.correction = method;
    try {
        const RunResult r = run(RunInput::file(bench::resolve(sample)), options);
        const Correction& c = *r.correction;
        size_t used = 0;
        for (const auto& l : c.extrusion.streamlines) used += l.used;
        const SingularitySummary& a = r.singularities->summary;
        std::printf("%-24s %-15s %8d %7.2f %7.2f %7.3f %8.2f %9.2f %4zu/%-4zu %6ld %5d -> %d%s\n", sample.c_str(),
                    method.c_str(), r.mesh->tets.num_tets(), r.timings.mesh, r.timings.field, c.extrusion_seconds,
                    c.remesh_seconds, c.seconds, used, c.extrusion.streamlines.size(), long(c.extrusion.points.rows()),
                    c.before.curves_3_5 + c.before.invalid_nodes, a.curves_3_5 + a.invalid_nodes, a.meshable ? " meshable" : "");
    } catch (const Error& e) {
        std::printf("%-24s %-15s error [%s]: %s\n", sample.c_str(), method.c_str(), e.stage().c_str(), e.what());
    }
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    RunOptions options;
    options.stop_after = Stage::correction;
    const std::vector<std::string> samples = bench::sample_args(argc, argv, options);
    if (samples.empty()) {
        std::fprintf(stderr, "usage: bench_extrusion [--size-factor F] [--threads T] SAMPLE...\n");
        return 2;
    }
    std::printf("%-24s %-15s %8s %7s %7s %7s %8s %9s %9s %6s %13s\n", "sample", "method", "tets", "mesh_s", "field_s",
                "trace_s", "remesh_s", "correct_s", "used", "points", "3-5+inv b->a");
    for (const std::string& s : samples)
        for (const char* m : {"extrude-curves", "extrude-nodes"}) row(s, m, options);
    return 0;
}
