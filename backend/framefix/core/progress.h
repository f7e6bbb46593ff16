#pragma once
// Progress reporting: stages call report(stage, fraction); the CLI prints
// "progress <stage> <fraction>" lines on stderr, which the workbench reads.
#include <functional>
#include <string>

namespace framefix {

using ProgressSink = std::function<void(const std::string& stage, double fraction)>;

inline void report(const ProgressSink& sink, const std::string& stage, double fraction) {
    if (sink) sink(stage, fraction);
}

}  // namespace framefix
