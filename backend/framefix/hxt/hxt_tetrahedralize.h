#pragma once
// Volume meshing with gmsh's HXT (Marot et al. 2019), an alternative to TetGen (--mesher hxt)
// for large meshes: a parallel Delaunay kernel, several times TetGen's speed on 2 cores
// (docs/results.md). It runs in the framefix-hxt worker (backend/hxt_worker), a program of its own.
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {

// Tets inside the closed surface `surface`, which HXT keeps as it is: the boundary triangles,
// their face tags, the feature segments and the corners come from `surface` unchanged, and the
// surface's points are the mesh's first vertices. The interior size follows the surface's edge
// lengths, capped at options.size, with options.threads threads (0 = all cores). HXT's failures
// and crashes come back as a status, as TetGen's do; a missing worker too, with what to install.
TetgenRun try_hxt(const SurfaceMesh& surface, const MeshOptions& options);

}  // namespace framefix
