#pragma once
// The boundary of a solid as a triangulated PLC: what OCCT's tessellation hands to TetGen.
#include <map>

#include <Eigen/Core>

#include "framefix/mesh/size_model.h"
#include "framefix/mesh/types.h"

namespace framefix {

struct SurfaceMesh {
    Points points;                  // #P x 3, model units; B-rep vertices come first
    Triangles triangles;            // #F x 3 point indices, oriented outward
    Eigen::VectorXi face_tags;      // #F, B-rep face index (1-based) of each triangle
    Segments feature_segments;      // #S x 2 point indices, polyline pieces of feature curves
    Eigen::VectorXi segment_tags;   // #S, B-rep edge index (1-based) of each segment
    Eigen::VectorXi corner_points;  // #C point index of B-rep vertex i+1
};

// The volume mesher: TetGen (the default), or gmsh's HXT through libgmsh (hxt/hxt_tetrahedralize.h).
enum class Mesher : char { tetgen, hxt };
inline const char* mesher_name(Mesher m) { return m == Mesher::hxt ? "hxt" : "tetgen"; }

// Options of the meshing stage (tessellate + tetrahedralize).
struct MeshOptions {
    double size = 0;            // target edge length h in model units; 0 = about target_tets tets
    int target_tets = kDefaultTargetTets;  // used only when size == 0
    double max_memory_mb = 0;   // refuse sizes whose estimate exceeds this; 0 = 80% of available RAM
    // B-rep face (1-based) -> a smaller edge length on it (the fillet correction's fillet
    // surfaces); TetGen's quality bound grades the tets from there to `size`.
    std::map<int, double> face_size;
    // A size coarser than the default coarsens only faces wide enough for it: narrower ones keep
    // 2.5 edges across, or the default size (pipeline/mesh_attempts.cpp).
    bool keep_narrow_faces = true;
    Mesher mesher = Mesher::tetgen;
    int threads = 0;            // HXT's threads, 0 = all cores (TetGen is serial)
};

}  // namespace framefix
