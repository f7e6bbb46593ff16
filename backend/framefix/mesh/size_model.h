#pragma once
// How many tets a size h gives and what they cost, calibrated on TetGen runs on the samples
// (bench/bench_mesh prints the measured figures next to these estimates). In mesh/ rather than
// tetgen/ because brep picks default sizes and checks memory before TetGen is ever called.
namespace framefix {

struct MeshOptions;

// Default tet count when no size is given: a few seconds for field + blocks on the samples.
constexpr int kDefaultTargetTets = 50000;

// Mean tet volume / h^3 of TetGen meshes made with -q1.3/15 -a<0.2 h^3> (a regular tet of edge h
// has 0.118 h^3; TetGen's are less regular). Measured on the samples.
constexpr double kMeanTetVolumePerH3 = 0.085;

// Tets TetGen will produce for this volume and size, and the memory that needs (MiB).
double estimate_tets(double volume, double size);
double estimate_memory_mb(double tets);

// The size h giving about `tets` tets in this volume (inverse of estimate_tets).
double size_for_tets(double volume, double tets);

// Throws Error("mesh", "size 0.001 needs about 2.1e9 tets (~900 GB); use --size 0.02 or larger")
// when meshing `volume` at `size` would need more than options.max_memory_mb (0 = 80% of
// MemAvailable). Called by tessellate and tetrahedralize before any work.
void check_memory(double volume, double size, const MeshOptions& options);

}  // namespace framefix
