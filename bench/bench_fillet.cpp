// bench_fillet [--size-factor F] [--threads T] SAMPLE...
// framefix correct --method fillet through the pipeline, for each sample (a path, or a name in
// samples/ such as "notch"): the fillet stage (choosing the edges + OCCT in its worker) next to
// the mesh and field stages, the remesh of the filleted solid, and the graph before and after.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/pipeline/pipeline.h"

#include "bench_common.h"

using namespace framefix;

int main(int argc, char** argv) {
    RunOptions options;
    options.correction = "fillet";
    options.stop_after = Stage::correction;
    const std::vector<std::string> samples = bench::sample_args(argc, argv, options);
    if (samples.empty()) {
        std::fprintf(stderr, "usage: bench_fillet [--size-factor F] [--threads T] SAMPLE...\n");
        return 2;
    }
    std::printf("%-28s %8s %7s %7s %8s %8s %9s %6s %13s\n", "sample", "tets", "mesh_s", "field_s", "fillet_s",
                "remesh_s", "correct_s", "edges", "3-5+inv b->a");
    for (const std::string& s : samples) {
        try {
            const RunResult r = run(RunInput::file(bench::resolve(s)), options);
            const Correction& c = *r.correction;
            int done = 0;
            for (const FilletOutcome& f : c.fillets) done += f.done;
            std::printf("%-28s %8d %7.2f %7.2f %8.3f %8.2f %9.2f %3d/%-2zu %6d -> %d%s\n", s.c_str(),
                        r.mesh->tets.num_tets(), r.timings.mesh, r.timings.field, c.fillet_seconds, c.remesh_seconds,
                        c.seconds, done, c.fillets.size(), c.before.curves_3_5 + c.before.invalid_nodes,
                        r.singularities->summary.curves_3_5 + r.singularities->summary.invalid_nodes,
                        r.singularities->summary.meshable ? " meshable" : "");
        } catch (const Error& e) {
            std::printf("%-28s error [%s]: %s\n", s.c_str(), e.stage().c_str(), e.what());
        }
        std::fflush(stdout);
    }
    return 0;
}
