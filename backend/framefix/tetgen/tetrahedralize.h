#pragma once
// Near-uniform volume meshing with TetGen: the only module that includes tetgen.h.
#include <string>

#include "framefix/mesh/size_model.h"
#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// Tets of target edge length options.size inside the closed PLC `surface`. Boundary triangles
// keep their face tags, feature segments their edge tags (split where TetGen refines them),
// corner points stay mesh vertices. Refuses (framefix::Error, stage "mesh") sizes whose memory
// estimate exceeds the limit, and reports TetGen failures (self-intersecting boundary, ...).
// `inserted` points become mesh vertices too (TetGen -i; points outside the solid are skipped),
// after the surface's points; find them by position, TetGen may drop near-duplicates.
TetMesh tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options, const Points& inserted = Points());

// How one TetGen run ended, for callers that try again another way (pipeline/mesh_attempts.h).
enum class TetgenStatus : char {
    meshed,
    self_intersecting,  // the surface crosses itself (TetGen's -d test); no tet was made
    recovery_failed,    // TetGen gave up recovering the boundary (tiny features, near-coincident facets)
    crashed,            // the worker died (a signal): TetGen's boundary recovery on some industrial parts
    failed,             // out of memory, an open surface: trying again will not help
};
struct TetgenRun {
    TetgenStatus status = TetgenStatus::failed;
    std::string message;  // what failed, for the report; empty when meshed
    TetMesh mesh;         // when meshed
};

// The tet edge length for `surface` (options.size, or the one giving about options.target_tets
// tets), after the checks every volume mesher needs: a closed, outward surface, and a size whose
// memory estimate fits (framefix::Error, stage "mesh", otherwise).
double checked_volume_size(const SurfaceMesh& surface, const MeshOptions& options);

// tetrahedralize() without throwing for TetGen's failures (bad options still throw).
// keep_boundary = false lets TetGen split boundary triangles and segments (no -Y); the pieces keep
// their face and edge tags.
TetgenRun try_tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options, bool keep_boundary,
                             const Points& inserted = Points());

}  // namespace framefix
