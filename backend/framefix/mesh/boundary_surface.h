#pragma once
// The boundary of a tet mesh as the tagged PLC it was made from, so that the solid can be meshed
// again with the same boundary triangles, feature segments and corners (extrusion corrections).
#include <vector>

#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct BoundarySurface {
    SurfaceMesh surface;        // boundary vertices renumbered 0..#P-1, corners first in B-rep order
    std::vector<int> vertex;    // #P: the tet-mesh vertex of each surface point
};

BoundarySurface boundary_surface(const TetMesh& mesh);

}  // namespace framefix
