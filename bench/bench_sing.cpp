// bench_sing MESH.msh [threads] [repeats]
// Solves the frame field on a gmsh/Medit tet mesh (crease features), then times
// extract_singularities and prints its cost relative to the solve (target: < 10 %), the graph
// summary and one line per curve. Run by hand, never by ctest.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "framefix/core/error.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/mesh/mesh_io.h"
#include "framefix/singularities/singularity_graph.h"

using namespace framefix;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_sing MESH.msh [threads] [repeats]\n");
        return 2;
    }
    try {
        const CreaseFeatures cf = detect_crease_features(read_tet_mesh(argv[1]));
        const TetTopology topo = build_topology(cf.mesh);
        FieldOptions fo;
        fo.threads = argc > 2 ? std::atoi(argv[2]) : 0;
        const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
        const FrameField field = solve_frame_field(cf.mesh, topo, boundary_constraints(cf.mesh, cf.features), fo);
        const double solve = field.seconds_init + field.seconds_smooth;

        SingularityOptions so;
        so.threads = fo.threads;
        SingularityGraph g;
        double best = 1e300;
        for (int r = 0; r < repeats; ++r) {
            g = extract_singularities(cf.mesh, topo, field, so);
            best = std::min(best, g.seconds);
        }
        so.direct_match_deg = 0;
        const SingularityGraph full = extract_singularities(cf.mesh, topo, field, so);

        std::printf("mesh %s vertices %d tets %d faces %d edges %d\n", argv[1], cf.mesh.num_vertices(), cf.mesh.num_tets(),
                    int(topo.faces.rows()), int(topo.edges.rows()));
        std::printf("field init %.3f s smooth %.3f s iterations %d\n", field.seconds_init, field.seconds_smooth,
                    field.iterations);
        std::printf("singularities %.4f s (best of %d) = %.1f %% of the solve; subsampled edges %d\n", best, repeats,
                    100 * best / solve, g.subsampled_edges);
        std::printf("always subsampling: %.4f s, same face labels: %s\n", full.seconds,
                    full.face_valence == g.face_valence ? "yes" : "NO");
        const SingularitySummary& s = g.summary;
        std::printf("summary curves %d valence3 %d valence5 %d 3-5 %d mixed_loops %d nodes %d invalid %d meshable %d "
                    "singular_faces %d complex %d\n",
                    s.curves, s.valence3, s.valence5, s.curves_3_5, s.mixed_loops, s.nodes, s.invalid_nodes,
                    int(s.meshable), s.singular_faces, s.complex_faces);
        std::printf("chains: dead ends %d (attached %d), junk %d, joined through %d\n", g.dead_ends, g.dead_ends_attached,
                    g.junk_chains, g.joined);
        for (const SingularCurve& c : g.curves) {
            int n3 = 0, n5 = 0;
            for (int v : c.valences) (v == 3 ? n3 : n5) += 1;
            const auto& p = c.points;
            std::printf("  curve %d %-8s faces %3zu (3:%d 5:%d) length %.3f ends %d %d  (%.2f %.2f %.2f) -> (%.2f %.2f %.2f)\n",
                        c.id, to_string(c.kind), c.faces.size(), n3, n5, c.length, c.ends[0], c.ends[1], p(0, 0), p(0, 1),
                        p(0, 2), p(p.rows() - 1, 0), p(p.rows() - 1, 1), p(p.rows() - 1, 2));
        }
        for (const SingularNode& n : g.nodes)
            std::printf("  node %d %s n3 %d n5 %d complex %d %s  (%.2f %.2f %.2f)\n", n.id, n.boundary ? "boundary" : "interior",
                        n.n3, n.n5, n.n_complex, n.valid ? "valid" : "INVALID", n.position.x(), n.position.y(),
                        n.position.z());
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_sing: error [%s]: %s\n", e.stage().c_str(), e.message().c_str());
        return 2;
    }
}
