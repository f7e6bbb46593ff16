#include "framefix/core/memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace framefix {
namespace {

double read_kb(const char* path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.compare(0, key.size(), key) == 0) {
            std::istringstream s(line.substr(key.size()));
            double kb = 0;
            s >> kb;
            return kb;
        }
    }
    return 0;
}

}  // namespace

double peak_memory_mb() { return read_kb("/proc/self/status", "VmHWM:") / 1024.0; }
double available_memory_mb() { return read_kb("/proc/meminfo", "MemAvailable:") / 1024.0; }

}  // namespace framefix
