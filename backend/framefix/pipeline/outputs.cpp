#include <filesystem>
#include <fstream>

#include "framefix/core/error.h"
#include "framefix/mesh/vtk_writer.h"
#include "framefix/pipeline/report.h"

namespace framefix {
namespace {

constexpr int kVtkLine = 3, kVtkPolyline = 4, kVtkTriangle = 5, kVtkTet = 10, kVtkVertex = 1;

// Tets, boundary triangles and feature edges in one grid, told apart by "cell_kind"
// (0 tet, 1 boundary triangle, 2 feature edge); the field as point data.
VtkGrid mesh_grid(const AnalysisResult& r) {
    const TetMesh& m = r.mesh;
    VtkGrid g;
    g.points = m.points;
    VtkArray kind{"cell_kind", 1, {}}, face{"face_tag", 1, {}}, edge{"edge_tag", 1, {}}, val{"edge_valence", 1, {}};
    auto add = [&](std::vector<int> cell, int type, int k, int f, int e) {
        g.cells.push_back(std::move(cell));
        g.cell_types.push_back(type);
        kind.data.push_back(k);
        face.data.push_back(f);
        edge.data.push_back(e);
        val.data.push_back(e > 0 ? r.features.valence_of(e) : 0);
    };
    for (int t = 0; t < m.num_tets(); ++t) add({m.tets(t, 0), m.tets(t, 1), m.tets(t, 2), m.tets(t, 3)}, kVtkTet, 0, 0, 0);
    for (int b = 0; b < m.boundary_faces.rows(); ++b)
        add({m.boundary_faces(b, 0), m.boundary_faces(b, 1), m.boundary_faces(b, 2)}, kVtkTriangle, 1, m.face_tags(b), 0);
    for (int s = 0; s < m.feature_edges.rows(); ++s)
        add({m.feature_edges(s, 0), m.feature_edges(s, 1)}, kVtkLine, 2, 0, m.edge_tags(s));
    g.cell_data = {kind, face, edge, val};
    if (r.has_field) {
        const FrameField& f = r.field;
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

VtkGrid curves_grid(const SingularityGraph& s) {
    VtkGrid g;
    int n = 0;
    for (const auto& c : s.curves) n += int(c.points.rows());
    g.points.resize(n, 3);
    VtkArray kind{"kind", 1, {}}, id{"curve_id", 1, {}};
    int at = 0;
    for (const auto& c : s.curves) {
        std::vector<int> cell;
        for (int i = 0; i < c.points.rows(); ++i, ++at) {
            g.points.row(at) = c.points.row(i);
            cell.push_back(at);
        }
        g.cells.push_back(cell);
        g.cell_types.push_back(kVtkPolyline);
        kind.data.push_back(int(c.kind));
        id.data.push_back(c.id);
    }
    g.cell_data = {kind, id};
    return g;
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
    VtkGrid g;
    int n = 0;
    for (const auto& p : snap.paths) n += int(p.points.rows());
    g.points.resize(n, 3);
    VtkArray source{"source_curve", 1, {}}, forced{"forced", 1, {}};
    int at = 0;
    for (const auto& p : snap.paths) {
        std::vector<int> cell;
        for (int i = 0; i < p.points.rows(); ++i, ++at) {
            g.points.row(at) = p.points.row(i);
            cell.push_back(at);
        }
        g.cells.push_back(cell);
        g.cell_types.push_back(kVtkPolyline);
        source.data.push_back(p.source_curve);
        forced.data.push_back(p.forced);
    }
    g.cell_data = {source, forced};
    return g;
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

std::vector<std::string> write_outputs(const AnalysisResult& r, const std::string& dir, const Correction* correction,
                                       const BlockDecomposition* blocks) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("output", "cannot create folder " + dir + ": " + ec.message());
    std::vector<std::string> written;
    const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };

    write_vtk(mesh_grid(r), path("mesh.vtk"), "FrameFix tet mesh, tags and frame field");
    written.push_back(path("mesh.vtk"));
    if (r.has_singularities) {
        write_vtk(curves_grid(r.singularities), path("singular_curves.vtk"), "FrameFix singular curves (kind: 0 valence3, 1 valence5, 2 3-5)");
        write_vtk(nodes_grid(r.singularities), path("singular_nodes.vtk"), "FrameFix singular nodes");
        written.push_back(path("singular_curves.vtk"));
        written.push_back(path("singular_nodes.vtk"));
    }
    if (correction) {
        write_vtk(curves_grid(correction->graph_before), path("singular_curves_before.vtk"), "FrameFix singular curves before correction");
        write_vtk(paths_grid(correction->snap), path("snapped_curves.vtk"), "FrameFix snapped curves (boundary paths)");
        written.push_back(path("singular_curves_before.vtk"));
        written.push_back(path("snapped_curves.vtk"));
    }
    if (blocks) {
        write_vtk(blocks_grid(r.mesh, *blocks), path("blocks.vtk"), "FrameFix blocks (tets labelled by block)");
        write_vtk(sheets_grid(blocks->sheets), path("sheets.vtk"), "FrameFix separatrix sheets");
        written.push_back(path("blocks.vtk"));
        written.push_back(path("sheets.vtk"));
    }
    std::ofstream out(path("report.json"));
    out << report_json(r, correction, blocks) << '\n';
    if (!out) throw Error("output", "cannot write " + path("report.json"));
    written.push_back(path("report.json"));
    return written;
}

}  // namespace framefix
