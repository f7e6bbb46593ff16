// framefix-hxt SURFACE H THREADS: the surface (hxt_protocol.h) from the file SURFACE, meshed
// with HXT at size H; the answer goes to standard output. Run by hxt_tetrahedralize.cpp.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "framefix/core/error.h"
#include "framefix/hxt/hxt_protocol.h"
#include "hxt_volume.h"

int main(int argc, char** argv) {
    using namespace framefix;
    std::string answer;
    try {
        if (argc != 4) throw Error("mesh", "usage: framefix-hxt SURFACE H THREADS");
        std::ifstream in(argv[1], std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        if (!in) throw Error("mesh", std::string("cannot read ") + argv[1]);
        const SurfaceMesh surface = hxt::as_surface(tet_mesh_from_bytes(bytes.str()));
        answer = hxt::mesh_volume(surface, std::atof(argv[2]), std::atoi(argv[3]));
    } catch (const Error& e) {
        answer = hxt::kFailed + e.message();
    } catch (const std::exception& e) {
        answer = hxt::kFailed + std::string(e.what());
    }
    std::fwrite(answer.data(), 1, answer.size(), stdout);
    return std::fflush(stdout) == 0 ? 0 : 1;
}
