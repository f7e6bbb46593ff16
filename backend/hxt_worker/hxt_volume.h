#pragma once
// gmsh's HXT (Marot et al. 2019) on a closed, tagged surface. It runs in the framefix-hxt
// process, never inside FrameFix's own: gmsh's OpenMP hangs in a child forked from a process
// that has used OpenMP (libgomp's thread pool does not survive fork()), and gmsh's copy of
// TetGen's classes clashes with the system TetGen that FrameFix links.
#include <string>

#include "framefix/mesh/surface_mesh.h"

namespace framefix::hxt {

// Tets inside `surface`, which HXT keeps as it is: its points are the mesh's first vertices,
// its triangles the boundary. The interior size follows the surface's edge lengths, capped at
// h; `threads` threads. Returns kMeshed + the TetMesh's bytes, or kFailed + why.
std::string mesh_volume(const SurfaceMesh& surface, double h, int threads);

}  // namespace framefix::hxt
