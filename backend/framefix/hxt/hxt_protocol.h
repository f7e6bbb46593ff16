#pragma once
// What the framefix-hxt worker reads and writes (backend/hxt_worker). Header only: the worker
// links gmsh and must not link TetGen (gmsh carries its own copy of TetGen's classes).
#include <string>

#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix::hxt {

constexpr const char* kWorkerName = "framefix-hxt";  // beside the framefix binary, in bin/

// First byte of the worker's standard output; a TetMesh's bytes or a message follow.
constexpr char kMeshed = 'M', kFailed = 'F';

// The surface travels as a TetMesh without tets: points, boundary faces, tags, corners.
inline TetMesh as_tet_mesh(const SurfaceMesh& s, double h) {
    TetMesh m;
    m.points = s.points;
    m.tets.resize(0, 4);
    m.boundary_faces = s.triangles;
    m.face_tags = s.face_tags;
    m.feature_edges = s.feature_segments;
    m.edge_tags = s.segment_tags;
    m.corner_vertices = s.corner_points;
    m.size = h;
    return m;
}

inline SurfaceMesh as_surface(const TetMesh& m) {
    SurfaceMesh s;
    s.points = m.points;
    s.triangles = m.boundary_faces;
    s.face_tags = m.face_tags;
    s.feature_segments = m.feature_edges;
    s.segment_tags = m.edge_tags;
    s.corner_points = m.corner_vertices;
    return s;
}

}  // namespace framefix::hxt
