// Meshing time and memory on every sample at the default size and at 0.7x:
//   bench_mesh [file.step ...] [--factor F ...]
// prints one line per run: file, size, vertices, tets, seconds (load+features+tessellate+TetGen),
// peak resident memory of the process so far, and the mesh quality figures.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/brep/brep_model.h"
#include "framefix/core/error.h"
#include "framefix/core/memory.h"
#include "framefix/tetgen/tetrahedralize.h"

using namespace framefix;

namespace {

const char* kSamples[] = {"cube", "cylinder", "l_prism", "notch", "box_arc", "box_arc_curved",
                          "half_sphere_box", "groove", "two_cylinders"};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run(const std::string& path, double factor) {
    const auto start = std::chrono::steady_clock::now();
    const BrepModel model = load_shape(path);
    const FeatureSet features = classify_features(model);
    MeshOptions options;
    options.size = factor * default_size(model);
    const SurfaceMesh surface = tessellate(model, features, options);
    const double t_surface = seconds_since(start);
    const TetMesh mesh = tetrahedralize(surface, options);
    const double t_total = seconds_since(start);
    const MeshQuality q = mesh_quality(mesh);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("%-34s %5.2fx h %-9.4g tris %7d verts %8d tets %9d (est %9.0f) s %6.2f (surf %5.2f) MB %7.0f "
                "in-range %.3f median/h %.2f features %d tagged-edges %d\n",
                name.c_str(), factor, options.size, int(surface.triangles.rows()), mesh.num_vertices(),
                mesh.num_tets(), estimate_tets(model.volume, options.size), t_total, t_surface, peak_memory_mb(),
                q.edge_fraction_in_range, q.median_edge / options.size, features.curves(),
                int(mesh.feature_edges.rows()));
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    std::vector<double> factors;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--factor" && i + 1 < argc) factors.push_back(std::atof(argv[++i]));
        else files.push_back(arg);
    }
    if (files.empty())
        for (const char* s : kSamples) files.push_back(std::string(FRAMEFIX_SAMPLES_DIR) + "/" + s + ".step");
    if (factors.empty()) factors = {1.0, 0.7};
    int failures = 0;
    for (const std::string& f : files)
        for (double factor : factors) {
            try {
                run(f, factor);
            } catch (const Error& e) {
                std::printf("%s %.2fx FAILED: %s\n", f.c_str(), factor, e.what());
                ++failures;
            }
        }
    return failures == 0 ? 0 : 1;
}
