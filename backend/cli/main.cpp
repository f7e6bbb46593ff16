// framefix command line: parse flags -> RunOptions -> pipeline::run -> files. Each subcommand
// only says where the run stops and what it writes. Errors become exit codes: 2 bad input or
// options (one line on stderr), 3 internal error. Never a stack trace.
#include <cstdio>
#include <cstdlib>

#include <unistd.h>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "framefix/core/error.h"
#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/report.h"

namespace {

struct Args {
    std::string part, out;
    double size = 0, size_factor = 1;
    int threads = 0;
    double budget_s = 0;
    bool quiet = false;
    bool fillet_rims = false;
    double hex_size = 0;
    int layers = 0, order = 1;
    bool no_refine = false;
    bool no_remesh_thin = false;
    std::string mesher = "tetgen";
    std::string method = framefix::correction_methods()[0].name;
};

void add_common(CLI::App* cmd, Args& a) {
    cmd->add_option("PART", a.part, "CAD file (.step/.stp/.brep/.iges/.igs) or tet mesh (.msh/.mesh)")->required();
    cmd->add_option("--size", a.size, "target tet edge length in model units (default: about 50k tets)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--size-factor", a.size_factor, "multiply the default size by F")->check(CLI::PositiveNumber);
    cmd->add_option("--out", a.out, "output folder (default: framefix-out)");
    cmd->add_option("--threads", a.threads, "threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->add_option("--mesher", a.mesher, "volume mesher: tetgen (default) or hxt (gmsh's parallel HXT)");
    cmd->add_flag("--quiet", a.quiet, "no progress lines");
}

// "snap (default), fillet (not available yet), ..." from the registry.
std::string method_help(bool with_none) {
    std::string s;
    for (const auto& m : framefix::correction_methods()) {
        if (!s.empty()) s += ", ";
        s += m.name + (s.empty() ? " (default)" : "") + (m.available ? "" : " (not available yet)");
    }
    return with_none ? s + ", or " + framefix::kNoCorrection + " (no correction)" : s;
}

framefix::RunOptions options_from(const Args& a, framefix::Stage stop_after) {
    framefix::RunOptions o;
    o.stop_after = stop_after;
    o.correction = a.method;
    o.budget_s = a.budget_s;
    o.fillet.rims = a.fillet_rims;
    o.hexmesh.size = a.hex_size;
    o.hexmesh.layers = a.layers;
    o.hexmesh.order = a.order;
    o.hexmesh.refine_flat = !a.no_refine;
    o.remesh_thin = !a.no_remesh_thin;
    o.mesh.size = a.size;
    o.mesh.mesher = framefix::mesher_named(a.mesher);
    o.size_factor = a.size_factor;
    o.threads = a.threads;
    if (!a.quiet)
        o.progress = [](const std::string& stage, double f) { std::fprintf(stderr, "progress %s %.3f\n", stage.c_str(), f); };
    return o;
}

// One subcommand, start to finish; errors propagate to main's translation into exit codes.
int run(const Args& a, framefix::Stage stop_after) {
    if (stop_after == framefix::Stage::correction && a.method == framefix::kNoCorrection)
        throw framefix::Error("correct", "method 'none' corrects nothing; use analyze, or --method snap");
    const framefix::RunResult r = framefix::run(framefix::RunInput::file(a.part), options_from(a, stop_after));
    const std::string out = a.out.empty() ? "framefix-out" : a.out;
    framefix::write_outputs(r, out);
    std::cout << framefix::human_summary(r) << "\n";
    std::cout << "results: " << out << "/report.json\n";
    return 0;
}

struct Subcommand {
    const char* name;
    const char* help;
    framefix::Stage stop_after;
    CLI::App* app = nullptr;
};

}  // namespace

int main(int argc, char** argv) {
    // libgomp reads OMP_WAIT_POLICY once, at load time. Its default spin-waiting made runs up to
    // 8x slower when other processes share the cores (CI runs tests in parallel, FreeCAD's GUI
    // runs beside the workbench's backend), so restart once with the passive policy.
    if (!std::getenv("OMP_WAIT_POLICY")) {
        setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
        execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
    }
    CLI::App app{"FrameFix: frame fields, singular curves and 3-5 curves of CAD solids for hex meshing"};
    app.require_subcommand(1);
    Args a;
    using framefix::Stage;
    std::vector<Subcommand> commands = {
        {"mesh", "load a part, classify feature curves, build the tet mesh", Stage::mesh},
        {"analyze", "mesh, frame field, singular curves, 3-5 curves", Stage::singularities},
        {"correct", "analyze, then correct the 3-5 curves and analyze again", Stage::correction},
        {"blocks", "analyze, correct, then cut the part into blocks", Stage::blocks},
        {"hexmesh", "analyze, correct, cut into blocks, then mesh the blocks with hexahedra", Stage::hexmesh},
    };
    for (auto& c : commands) {
        c.app = app.add_subcommand(c.name, c.help);
        add_common(c.app, a);
    }
    commands[2].app->add_option("--method", a.method, method_help(false));
    commands[3].app->add_option("--method", a.method, "correction before the blocks: " + method_help(true));
    commands[4].app->add_option("--method", a.method, "correction before the blocks: " + method_help(true));
    commands[4].app->add_option("--hex-size", a.hex_size, "target hex edge length in model units (default: 2 tet edges)")
        ->check(CLI::PositiveNumber);
    commands[4].app->add_option("--layers", a.layers, "hexes along the shortest block edge (overrides --hex-size)")
        ->check(CLI::PositiveNumber);
    commands[4].app->add_option("--order", a.order, "1: 8-node hexes (C3D8), 2: 20-node (C3D20)")->check(CLI::Range(1, 2));
    for (int k : {3, 4})
        commands[k].app->add_flag("--no-refine", a.no_refine, "keep blocks with a flat edge as they are (no three-block template)");
    for (int k : {3, 4})
        commands[k].app->add_flag("--no-remesh-thin", a.no_remesh_thin,
                                  "keep the mesh when blocks thinner than 3 tet edges come out invalid (no finer mesh next to them)");
    for (int k : {2, 3, 4})
        commands[k].app->add_option("--budget-s", a.budget_s, "method auto: seconds for its tries (default: 120 per 50k tets)")
            ->check(CLI::PositiveNumber);
    for (int k : {2, 3, 4})
        commands[k].app->add_flag("--fillet-rims", a.fillet_rims,
                                  "method fillet: also fillet the rims across the wall from each concave edge");
    auto* info = app.add_subcommand("info", "print the defaults and the correction methods as JSON");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "framefix: error [options]: " << e.what() << " (see framefix --help)\n";
        return 2;
    }
    try {
        if (info->parsed()) {
            std::cout << framefix::info_json() << "\n";
            return 0;
        }
        for (const auto& c : commands)
            if (c.app->parsed()) return run(a, c.stop_after);
        return 2;  // unreachable: CLI11 requires one subcommand
    } catch (const framefix::Error& e) {
        std::cerr << "framefix: error [" << e.stage() << "]: " << e.message() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "framefix: error [memory]: out of memory; use a larger --size\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "framefix: internal error: " << e.what() << "\n";
        return 3;
    } catch (...) {
        std::cerr << "framefix: internal error: unknown exception\n";
        return 3;
    }
}
