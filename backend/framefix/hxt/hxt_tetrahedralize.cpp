#include "framefix/hxt/hxt_tetrahedralize.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <omp.h>
#include <unistd.h>

#include "framefix/core/error.h"
#include "framefix/core/isolation.h"
#include "framefix/hxt/hxt_protocol.h"

namespace framefix {
namespace {

namespace fs = std::filesystem;

// The folder of the binary this code is in: the framefix CLI (bin/), or the Python extension
// (python/framefix/), in the build tree and in an install alike.
fs::path own_folder() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&try_hxt), &info) && info.dli_fname) {
        std::error_code error;
        const fs::path path = fs::canonical(info.dli_fname, error);
        if (!error) return path.parent_path();
    }
    std::error_code error;
    return fs::canonical("/proc/self/exe", error).parent_path();
}

// FRAMEFIX_HXT_WORKER, or framefix-hxt beside this binary or in ../../bin from the Python
// package; empty when there is none.
std::string find_worker() {
    if (const char* given = std::getenv("FRAMEFIX_HXT_WORKER")) return given;
    const fs::path here = own_folder();
    for (const fs::path& p : {here / hxt::kWorkerName, here / ".." / ".." / "bin" / hxt::kWorkerName})
        if (::access(p.c_str(), X_OK) == 0) return p.lexically_normal();
    return "";
}

// A file of this process's own for the surface, removed when it goes out of scope.
struct TempFile {
    std::string path;
    explicit TempFile(const std::string& bytes) {
        std::string pattern = (fs::temp_directory_path() / "framefix-hxt-XXXXXX").string();
        const int fd = ::mkstemp(pattern.data());
        if (fd < 0) throw Error("mesh", "cannot create a temporary file in " + fs::temp_directory_path().string());
        ::close(fd);
        path = pattern;
        std::ofstream out(path, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out) throw Error("mesh", "cannot write the surface to " + path + "; is the disk full?");
    }
    ~TempFile() { std::remove(path.c_str()); }
};

}  // namespace

TetgenRun try_hxt(const SurfaceMesh& surface, const MeshOptions& options) {
    const double h = checked_volume_size(surface, options);
    const std::string worker = find_worker();
    if (worker.empty())
        throw Error("mesh", std::string("--mesher hxt needs ") + hxt::kWorkerName +
                                ", which is built when gmsh's library is installed (Debian libgmsh-dev); "
                                "install it and rebuild, or use --mesher tetgen");
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    const TempFile input(tet_mesh_bytes(hxt::as_tet_mesh(surface, h)));
    char h_text[32];
    std::snprintf(h_text, sizeof h_text, "%.17g", h);
    TetgenRun run;
    std::string answer;
    try {
        answer = run_program({"mesh", "gmsh's HXT", ""}, worker, {input.path, h_text, std::to_string(threads)});
    } catch (const Error& e) {
        run.status = TetgenStatus::crashed;
        run.message = e.message();
        return run;
    }
    if (answer.empty() || (answer[0] != hxt::kMeshed && answer[0] != hxt::kFailed)) {
        run.status = TetgenStatus::crashed;
        run.message = std::string(hxt::kWorkerName) + " gave no answer";
        return run;
    }
    if (answer[0] == hxt::kFailed) {
        run.status = TetgenStatus::recovery_failed;
        run.message = answer.substr(1);
        return run;
    }
    run.status = TetgenStatus::meshed;
    run.mesh = tet_mesh_from_bytes(answer.substr(1));
    return run;
}

}  // namespace framefix
