#pragma once
// Helpers shared by the benchmark programs.
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "framefix/pipeline/run_options.h"

namespace framefix::bench {

using Clock = std::chrono::steady_clock;
inline double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A sample name ("notch") means samples/notch.step; anything with a '/' or '.' is a path.
inline std::string resolve(const std::string& name) {
    if (name.find('/') != std::string::npos || name.find('.') != std::string::npos) return name;
    return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step";
}

// The correction benchmarks' arguments: [--size-factor F] [--threads T] SAMPLE...
inline std::vector<std::string> sample_args(int argc, char** argv, RunOptions& options) {
    std::vector<std::string> samples;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string("0"); };
        if (a == "--size-factor") options.size_factor = std::atof(next().c_str());
        else if (a == "--threads") options.threads = std::atoi(next().c_str());
        else samples.push_back(a);
    }
    return samples;
}

}  // namespace framefix::bench
