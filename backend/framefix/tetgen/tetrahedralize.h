#pragma once
// Near-uniform volume meshing with TetGen: the only module that includes tetgen.h.
#include "framefix/mesh/size_model.h"
#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// Tets of target edge length options.size inside the closed PLC `surface`. Boundary triangles
// keep their face tags, feature segments their edge tags (split where TetGen refines them),
// corner points stay mesh vertices. Refuses (framefix::Error, stage "mesh") sizes whose memory
// estimate exceeds the limit, and reports TetGen failures (self-intersecting boundary, ...).
TetMesh tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options);

}  // namespace framefix
