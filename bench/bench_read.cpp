// bench_read MESH.msh|MESH.mesh [repeats]
// Reads a tet mesh file `repeats` times (default 3) and prints the best time, the file size and
// the rate in MB/s (issue goal for .msh: 50 MB/s), then the same for the crease features the
// pipeline's mesh stage computes next.
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "framefix/core/error.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/mesh/mesh_io.h"

using namespace framefix;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_read MESH.msh|MESH.mesh [repeats]\n");
        return 2;
    }
    struct stat st {};
    if (stat(argv[1], &st) != 0) {
        std::fprintf(stderr, "bench_read: cannot stat %s\n", argv[1]);
        return 2;
    }
    const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    try {
        double best_read = 1e300, best_crease = 1e300;
        TetMesh mesh;
        for (int r = 0; r < repeats; ++r) {
            auto t0 = Clock::now();
            mesh = read_tet_mesh(argv[1]);
            best_read = std::min(best_read, since(t0));
            t0 = Clock::now();
            const CreaseFeatures cf = detect_crease_features(TetMesh(mesh));
            best_crease = std::min(best_crease, since(t0));
        }
        const double mb = double(st.st_size) / 1e6;
        std::printf("file %s  %.1f MB  vertices %d  tets %d\n", argv[1], mb, mesh.num_vertices(), mesh.num_tets());
        std::printf("read %.3f s  %.1f MB/s  (best of %d)\n", best_read, mb / best_read, repeats);
        std::printf("crease features %.3f s\n", best_crease);
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_read: %s\n", e.what());
        return 2;
    }
    return 0;
}
