#pragma once
// Near-uniform volume meshing with TetGen: the only module that includes tetgen.h.
#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// Tets of target edge length options.size inside the closed PLC `surface`. Boundary triangles
// keep their face tags, feature segments their edge tags (split where TetGen refines them),
// corner points stay mesh vertices. Refuses (framefix::Error, stage "mesh") sizes whose memory
// estimate exceeds the limit, and reports TetGen failures (self-intersecting boundary, ...).
TetMesh tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options);

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
