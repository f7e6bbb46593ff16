#pragma once
// Memory figures for reports and for refusing sizes the machine cannot hold.
#include <cstdint>

namespace framefix {

double peak_memory_mb();          // peak resident set of this process (VmHWM), in MiB
double available_memory_mb();     // MemAvailable from /proc/meminfo, in MiB

}  // namespace framefix
