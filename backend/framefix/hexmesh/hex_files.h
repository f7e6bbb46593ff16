#pragma once
// The hex mesh as files: legacy VTK (ParaView), gmsh's MSH 4.1 ASCII, and CalculiX/Abaqus .inp.
#include <string>

#include "framefix/hexmesh/hexmesh.h"

namespace framefix {

// Each throws framefix::Error("output") when the file cannot be written.
// VTK_HEXAHEDRON (or VTK_QUADRATIC_HEXAHEDRON at order 2) cells with "block" and
// "scaled_jacobian" cell data.
void write_hex_vtk(const HexMesh& mesh, const std::string& path);
// One volume entity; 8-node hexes (type 5) or 20-node (type 17), node tags from 1.
void write_hex_msh(const HexMesh& mesh, const std::string& path);
// *NODE, *ELEMENT (C3D8 or C3D20) in ELSET EALL, and one NSET FACE<tag> per B-rep face with the
// nodes on it, for boundary conditions.
void write_hex_inp(const HexMesh& mesh, const std::string& path);

}  // namespace framefix
