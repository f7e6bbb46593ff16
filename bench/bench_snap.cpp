// bench_snap [--tets N] [--passes K] [--radius R] [--interp] [--threads T] SAMPLE...
// analyze -> snap the 3-5 curves -> re-solve on the same mesh -> extract, for each sample (a path,
// or a name in samples/ such as "notch"); prints before/after summaries, the snapped curves, the
// locality of the change and timings. With --passes 2 the corrected result is snapped again
// (re-run the detection after the correction: docs/algorithms.md#3-5-detection).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/corrections/snapping.h"
#include "framefix/pipeline/pipeline.h"

#include "bench_common.h"

using namespace framefix;

namespace {

using bench::Clock;
using bench::resolve;
using bench::since;

void print_summary(const char* tag, const SingularityGraph& g) {
    const SingularitySummary& s = g.summary;
    std::printf("  %-7s curves %3d (v3 %3d v5 %3d 3-5 %2d) nodes %3d invalid %2d singular_faces %4d complex %3d "
                "mixed_loops %d meshable %d\n",
                tag, s.curves, s.valence3, s.valence5, s.curves_3_5, s.nodes, s.invalid_nodes, s.singular_faces,
                s.complex_faces, s.mixed_loops, int(s.meshable));
}

// Singular faces after the correction that touch a path or freed vertex: the locality test
// that nothing is left where the snapped curves were.
int singular_faces_near(const TetTopology& topo, const SingularityGraph& g, const std::vector<SnapRole>& roles) {
    int n = 0;
    for (int f = 0; f < int(g.face_valence.size()); ++f) {
        if (g.face_valence[f] == 0) continue;
        bool touch = false;
        for (int k = 0; k < 3; ++k) touch |= roles[topo.faces(f, k)] != SnapRole::Untouched;
        n += touch;
    }
    return n;
}

void print_snap(const SnapResult& s) {
    int forced = 0, crossing = 0, path_vertices = 0;
    for (const SnappedPath& p : s.paths) forced += p.forced, crossing += p.crosses_features, path_vertices += int(p.vertices.size());
    std::printf("  snap    3-5 %d snapped_curves %d paths %zu (forced %d, crossing features %d, %d vertices) "
                "collapsed_ends %d freed %d hb %.4f  %.3f s\n",
                s.three_five_curves, s.snapped_curves, s.paths.size(), forced, crossing, path_vertices,
                s.collapsed_ends, s.freed_vertices, s.hb, s.seconds);
    for (const SnappedPath& p : s.paths)
        std::printf("          curve %3d %s %3zu vertices  (%.3f %.3f %.3f) -> (%.3f %.3f %.3f)\n", p.source_curve,
                    p.forced ? "forced" : "3-5   ", p.vertices.size(), p.points(0, 0), p.points(0, 1), p.points(0, 2),
                    p.points(p.points.rows() - 1, 0), p.points(p.points.rows() - 1, 1), p.points(p.points.rows() - 1, 2));
}

}  // namespace

int main(int argc, char** argv) {
    RunOptions options;
    SnapOptions snap;
    int passes = 1;
    std::vector<std::string> samples;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string("0"); };
        if (a == "--tets") options.mesh.target_tets = std::atoi(next().c_str());
        else if (a == "--passes") passes = std::atoi(next().c_str());
        else if (a == "--radius") snap.free_radius_hb = std::atof(next().c_str());
        else if (a == "--interp") snap.interpolate_split_curves = true;
        else if (a == "--threads") options.threads = std::atoi(next().c_str());
        else samples.push_back(a);
    }
    if (samples.empty()) {
        std::fprintf(stderr, "usage: bench_snap [--tets N] [--passes K] [--radius R] [--interp] [--threads T] SAMPLE...\n");
        return 2;
    }
    int failures = 0;
    for (const std::string& name : samples) {
        try {
            auto t0 = Clock::now();
            const RunResult r = run(RunInput::file(resolve(name)), options);
            const double t_analyze = since(t0);
            const TetMesh& mesh = r.mesh->tets;
            const TetTopology& topology = r.mesh->topology;
            const FrameField& analysed = r.field->frames;
            std::printf("%s: %d vertices %d tets  analyze %.2f s (mesh %.2f field %.2f singularities %.2f)\n",
                        name.c_str(), mesh.num_vertices(), mesh.num_tets(), t_analyze, r.timings.mesh,
                        r.timings.field, r.timings.singularities);
            print_summary("before", *r.singularities);

            Constraints constraints = r.field->constraints;
            FrameField field = analysed;
            SingularityGraph graph = *r.singularities;
            std::vector<SnapRole> roles(mesh.num_vertices(), SnapRole::Untouched);
            for (int pass = 1; pass <= passes && graph.summary.curves_3_5 > 0; ++pass) {
                const SnapResult s = snap_three_five_curves(mesh, topology, r.mesh->features, constraints, field, graph, snap);
                print_snap(s);
                for (size_t v = 0; v < roles.size(); ++v)
                    if (s.vertex_role[v] != SnapRole::Untouched) roles[v] = s.vertex_role[v];
                FieldOptions fo = options.field;
                fo.threads = options.threads;
                t0 = Clock::now();
                field = solve_frame_field(mesh, topology, s.constraints, fo);
                const double t_solve = since(t0);
                t0 = Clock::now();
                graph = extract_singularities(mesh, topology, field, options.singularities);
                const double t_extract = since(t0);
                constraints = s.constraints;
                print_summary(pass == 1 ? "after" : "after2", graph);
                const Eigen::VectorXd deg = frame_rotation_degrees(analysed, field);
                std::printf("  locality >5deg %.4f >10deg %.4f >20deg %.4f max %.1f deg; singular faces at snapped/freed "
                            "vertices %d\n",
                            rotated_fraction(analysed, field, 5), rotated_fraction(analysed, field, 10),
                            rotated_fraction(analysed, field, 20), deg.size() ? deg.maxCoeff() : 0.0,
                            singular_faces_near(topology, graph, roles));
                std::printf("  timings snap %.3f s  re-solve %.2f s (%d iterations)  extract %.2f s\n", s.seconds,
                            t_solve, field.iterations, t_extract);
            }
            if (r.singularities->summary.curves_3_5 == 0) std::printf("  no 3-5 curve: nothing to snap\n");
        } catch (const Error& e) {
            std::printf("%s: error [%s]: %s\n", name.c_str(), e.stage().c_str(), e.message().c_str());
            ++failures;
        }
        std::fflush(stdout);
    }
    return failures ? 1 : 0;
}
