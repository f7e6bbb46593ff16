#pragma once
// Meshing a B-rep solid, tried again another way when TetGen fails: a crash or a failed boundary
// recovery first lets TetGen split boundary triangles, then refines the surface; a
// self-intersecting surface triangulation is first checked against the solid itself (a solid
// that crosses itself is the user's to repair), then refined. With --mesher hxt, gmsh's HXT
// tries first and TetGen's ways follow if it fails. Each try is recorded for report.json.
#include <string>
#include <vector>

#include "framefix/brep/brep_model.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

struct MeshAttempt {
    std::string how;      // "surface at h, boundary kept", ...
    std::string failure;  // why it failed; empty for the attempt that meshed
};

struct BrepMeshing {
    TetMesh tets;
    std::vector<MeshAttempt> attempts;  // in order; the last one meshed
    int narrow_faces = 0;               // faces meshed finer than the size (MeshOptions::keep_narrow_faces)
    Mesher mesher = Mesher::tetgen;     // the one that made the tets (HXT falls back to TetGen)
};

// Throws framefix::Error (stage "mesh") when every attempt fails, naming the first failure.
BrepMeshing mesh_brep(const BrepModel& model, const FeatureSet& features, const MeshOptions& options);

}  // namespace framefix
