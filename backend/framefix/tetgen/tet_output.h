#pragma once
// TetGen's output arrays -> TetMesh with our conventions (positive tets, outward tagged
// boundary, tagged feature edges, corners at B-rep vertices).
#include <tetgen.h>

#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// Input edge markers are kFeatureMarker + B-rep edge index: TetGen also marks the other boundary
// edges (with facet markers), and this offset tells them apart.
constexpr int kFeatureMarker = 1 << 28;

// `out` from tetrahedralize("p...zfe") on the PLC `surface` (0-based numbering).
TetMesh tet_mesh_from_tetgen(const tetgenio& out, const SurfaceMesh& surface);

}  // namespace framefix
