#include <filesystem>
#include <fstream>

#include "framefix/core/error.h"
#include "framefix/hexmesh/hex_files.h"
#include "framefix/mesh/vtk_writer.h"
#include "framefix/pipeline/report.h"

namespace framefix {
namespace {

constexpr int kVtkLine = 3, kVtkPolyline = 4, kVtkTriangle = 5, kVtkTet = 10, kVtkVertex = 1;

// Tets, boundary triangles and feature edges in one grid, told apart by "cell_kind"
// (0 tet, 1 boundary triangle, 2 feature edge); the field as point data.
VtkGrid mesh_grid(const RunResult& r) {
    const TetMesh& m = r.mesh->tets;
    VtkGrid g;
    g.points = m.points;
    VtkArray kind{"cell_kind", 1, {}}, face{"face_tag", 1, {}}, edge{"edge_tag", 1, {}}, val{"edge_valence", 1, {}};
    auto add = [&](std::vector<int> cell, int type, int k, int f, int e) {
        g.cells.push_back(std::move(cell));
        g.cell_types.push_back(type);
        kind.data.push_back(k);
        face.data.push_back(f);
        edge.data.push_back(e);
        val.data.push_back(e > 0 ? r.mesh->features.valence_of(e) : 0);
    };
    for (int t = 0; t < m.num_tets(); ++t) add({m.tets(t, 0), m.tets(t, 1), m.tets(t, 2), m.tets(t, 3)}, kVtkTet, 0, 0, 0);
    for (int b = 0; b < m.boundary_faces.rows(); ++b)
        add({m.boundary_faces(b, 0), m.boundary_faces(b, 1), m.boundary_faces(b, 2)}, kVtkTriangle, 1, m.face_tags(b), 0);
    for (int s = 0; s < m.feature_edges.rows(); ++s)
        add({m.feature_edges(s, 0), m.feature_edges(s, 1)}, kVtkLine, 2, 0, m.edge_tags(s));
    g.cell_data = {kind, face, edge, val};
    if (r.field) {
        const FrameField& f = r.field->frames;
        VtkArray q{"frame_coefficients", 9, std::vector<double>(f.coefficients.data(), f.coefficients.data() + f.coefficients.size())};
        VtkArray d{"distance_to_manifold", 1, std::vector<double>(f.distance.data(), f.distance.data() + f.distance.size())};
        VtkArray c{"constraint_kind", 1, {}};
        for (auto k : f.kind) c.data.push_back(double(int(k)));
        g.point_data = {q, d, c};
        for (int a = 0; a < 3; ++a) {
            VtkArray axis{"axis" + std::to_string(a + 1), 3, {}};
            for (int v = 0; v < f.axes.rows(); ++v)
                for (int k = 0; k < 3; ++k) axis.data.push_back(f.axes(v, 3 * a + k));
            g.point_data.push_back(axis);
        }
    }
    return g;
}

// Polylines, one cell each, with one value per polyline for each named cell array.
VtkGrid polylines_grid(const std::vector<const Points*>& lines, std::vector<VtkArray> cell_arrays) {
    VtkGrid g;
    int n = 0;
    for (const Points* p : lines) n += int(p->rows());
    g.points.resize(n, 3);
    int at = 0;
    for (const Points* p : lines) {
        std::vector<int> cell;
        for (int i = 0; i < p->rows(); ++i, ++at) {
            g.points.row(at) = p->row(i);
            cell.push_back(at);
        }
        g.cells.push_back(cell);
        g.cell_types.push_back(kVtkPolyline);
    }
    g.cell_data = std::move(cell_arrays);
    return g;
}

VtkGrid curves_grid(const SingularityGraph& s) {
    std::vector<const Points*> lines;
    VtkArray kind{"kind", 1, {}}, id{"curve_id", 1, {}};
    for (const auto& c : s.curves) {
        lines.push_back(&c.points);
        kind.data.push_back(int(c.kind));
        id.data.push_back(c.id);
    }
    return polylines_grid(lines, {kind, id});
}

VtkGrid nodes_grid(const SingularityGraph& s) {
    VtkGrid g;
    g.points.resize(int(s.nodes.size()), 3);
    VtkArray valid{"valid", 1, {}}, n3{"n3", 1, {}}, n5{"n5", 1, {}}, boundary{"boundary", 1, {}};
    for (size_t i = 0; i < s.nodes.size(); ++i) {
        g.points.row(int(i)) = s.nodes[i].position.transpose();
        g.cells.push_back({int(i)});
        g.cell_types.push_back(kVtkVertex);
        valid.data.push_back(s.nodes[i].valid);
        n3.data.push_back(s.nodes[i].n3);
        n5.data.push_back(s.nodes[i].n5);
        boundary.data.push_back(s.nodes[i].boundary);
    }
    g.cell_data = {valid, n3, n5, boundary};
    return g;
}

VtkGrid paths_grid(const SnapResult& snap) {
    std::vector<const Points*> lines;
    VtkArray source{"source_curve", 1, {}}, forced{"forced", 1, {}};
    for (const auto& p : snap.paths) {
        lines.push_back(&p.points);
        source.data.push_back(p.source_curve);
        forced.data.push_back(p.forced);
    }
    return polylines_grid(lines, {source, forced});
}

// The extrusions' streamlines, with their stop reason (StopReason's number) and whether they are used.
VtkGrid streamlines_grid(const ExtrusionPlan& plan) {
    std::vector<const Points*> lines;
    VtkArray used{"used", 1, {}}, stop{"stop_reason", 1, {}};
    for (const auto& l : plan.streamlines) {
        lines.push_back(&l.line.points);
        used.data.push_back(l.used);
        stop.data.push_back(int(l.line.reason));
    }
    return polylines_grid(lines, {used, stop});
}

// Tets labelled by block, and the separatrix sheets.
VtkGrid blocks_grid(const TetMesh& m, const BlockDecomposition& b) {
    VtkGrid g;
    g.points = m.points;
    VtkArray block{"block", 1, {}}, valid{"block_valid", 1, {}};
    for (int t = 0; t < m.num_tets(); ++t) {
        g.cells.push_back({m.tets(t, 0), m.tets(t, 1), m.tets(t, 2), m.tets(t, 3)});
        g.cell_types.push_back(kVtkTet);
        const int id = b.tet_block(t);
        block.data.push_back(id);
        valid.data.push_back(id >= 0 && id < int(b.blocks.size()) && b.blocks[id].valid);
    }
    g.cell_data = {block, valid};
    return g;
}

VtkGrid block_surfaces_grid(const BlockDecomposition& b) {
    const BlockSurfaces& s = b.surfaces;
    VtkGrid g;
    g.points = s.points;
    VtkArray block{"block", 1, {}}, across{"neighbour", 1, {}}, valid{"block_valid", 1, {}};
    for (int t = 0; t < s.triangles.rows(); ++t) {
        g.cells.push_back({s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)});
        g.cell_types.push_back(kVtkTriangle);
        block.data.push_back(s.block[t]);
        across.data.push_back(s.neighbour[t]);
        valid.data.push_back(s.block[t] < int(b.blocks.size()) && b.blocks[s.block[t]].valid);
    }
    g.cell_data = {block, across, valid};
    return g;
}

VtkGrid block_edges_grid(const BlockSurfaces& s) {
    VtkGrid g;
    VtkArray block{"block", 1, std::vector<double>(s.edge_block.begin(), s.edge_block.end())};
    g.cell_data = {block};
    int n = 0;
    for (const Points& p : s.edges) n += int(p.rows());
    g.points.resize(n, 3);
    int r = 0;
    for (const Points& p : s.edges) {
        std::vector<int> cell;
        for (int i = 0; i < p.rows(); ++i) g.points.row(r) = p.row(i), cell.push_back(r++);
        g.cells.push_back(cell);
        g.cell_types.push_back(kVtkPolyline);
    }
    return g;
}

VtkGrid sheets_grid(const SheetSoup& s) {
    VtkGrid g;
    g.points = s.points;
    VtkArray source{"source", 1, {}};
    for (int t = 0; t < s.triangles.rows(); ++t) {
        g.cells.push_back({s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)});
        g.cell_types.push_back(kVtkTriangle);
        source.data.push_back(s.source(t));
    }
    g.cell_data = {source};
    return g;
}

}  // namespace

