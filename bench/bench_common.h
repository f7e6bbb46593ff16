#pragma once
// Helpers shared by the benchmark programs.
#include <chrono>
#include <string>

namespace framefix::bench {

using Clock = std::chrono::steady_clock;
inline double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A sample name ("notch") means samples/notch.step; anything with a '/' or '.' is a path.
inline std::string resolve(const std::string& name) {
    if (name.find('/') != std::string::npos || name.find('.') != std::string::npos) return name;
    return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step";
}

}  // namespace framefix::bench
