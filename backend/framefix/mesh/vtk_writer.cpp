#include "framefix/mesh/vtk_writer.h"

#include <cstdio>
#include <fstream>

#include "framefix/core/error.h"

namespace framefix {
namespace {

void write_arrays(std::ofstream& out, const std::vector<VtkArray>& arrays, size_t count) {
    std::vector<const VtkArray*> field;
    for (const auto& a : arrays) {
        if (a.data.size() != count * size_t(a.components))
            throw InternalError("vtk array " + a.name + " has the wrong length");
        if (a.components == 1) {
            out << "SCALARS " << a.name << " double 1\nLOOKUP_TABLE default\n";
        } else if (a.components == 3) {
            out << "VECTORS " << a.name << " double\n";
        } else {
            field.push_back(&a);
            continue;
        }
        for (size_t i = 0; i < count; ++i) {
            for (int c = 0; c < a.components; ++c) out << (c ? " " : "") << a.data[i * a.components + c];
            out << '\n';
        }
    }
    if (field.empty()) return;
    out << "FIELD FieldData " << field.size() << '\n';
    for (const auto* a : field) {
        out << a->name << ' ' << a->components << ' ' << count << " double\n";
        for (size_t i = 0; i < count; ++i) {
            for (int c = 0; c < a->components; ++c) out << (c ? " " : "") << a->data[i * a->components + c];
            out << '\n';
        }
    }
}

}  // namespace

void write_vtk(const VtkGrid& g, const std::string& path, const std::string& title) {
    std::ofstream out(path);
    if (!out) throw Error("output", "cannot write " + path + "; check that the folder exists and is writable");
    out.precision(10);
    out << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << g.points.rows() << " double\n";
    for (int i = 0; i < g.points.rows(); ++i)
        out << g.points(i, 0) << ' ' << g.points(i, 1) << ' ' << g.points(i, 2) << '\n';
    size_t total = 0;
    for (const auto& c : g.cells) total += c.size() + 1;
    out << "CELLS " << g.cells.size() << ' ' << total << '\n';
    for (const auto& c : g.cells) {
        out << c.size();
        for (int v : c) out << ' ' << v;
        out << '\n';
    }
    out << "CELL_TYPES " << g.cells.size() << '\n';
    for (int t : g.cell_types) out << t << '\n';
    if (!g.cell_data.empty()) {
        out << "CELL_DATA " << g.cells.size() << '\n';
        write_arrays(out, g.cell_data, g.cells.size());
    }
    if (!g.point_data.empty()) {
        out << "POINT_DATA " << g.points.rows() << '\n';
        write_arrays(out, g.point_data, size_t(g.points.rows()));
    }
    if (!out) throw Error("output", "writing " + path + " failed (disk full?)");
}

}  // namespace framefix
