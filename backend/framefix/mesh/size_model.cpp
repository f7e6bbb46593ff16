#include "framefix/mesh/size_model.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <string>

#include "framefix/core/error.h"
#include "framefix/core/memory.h"
#include "framefix/mesh/surface_mesh.h"

namespace framefix {
namespace {

// Peak resident memory per tet while TetGen runs and the result is copied, MiB.
constexpr double kMbPerTet = 4.0e-4;  // measured ~2.5e-4 (bench_mesh: 1.75M tets, 416 MB peak)
constexpr double kBaseMb = 50.0;

std::string format(const char* fmt, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, x);
    return buf;
}

std::string megabytes(double mb) {
    if (mb < 1024) return format("%.0f", mb) + " MB";
    return format(mb < 10240 ? "%.1f" : "%.0f", mb / 1024) + " GB";
}

// Round up to two significant digits, so the suggested size is really large enough.
double round_up_2(double x) {
    const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1);
    return std::ceil(x / scale - 1e-9) * scale;
}

}  // namespace

double estimate_tets(double volume, double size) { return volume / (kMeanTetVolumePerH3 * size * size * size); }

double estimate_memory_mb(double tets) { return kBaseMb + kMbPerTet * tets; }

double size_for_tets(double volume, double tets) { return std::cbrt(volume / (kMeanTetVolumePerH3 * tets)); }

void check_memory(double volume, double size, const MeshOptions& options) {
    if (!(size > 0)) throw Error("mesh", "size " + format("%g", size) + " is not positive; give an edge length > 0");
    const double limit = options.max_memory_mb > 0 ? options.max_memory_mb : 0.8 * available_memory_mb();
    const double tets = estimate_tets(volume, size);
    const double mb = estimate_memory_mb(tets);
    if (mb <= limit) return;
    const double min_size = round_up_2(size_for_tets(volume, std::max(limit - kBaseMb, 1.0) / kMbPerTet));
    const std::string need = "~" + megabytes(mb), have = megabytes(limit);
    throw Error("mesh", "size " + format("%g", size) + " needs about " + format("%.2g", tets) + " tets (" + need +
                            ", limit " + have + "); use --size " + format("%g", min_size) + " or larger");
}

}  // namespace framefix
