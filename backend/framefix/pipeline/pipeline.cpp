#include "framefix/pipeline/pipeline.h"

#include <algorithm>
#include <cctype>
#include <chrono>

#include "framefix/core/error.h"
#include "framefix/core/memory.h"
#include "framefix/mesh/crease_features.h"
#include "framefix/mesh/mesh_io.h"
#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/flat_blocks.h"
#include "framefix/pipeline/mesh_attempts.h"
#include "framefix/pipeline/solve_stages.h"
#include "framefix/pipeline/thin_blocks.h"

namespace framefix {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

bool is_tet_mesh(const std::string& kind) { return kind == "msh" || kind == "mesh"; }

// Throws before any work when the run would reach an unknown or unavailable correction.
void check_options(const RunOptions& o) {
    if (o.stop_after >= Stage::correction && o.correction != kNoCorrection) find_correction_method(o.correction);
    if (o.hexmesh.order != 1 && o.hexmesh.order != 2)
        throw Error("hexmesh", "order " + std::to_string(o.hexmesh.order) + " is not offered; use 1 (8-node hexes) or 2 (20-node)");
    if (o.hexmesh.size < 0 || o.hexmesh.layers < 0)
        throw Error("hexmesh", "the hex size and the layer count must not be negative");
}

// load: the B-rep of a CAD file (or the given model), or the tets of a mesh file.
std::optional<TetMesh> load(const RunInput& in, const RunOptions& o, RunResult& r) {
    report(o.progress, "load", 0.0);
    std::optional<TetMesh> tets;
    if (in.model) {
        r.model = in.model;
    } else if (is_tet_mesh(input_kind(in.path))) {
        tets = read_tet_mesh(in.path);
    } else {
        r.model = std::make_shared<const BrepModel>(load_shape(in.path));
    }
    r.input_path = r.model ? r.model->path : in.path;
    r.input_kind = r.model ? r.model->kind : input_kind(in.path);
    report(o.progress, "load", 1.0);
    return tets;
}

// mesh: feature curves and tets; from the B-rep, or the crease edges of a tet mesh.
MeshStage mesh(const RunResult& r, std::optional<TetMesh> tets, const RunOptions& o) {
    report(o.progress, "mesh", 0.0);
    MeshStage m;
    if (tets) {
        CreaseFeatures cf = detect_crease_features(std::move(*tets));
        m.tets = std::move(cf.mesh);
        m.features = std::move(cf.features);
    } else {
        m.features = classify_features(*r.model, o.features);
        MeshOptions mo = o.mesh;
        if (mo.size <= 0) mo.size = default_size(*r.model, mo.target_tets) * o.size_factor;
        if (mo.threads == 0) mo.threads = o.threads;
        BrepMeshing meshing = mesh_brep(*r.model, m.features, mo);
        m.tets = std::move(meshing.tets);
        m.attempts = std::move(meshing.attempts);
        m.narrow_faces = meshing.narrow_faces;
        m.mesher = mesher_name(meshing.mesher);
    }
    m.topology = build_topology(m.tets);
    report(o.progress, "mesh", 1.0);
    return m;
}

BlockDecomposition blocks(const RunResult& r, const RunOptions& o) {
    report(o.progress, "blocks", 0.0);
    BlockOptions bo = o.blocks;
    if (bo.threads == 0) bo.threads = o.threads;
    static const std::vector<SnappedPath> no_paths;
    const auto& paths = r.correction ? r.correction->snap.paths : no_paths;
    BlockDecomposition b =
        build_blocks(r.mesh->tets, r.mesh->topology, r.mesh->features, r.field->frames, *r.singularities, paths, bo);
    report(o.progress, "blocks", 1.0);
    return b;
}

// Boundary vertices go onto the solid the tets were made from: the filleted one after a fillet
// correction, none for a tet-mesh input. The flat refinement's hex mesh when it made one.
HexMesh hexmesh(const RunResult& r, const RunOptions& o) {
    report(o.progress, "hexmesh", 0.0);
    HexMesh h = r.flat && r.flat->hexes ? *r.flat->hexes : mesh_hexes(r, o);
    report(o.progress, "hexmesh", 1.0);
    return h;
}

// Times one stage into `seconds` and the run's total.
template <class F>
void timed(double& seconds, Timings& t, F&& stage) {
    const auto t0 = Clock::now();
    stage();
    seconds = since(t0);
    t.total += seconds;
}

}  // namespace

const char* stage_name(Stage stage) {
    switch (stage) {
        case Stage::load: return "load";
        case Stage::mesh: return "mesh";
        case Stage::field: return "field";
        case Stage::singularities: return "singularities";
        case Stage::correction: return "correct";
        case Stage::blocks: return "blocks";
        case Stage::hexmesh: return "hexmesh";
    }
    return "?";
}

Mesher mesher_named(const std::string& name) {
    for (Mesher m : {Mesher::tetgen, Mesher::hxt})
        if (name == mesher_name(m)) return m;
    throw Error("options", "unknown mesher '" + name + "'; use tetgen (the default) or hxt (gmsh's HXT)");
}

RunInput RunInput::file(std::string path) { return {std::move(path), nullptr}; }

RunInput RunInput::shape(const BrepModel& model) { return {model.path, std::make_shared<const BrepModel>(model)}; }

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

RunResult run(const RunInput& input, const RunOptions& o) {
    check_options(o);
    RunResult r;
    Timings& t = r.timings;
    std::optional<TetMesh> tets;
    timed(t.load, t, [&] { tets = load(input, o, r); });
    const auto done = [&](Stage s) {
        r.peak_memory_mb = peak_memory_mb();
        return o.stop_after == s;
    };
    if (done(Stage::load)) return r;
    timed(t.mesh, t, [&] { r.mesh = mesh(r, std::move(tets), o); });
    if (done(Stage::mesh)) return r;
    timed(t.field, t, [&] {
        report(o.progress, "field", 0.0);
        r.field = detail::solve_field(*r.mesh, boundary_constraints(r.mesh->tets, r.mesh->features), o,
                                      o.progress);
        report(o.progress, "field", 1.0);
    });
    if (done(Stage::field)) return r;
    timed(t.singularities, t, [&] {
        report(o.progress, "singularities", 0.0);
        r.singularities = detail::find_singularities(*r.mesh, *r.field, o);
        report(o.progress, "singularities", 1.0);
    });
    if (done(Stage::singularities)) return r;
    if (o.correction != kNoCorrection)
        timed(t.correct, t, [&] { r.correction = detail::correct(*r.mesh, *r.field, *r.singularities, o, r.model.get()); });
    if (done(Stage::correction)) return r;
    timed(t.blocks, t, [&] { r.blocks = blocks(r, o); });
    if (o.remesh_thin) {
        double seconds = 0;
        timed(seconds, t, [&] { r.thin = refine_thin_blocks(o, r); });
        t.blocks += seconds;
    } else {
        r.thin = ThinRefinement{};
        r.thin->reason = "turned off (--no-remesh-thin)";
    }
    {
        double seconds = 0;
        timed(seconds, t, [&] { r.flat = refine_flat_blocks(o, r); });
        t.blocks += seconds;
    }
    if (done(Stage::blocks)) return r;
    timed(t.hexmesh, t, [&] { r.hexmesh = hexmesh(r, o); });
    done(Stage::hexmesh);
    return r;
}

}  // namespace framefix
