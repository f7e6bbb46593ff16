#include "framefix/pipeline/pipeline.h"

#include <algorithm>
#include <cctype>
#include <chrono>

#include <omp.h>

#include "framefix/core/error.h"
#include "framefix/core/memory.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/mesh/mesh_io.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

double since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void set_threads(int threads) {
    if (threads > 0) omp_set_num_threads(threads);
}

}  // namespace

std::string input_kind(const std::string& path) {
    const auto dot = path.find_last_of('.');
    std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == "step" || ext == "stp") return "step";
    if (ext == "brep" || ext == "brp") return "brep";
    if (ext == "iges" || ext == "igs") return "iges";
    if (ext == "msh") return "msh";
    if (ext == "mesh") return "mesh";
    throw Error("load", "'" + path + "' has an unknown extension; give a .step, .stp, .brep, .iges, .igs, .msh or .mesh file");
}

AnalysisResult mesh_model(const BrepModel& model, const AnalysisOptions& options) {
    set_threads(options.threads);
    const auto t0 = std::chrono::steady_clock::now();
    AnalysisResult r;
    r.input_path = model.path;
    r.input_kind = model.kind;
    r.model = std::make_shared<BrepModel>(model);
    report(options.progress, "mesh", 0.0);
    r.features = classify_features(model, options.features);
    MeshOptions mo = options.mesh;
    if (mo.size <= 0) mo.size = default_size(model, mo.target_tets) * options.size_factor;
    const SurfaceMesh surface = tessellate(model, r.features, mo);
    report(options.progress, "mesh", 0.3);
    r.mesh = tetrahedralize(surface, mo);
    r.topology = build_topology(r.mesh);
    report(options.progress, "mesh", 1.0);
    r.timings.mesh = since(t0);
    r.timings.total = r.timings.mesh;
    r.peak_memory_mb = peak_memory_mb();
    return r;
}

AnalysisResult mesh_part(const std::string& path, const AnalysisOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string kind = input_kind(path);
    report(options.progress, "load", 0.0);
    AnalysisResult r;
    if (kind == "msh" || kind == "mesh") {
        CreaseFeatures cf = detect_crease_features(read_tet_mesh(path));
        r.mesh = std::move(cf.mesh);
        r.features = std::move(cf.features);
        r.topology = build_topology(r.mesh);
        r.input_path = path;
        r.input_kind = kind;
        r.timings.load = since(t0);
    } else {
        const BrepModel model = load_shape(path);
        const double load_s = since(t0);
        report(options.progress, "load", 1.0);
        r = mesh_model(model, options);
        r.timings.load = load_s;
    }
    report(options.progress, "load", 1.0);
    r.timings.total = since(t0);
    r.peak_memory_mb = peak_memory_mb();
    return r;
}

void analyze_mesh(AnalysisResult& r, const AnalysisOptions& options) {
    set_threads(options.threads);
    auto t0 = std::chrono::steady_clock::now();
    report(options.progress, "field", 0.0);
    r.constraints = boundary_constraints(r.mesh, r.topology, r.features);
    FieldOptions fo = options.field;
    if (!fo.progress) fo.progress = options.progress;
    if (fo.threads == 0) fo.threads = options.threads;
    r.field = solve_frame_field(r.mesh, r.topology, r.constraints, fo);
    r.has_field = true;
    report(options.progress, "field", 1.0);
    r.timings.field = since(t0);

    t0 = std::chrono::steady_clock::now();
    report(options.progress, "singularities", 0.0);
    SingularityOptions so = options.singularities;
    if (so.threads == 0) so.threads = options.threads;
    r.singularities = extract_singularities(r.mesh, r.topology, r.field, so);
    r.has_singularities = true;
    report(options.progress, "singularities", 1.0);
    r.timings.singularities = since(t0);
    r.timings.total += r.timings.field + r.timings.singularities;
    r.peak_memory_mb = peak_memory_mb();
}

AnalysisResult analyze(const std::string& path, const AnalysisOptions& options) {
    AnalysisResult r = mesh_part(path, options);
    analyze_mesh(r, options);
    return r;
}

}  // namespace framefix
