#pragma once
// A small legacy-VTK (ASCII, UNSTRUCTURED_GRID) writer that ParaView opens. Written by hand
// because VTK itself is a large dependency for writing a few arrays.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/types.h"

namespace framefix {

struct VtkArray {
    std::string name;
    int components = 1;        // 1 scalar, 3 vector, or any count (written as FIELD data)
    std::vector<double> data;  // #items x components, row-major
};

struct VtkGrid {
    Points points;                       // #P x 3
    std::vector<std::vector<int>> cells; // each: point indices (2 line, 3 triangle, 4 tet, n polyline)
    std::vector<int> cell_types;         // VTK cell type per cell (3 line, 4 polyline, 5 triangle, 10 tet)
    std::vector<VtkArray> point_data;    // each #P items
    std::vector<VtkArray> cell_data;     // each #cells items
};

// Throws framefix::Error("output", ...) when the file cannot be written.
void write_vtk(const VtkGrid& grid, const std::string& path, const std::string& title);

}  // namespace framefix