std::vector<std::string> write_outputs(const RunResult& r, const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("output", "cannot create folder " + dir + ": " + ec.message());
    std::vector<std::string> written;
    const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };

    if (r.mesh) {
        write_vtk(mesh_grid(r), path("mesh.vtk"), "FrameFix tet mesh, tags and frame field");
        written.push_back(path("mesh.vtk"));
    }
    if (r.singularities) {
        write_vtk(curves_grid(*r.singularities), path("singular_curves.vtk"), "FrameFix singular curves (kind: 0 valence3, 1 valence5, 2 3-5)");
        write_vtk(nodes_grid(*r.singularities), path("singular_nodes.vtk"), "FrameFix singular nodes");
        written.push_back(path("singular_curves.vtk"));
        written.push_back(path("singular_nodes.vtk"));
    }
    if (const auto& correction = r.correction) {
        write_vtk(curves_grid(correction->graph_before), path("singular_curves_before.vtk"), "FrameFix singular curves before correction");
        write_vtk(paths_grid(correction->snap), path("snapped_curves.vtk"), "FrameFix snapped curves (boundary paths)");
        written.push_back(path("singular_curves_before.vtk"));
        written.push_back(path("snapped_curves.vtk"));
        if (correction->mapped) {
            write_vtk(curves_grid(*correction->mapped), path("mapped_curves.vtk"), "FrameFix corrected curves mapped onto the original part");
            written.push_back(path("mapped_curves.vtk"));
        }
        if (correction->flat_corners && correction->flat_corners->solved) {
            write_vtk(curves_grid(correction->flat_corners->graph), path("flat_corner_curves.vtk"),
                      "FrameFix original part's curves, solved again with flat corners under the mapped curves");
            written.push_back(path("flat_corner_curves.vtk"));
        }
        if (correction->method.rfind("extrude", 0) == 0 || correction->chosen.rfind("extrude", 0) == 0) {
            write_vtk(streamlines_grid(correction->extrusion), path("streamlines.vtk"), "FrameFix extrusion streamlines");
            written.push_back(path("streamlines.vtk"));
        }
        if (correction->filleted)
            for (const char* name : {"filleted.brep", "filleted.step"}) {
                write_shape(*correction->filleted, path(name));
                written.push_back(path(name));
            }
    }
    if (const auto& blocks = r.blocks) {
        write_vtk(blocks_grid(r.mesh->tets, *blocks), path("blocks.vtk"), "FrameFix blocks (tets labelled by block)");
        write_vtk(sheets_grid(blocks->sheets), path("sheets.vtk"), "FrameFix separatrix sheets");
        write_vtk(block_surfaces_grid(*blocks), path("block_surfaces.vtk"), "FrameFix block boundaries, smoothed for display");
        write_vtk(block_edges_grid(blocks->surfaces), path("block_edges.vtk"), "FrameFix block edges, smoothed for display");
        for (const char* name : {"blocks.vtk", "sheets.vtk", "block_surfaces.vtk", "block_edges.vtk"}) written.push_back(path(name));
    }
    if (r.hexmesh && r.hexmesh->done) {
        write_hex_vtk(*r.hexmesh, path("hex.vtk"));
        write_hex_msh(*r.hexmesh, path("hex.msh"));
        write_hex_inp(*r.hexmesh, path("hex.inp"));
        for (const char* name : {"hex.vtk", "hex.msh", "hex.inp"}) written.push_back(path(name));
    }
    std::ofstream out(path("report.json"));
    out << report_json(r) << '\n';
    if (!out) throw Error("output", "cannot write " + path("report.json"));
    written.push_back(path("report.json"));
    return written;
}

}  // namespace framefix
