// bench_blocks [--size H] [--tets N] [--threads T] [--blocks] SAMPLE...
// run() to the blocks stage (snapping the 3-5 curves first, if any), for each sample (a path or a
// name in samples/). Prints the block counts, validity, conformity, flat edges/corners and the cost
// of sheets / partition / validation next to the field solve (the target: blocks < field).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/blocks/blocks.h"
#include "framefix/pipeline/pipeline.h"

#include "bench_common.h"

using namespace framefix;

namespace {

using bench::resolve;

}  // namespace

int main(int argc, char** argv) {
    RunOptions options;
    BlockOptions blocks;
    bool per_block = false;
    std::vector<std::string> samples;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string("0"); };
        if (a == "--size") options.mesh.size = std::atof(next().c_str());
        else if (a == "--tets") options.mesh.target_tets = std::atoi(next().c_str());
        else if (a == "--threads") options.threads = blocks.threads = std::atoi(next().c_str());
        else if (a == "--blocks") per_block = true;
        else samples.push_back(a);
    }
    if (samples.empty()) {
        std::fprintf(stderr, "usage: bench_blocks [--size H] [--tets N] [--threads T] [--blocks] SAMPLE...\n");
        return 2;
    }
    options.stop_after = Stage::blocks;
    for (const std::string& name : samples) {
        options.blocks = blocks;
        const RunResult r = run(RunInput::file(resolve(name)), options);
        const BlockDecomposition& d = *r.blocks;
        const size_t paths = r.correction ? r.correction->snap.paths.size() : 0;
        const double field_seconds = r.timings.field, correct_seconds = r.timings.correct;
        std::printf("%s: %d vertices %d tets h %.4f  curves %d paths %zu\n", name.c_str(), r.mesh->tets.num_vertices(),
                    r.mesh->tets.num_tets(), d.h, r.singularities->summary.curves, paths);
        std::printf("  blocks %d valid %d conforming pairs %d/%d flat edges %d flat corners %d\n", d.count, d.valid,
                    d.conforming_pairs, d.pairs, d.flat_edges, d.flat_corners);
        const SheetStats& s = d.stats;
        std::printf("  sheets: sources %d streamlines %d (left %d sing %d turn %d cycle %d steps %d out %d) ribbons %d "
                    "cross %d triangles %d cut edges %d\n",
                    s.sources, s.streamlines, s.left_solid, s.reached_singularity, s.sharp_turn, s.limit_cycle,
                    s.max_steps, s.start_outside, s.ribbons, s.cross_ribbons, int(d.sheets.triangles.rows()), s.cut_edges);
        std::printf("  seconds: blocks %.3f (sheets %.3f partition %.3f validation %.3f)  field solve %.3f  "
                    "correction %.3f\n",
                    d.seconds, d.seconds_sheets, d.seconds_partition, d.seconds_validation, field_seconds, correct_seconds);
        if (per_block)
            for (int b = 0; b < d.count; ++b) {
                const BlockInfo& i = d.blocks[b];
                std::printf("    block %2d tets %6zu vol %.4f F %d E %2d V %2d chi %d flat e%d c%d at (%.2f %.2f %.2f) %s\n", b,
                            i.tets.size(), i.volume, i.faces, i.edges, i.corners, i.euler, i.flat_edges, i.flat_corners,
                            i.centroid.x(), i.centroid.y(), i.centroid.z(), i.valid ? "valid" : i.reason.c_str());
            }
        for (const BlockPair& p : d.neighbour_pairs)
            if (!p.conforming && per_block) std::printf("    pair %d-%d: %s\n", p.a, p.b, p.reason.c_str());
    }
    return 0;
}
