#pragma once
// Reading and writing tet meshes: gmsh .msh version 4 ASCII and Medit .mesh. Only the linear
// tets (and, for face tags, the boundary triangles) are read; lines/edges/corners in the file are
// ignored: feature curves of an imported mesh come from its creases (crease_features.h).
// Written by hand (no library): two small text formats, and the readers must turn every bad
// file into a framefix::Error("load", ...) instead of a crash.
#include <string>

#include "framefix/mesh/tet_mesh.h"

namespace framefix {

// By extension: .msh or .mesh. The returned mesh has
//   points         only the vertices used by a tet, in file order;
//   tets           positively oriented (two vertices swapped where the file had them negative);
//   boundary_faces the triangles of one tet only, outward (kTetFace of their tet);
//   face_tags      the file's surface tag of each boundary triangle (gmsh entity tag or Medit
//                  reference), 0 where the file has no such triangle;
//   feature_edges, edge_tags, corner_vertices empty; size = mean tet edge length.
// Throws Error("load") for a missing, empty, truncated or malformed file, binary or v2 .msh,
// non-tet volume elements, out-of-range node indices and flat tets.
TetMesh read_tet_mesh(const std::string& path);
TetMesh read_msh(const std::string& path);
TetMesh read_medit(const std::string& path);

// Tets, points and the tagged boundary triangles (gmsh: one surface entity per face tag).
void write_msh(const TetMesh& mesh, const std::string& path);
void write_medit(const TetMesh& mesh, const std::string& path);

// What read_* do after parsing: orient, drop unused vertices, extract and tag the boundary.
// tri/tri_tags: triangles of the file with their tags (may be empty). Exposed for tests.
TetMesh assemble_tet_mesh(Points points, Tets tets, const Triangles& tri, const Eigen::VectorXi& tri_tags);

}  // namespace framefix
