// framefix command line: parse flags -> AnalysisOptions -> pipeline -> files. Errors become exit
// codes: 2 bad input or options (one line on stderr), 3 internal error. Never a stack trace.
#include <cstdio>
#include <cstdlib>

#include <unistd.h>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "framefix/core/error.h"
#include "framefix/pipeline/block_stage.h"
#include "framefix/pipeline/correction.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/report.h"

namespace {

struct Args {
    std::string part, out;
    double size = 0, size_factor = 1;
    int threads = 0;
    bool quiet = false;
    std::string method = "snap";
};

void add_common(CLI::App* cmd, Args& a) {
    cmd->add_option("PART", a.part, "CAD file (.step/.stp/.brep/.iges/.igs) or tet mesh (.msh/.mesh)")->required();
    cmd->add_option("--size", a.size, "target tet edge length in model units (default: about 50k tets)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--size-factor", a.size_factor, "multiply the default size by F")->check(CLI::PositiveNumber);
    cmd->add_option("--out", a.out, "output folder (default: framefix-out)");
    cmd->add_option("--threads", a.threads, "threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->add_flag("--quiet", a.quiet, "no progress lines");
}

framefix::AnalysisOptions options_from(const Args& a) {
    framefix::AnalysisOptions o;
    o.mesh.size = a.size;
    o.size_factor = a.size_factor;
    o.threads = a.threads;
    if (!a.quiet)
        o.progress = [](const std::string& stage, double f) { std::fprintf(stderr, "progress %s %.3f\n", stage.c_str(), f); };
    return o;
}

int finish(const framefix::AnalysisResult& r, const Args& a, const framefix::Correction* c = nullptr,
           const framefix::BlockDecomposition* b = nullptr) {
    const std::string out = a.out.empty() ? "framefix-out" : a.out;
    framefix::write_outputs(r, out, c, b);
    std::cout << framefix::human_summary(r, c, b) << "\n";
    std::cout << "results: " << out << "/report.json\n";
    return 0;
}

// One subcommand, start to finish; errors propagate to main's translation into exit codes.
int run(const Args& a, const std::string& command) {
    const auto o = options_from(a);
    if (command == "mesh") return finish(framefix::mesh_part(a.part, o), a);
    if (command == "analyze") return finish(framefix::analyze(a.part, o), a);
    if (command == "blocks" && a.method == "none") {
        auto r = framefix::analyze(a.part, o);
        const auto b = framefix::decompose(r, nullptr, o);
        return finish(r, a, nullptr, &b);
    }
    framefix::CorrectionOptions co;
    co.method = a.method;
    framefix::check_correction_method(co.method);  // refuse before the long analysis
    auto r = framefix::analyze(a.part, o);
    const auto c = framefix::correct(r, co, o);
    if (command == "correct") return finish(r, a, &c);
    const auto b = framefix::decompose(r, &c, o);
    return finish(r, a, &c, &b);
}

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
    auto* mesh = app.add_subcommand("mesh", "load a part, classify feature curves, build the tet mesh");
    auto* analyze = app.add_subcommand("analyze", "mesh, frame field, singular curves, 3-5 curves");
    auto* correct = app.add_subcommand("correct", "analyze, then correct the 3-5 curves and analyze again");
    add_common(mesh, a);
    add_common(analyze, a);
    add_common(correct, a);
    correct->add_option("--method", a.method, "snap (default), fillet, extrude-curves, extrude-nodes")
        ->check(CLI::IsMember({"snap", "fillet", "extrude-curves", "extrude-nodes"}));
    auto* blocks = app.add_subcommand("blocks", "analyze, correct (snap), then cut the part into blocks");
    add_common(blocks, a);
    blocks->add_option("--method", a.method, "correction before the blocks: snap (default) or none")
        ->check(CLI::IsMember({"snap", "none"}));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "framefix: error [options]: " << e.what() << " (see framefix --help)\n";
        return 2;
    }
    try {
        return run(a, mesh->parsed() ? "mesh" : analyze->parsed() ? "analyze" : correct->parsed() ? "correct" : "blocks");
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
