// The pipeline in Python: one entry point, run(), whose result carries every stage it reached.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "framefix/core/error.h"
#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/report.h"

namespace py = pybind11;

namespace framefix::python {
namespace {

Stage stage_named(const std::string& name) {
    for (Stage s : {Stage::load, Stage::mesh, Stage::field, Stage::singularities, Stage::correction, Stage::blocks, Stage::hexmesh})
        if (name == stage_name(s)) return s;
    throw Error("options", "unknown stage '" + name + "'; use load, mesh, field, singularities, correct, blocks or hexmesh");
}

struct HexArgs { double size = 0; int layers = 0, order = 1; bool refine = true; };

struct BlockArgs { bool remesh_thin = true; };

RunOptions make_options(const std::string& stop_after, const std::string& method, double size, double size_factor,
                        int threads, double budget_s, bool fillet_rims, const HexArgs& hex, const std::string& mesher,
                        const BlockArgs& blocks) {
    RunOptions o;
    o.remesh_thin = blocks.remesh_thin;
    o.mesh.mesher = mesher_named(mesher);
    o.hexmesh.size = hex.size;
    o.hexmesh.layers = hex.layers;
    o.hexmesh.order = hex.order;
    o.hexmesh.refine_flat = hex.refine;
    o.budget_s = budget_s;
    o.fillet.rims = fillet_rims;
    o.stop_after = stage_named(stop_after);
    o.correction = method;
    o.mesh.size = size;
    o.size_factor = size_factor;
    o.threads = threads;
    return o;
}

template <class T>
py::object optional_of(const std::optional<T>& v) {
    return v ? py::cast(*v) : py::none();
}

void bind_correction(py::module_& m) {
    py::class_<Correction>(m, "Correction", "What a correction did; the run's field and graph are the corrected ones")
        .def_readonly("method", &Correction::method)
        .def_readonly("chosen", &Correction::chosen, "method auto: the method or combination kept, '' if none helped")
        .def_property_readonly("tries", [](const Correction& c) {
            py::list out;
            for (const CorrectionTry& t : c.tries)
                out.append(py::dict(py::arg("method") = t.method, py::arg("ran") = t.ran, py::arg("kept") = t.kept,
                                    py::arg("after") = summary_dict(t.after), py::arg("seconds") = t.seconds,
                                    py::arg("reason") = t.reason));
            return out;
        }, "method auto: one dict per try (method, ran, kept, after, seconds, reason)")
        .def_property_readonly("snap_rounds", [](const Correction& c) {
            py::list out;
            for (const SingularitySummary& s : c.snap_rounds) out.append(summary_dict(s));
            return out;
        }, "the summary after each snapping round")
        .def_readonly("changed", &Correction::changed)
        .def_readonly("rotated_fraction", &Correction::rotated_fraction, "vertices whose frame turned > 10 deg")
        .def_readonly("graph_before", &Correction::graph_before)
        .def_property_readonly("before", [](const Correction& c) { return summary_dict(c.before); })
        .def_property_readonly("snapped_paths", [](const Correction& c) {
            std::vector<Points> out;
            for (const auto& p : c.snap.paths) out.push_back(p.points);
            return out;
        })
        .def_property_readonly("fillets", [](const Correction& c) {
            py::list out;
            for (const FilletOutcome& f : c.fillets) {
                py::dict d;
                d["edge"] = f.edge;
                d["radius"] = f.radius;
                d["done"] = f.done;
                d["reason"] = f.reason;
                out.append(d);
            }
            return out;
        }, "method fillet: one dict per edge tried (edge, radius, done, reason)")
        .def_readonly("notes", &Correction::notes, "method fillet: 3-5 curves it cannot remove, radii cut by the room")
        .def_readonly("remeshed", &Correction::remeshed, "the run's mesh is the filleted solid's")
        .def_property_readonly("filleted_brep", [](const Correction& c) {
            return c.filleted ? py::object(py::str(to_brep_string(*c.filleted))) : py::object(py::none());
        }, "method fillet: the filleted solid as BREP text (Part.Shape().importBrepFromString), else None")
        .def_property_readonly("streamlines", [](const Correction& c) {
            py::list out;
            for (const ExtrusionStreamline& l : c.extrusion.streamlines) {
                py::dict d;
                d["source"] = l.source;
                d["points"] = l.line.points;
                d["length"] = l.line.length;
                d["stop"] = to_string(l.line.reason);
                d["used"] = l.used;
                d["failure"] = l.failure;
                out.append(d);
            }
            return out;
        }, "methods extrude-*: one dict per streamline (source, points, length, stop, used, failure)")
        .def_property_readonly("failures", [](const Correction& c) {
            py::list out;
            for (const ExtrusionFailure& f : c.extrusion.failures) out.append(py::dict(py::arg("what") = f.what, py::arg("why") = f.why));
            return out;
        }, "methods extrude-*: what failed and why (a failure is a result, not an error)")
        .def_readonly("constrained_points", &Correction::constrained_points,
                      "methods extrude-*: vertices of the new mesh carrying an internal constraint")
        .def_property_readonly("mapped", [](const Correction& c) { return optional_of(c.mapped); },
                               "method fillet: the corrected graph mapped onto the original part, else None")
        .def_property_readonly("flat_corners", [](const Correction& c) -> py::object {
            if (!c.flat_corners || !c.flat_corners->solved) return py::none();
            return py::cast(c.flat_corners->graph);
        }, "method fillet: the original part's graph solved again with flat corners under the mapped "
           "valence-5 curves, else None");
}

void bind_blocks(py::module_& m) {
    py::class_<BlockDecomposition>(m, "Blocks", "The block decomposition and its validation")
        .def_readonly("tet_block", &BlockDecomposition::tet_block, "#T block id per tet")
        .def_readonly("count", &BlockDecomposition::count)
        .def_readonly("valid", &BlockDecomposition::valid)
        .def_readonly("conforming_pairs", &BlockDecomposition::conforming_pairs)
        .def_readonly("pairs", &BlockDecomposition::pairs)
        .def_readonly("convex_paths", &BlockDecomposition::convex_paths,
                      "indices of the snapped paths on a convex surface (they emit no sheet)")
        .def_readonly("curtain_corners", &BlockDecomposition::curtain_corners,
                      "corner lines below those paths' feet that emit sheets instead")
        .def_readonly("ring_cuts", &BlockDecomposition::ring_cuts,
                      "meridian sheets across rings (blocks that were solid tori, as a tube)")
        .def_readonly("joined_blocks", &BlockDecomposition::joined_blocks,
                      "invalid blocks of fewer than 6 faces joined to a neighbour, making a hexahedron")
        .def_readonly("split_blocks", &BlockDecomposition::split_blocks,
                      "invalid blocks of fewer than 6 faces shared between two neighbours, making both hexahedra")
        .def_readonly("prism_cuts", &BlockDecomposition::prism_cuts,
                      "invalid prism blocks (5 to 8 faces around) cut into hexahedra")
        .def_readonly("carried_cuts", &BlockDecomposition::carried_cuts,
                      "of the prism cuts, those carried on through the neighbours whose faces they split")
        .def_readonly("triangle_folds", &BlockDecomposition::triangle_folds,
                      "invalid triangular prism blocks made hexahedra by splitting a boundary side face in two")
        .def_property_readonly("junction_tries", [](const BlockDecomposition& b) {
            py::list out;
            for (const auto& t : b.junction_tries)
                out.append(py::dict(py::arg("mode") = t.mode, py::arg("count") = t.count, py::arg("valid") = t.valid, py::arg("pairs") = t.pairs,
                                    py::arg("conforming_pairs") = t.conforming_pairs));
            return out;
        }, "sheet modes tried at interior nodes where 3+ curves meet, with their blocks (empty: no such node)")
        .def_readonly("junction_mode", &BlockDecomposition::junction_mode, "the mode whose blocks were kept");
}

void bind_hexmesh(py::module_& m) {
    py::class_<HexMesh>(m, "HexMesh", "The hex mesh of the blocks, or why there is none")
        .def_readonly("done", &HexMesh::done)
        .def_readonly("reason", &HexMesh::reason, "why there is no hex mesh, when not done")
        .def_readonly("points", &HexMesh::points, "#V x 3")
        .def_property_readonly("hexes", [](const HexMesh& h) {
            Eigen::Matrix<int, Eigen::Dynamic, 8, Eigen::RowMajor> out(Eigen::Index(h.hexes.size()), 8);
            for (size_t i = 0; i < h.hexes.size(); ++i)
                for (int c = 0; c < 8; ++c) out(Eigen::Index(i), c) = h.hexes[i][c];
            return out;
        }, "#H x 8 vertex ids in VTK_HEXAHEDRON / C3D8 order")
        .def_property_readonly("midpoints", [](const HexMesh& h) {
            Eigen::Matrix<int, Eigen::Dynamic, 12, Eigen::RowMajor> out(Eigen::Index(h.midpoints.size()), 12);
            for (size_t i = 0; i < h.midpoints.size(); ++i)
                for (int c = 0; c < 12; ++c) out(Eigen::Index(i), c) = h.midpoints[i][c];
            return out;
        }, "order 2: #H x 12 edge-midpoint ids in C3D20 order; else 0 rows")
        .def_readonly("hex_block", &HexMesh::hex_block, "block id per hex")
        .def_readonly("scaled_jacobian", &HexMesh::scaled_jacobian, "minimum scaled Jacobian per hex")
        .def_property_readonly("quality", [](const HexMesh& h) {
            const HexQuality& q = h.quality;
            return py::dict(py::arg("min_scaled_jacobian") = q.min_scaled_jacobian,
                            py::arg("mean_scaled_jacobian") = q.mean_scaled_jacobian,
                            py::arg("share_sj_ge_0_5") = q.share_sj_ge_0_5, py::arg("inverted") = q.inverted,
                            py::arg("volume") = q.volume);
        })
        .def_property_readonly("refinement", [](const HexMesh& h) {
            const HexRefinement& r = h.refinement;
            return py::dict(py::arg("applied") = r.applied, py::arg("kept") = r.kept,
                            py::arg("plain_min_scaled_jacobian") = r.plain_min_scaled_jacobian,
                            py::arg("refined_min_scaled_jacobian") = r.refined_min_scaled_jacobian,
                            py::arg("blocks_before") = r.blocks_before, py::arg("blocks") = r.blocks,
                            py::arg("refined") = r.refined, py::arg("flat_edges_before") = r.flat_edges_before,
                            py::arg("flat_corners_before") = r.flat_corners_before, py::arg("flat_edges") = r.flat_edges,
                            py::arg("flat_corners") = r.flat_corners, py::arg("skipped") = r.skipped);
        }, "the flat-edge refinement: report.json's hexmesh.refinement");
}

void bind_result(py::module_& m) {
    py::class_<RunResult>(m, "Analysis", "Every stage a run reached (None for the others), plus its report")
        .def_readonly("input_path", &RunResult::input_path)
        .def_readonly("input_kind", &RunResult::input_kind)
        .def_property_readonly("mesh", [](const RunResult& r) { return r.mesh ? py::cast(r.mesh->tets) : py::none(); })
        .def_property_readonly("mesh_attempts", [](const RunResult& r) {
            py::list out;  // how the tets were made: the last entry meshed
            if (r.mesh)
                for (const MeshAttempt& a : r.mesh->attempts)
                    out.append(py::dict(py::arg("how") = a.how,
                                        py::arg("failure") = a.failure.empty() ? py::object(py::none()) : py::cast(a.failure)));
            return out;
        })
        .def_property_readonly("features", [](const RunResult& r) {
            return r.mesh ? r.mesh->features.edges : std::vector<EdgeFeature>{};
        })
        .def_property_readonly("field", [](const RunResult& r) { return r.field ? py::cast(r.field->frames) : py::none(); })
        .def_property_readonly("singularities", [](const RunResult& r) { return optional_of(r.singularities); })
        .def_property_readonly("correction", [](const RunResult& r) { return optional_of(r.correction); })
        .def_property_readonly("blocks", [](const RunResult& r) { return optional_of(r.blocks); })
        .def_property_readonly("hexmesh", [](const RunResult& r) { return optional_of(r.hexmesh); })
        .def_property_readonly("report_json", [](const RunResult& r) { return report_json(r); })
        .def("write_outputs", [](const RunResult& r, const std::string& dir) { return write_outputs(r, dir); },
             py::arg("folder"))
        .def_property_readonly("human_summary", [](const RunResult& r) { return human_summary(r); });
}

}  // namespace

void bind_pipeline(py::module_& m) {
    bind_correction(m);
    bind_blocks(m);
    bind_hexmesh(m);
    bind_result(m);
    m.def(
        "run_file",
        [](const std::string& path, const std::string& stop_after, const std::string& method, double size,
           double size_factor, int threads, double budget_s, bool fillet_rims, double hex_size, int layers, int order,
           const std::string& mesher, bool refine, bool remesh_thin) {
            return run(RunInput::file(path), make_options(stop_after, method, size, size_factor, threads, budget_s, fillet_rims,
                                                         HexArgs{hex_size, layers, order, refine}, mesher,
                                                         BlockArgs{remesh_thin}));
        },
        py::arg("path"), py::arg("stop_after") = "singularities", py::arg("method") = "auto", py::arg("size") = 0.0,
        py::arg("size_factor") = 1.0, py::arg("threads") = 0, py::arg("budget_s") = 0.0,
        py::arg("fillet_rims") = false, py::arg("hex_size") = 0.0, py::arg("layers") = 0, py::arg("order") = 1,
        py::arg("mesher") = "tetgen", py::arg("refine") = true, py::arg("remesh_thin") = true,
        py::call_guard<py::gil_scoped_release>());
    m.def(
        "run_shape",
        [](const BrepModel& shape, const std::string& stop_after, const std::string& method, double size,
           double size_factor, int threads, double budget_s, bool fillet_rims, double hex_size, int layers, int order,
           const std::string& mesher, bool refine, bool remesh_thin) {
            return run(RunInput::shape(shape), make_options(stop_after, method, size, size_factor, threads, budget_s, fillet_rims,
                                                         HexArgs{hex_size, layers, order, refine}, mesher,
                                                         BlockArgs{remesh_thin}));
        },
        py::arg("shape"), py::arg("stop_after") = "singularities", py::arg("method") = "auto", py::arg("size") = 0.0,
        py::arg("size_factor") = 1.0, py::arg("threads") = 0, py::arg("budget_s") = 0.0,
        py::arg("fillet_rims") = false, py::arg("hex_size") = 0.0, py::arg("layers") = 0, py::arg("order") = 1,
        py::arg("mesher") = "tetgen", py::arg("refine") = true, py::arg("remesh_thin") = true,
        py::call_guard<py::gil_scoped_release>());
    m.def("info_json", &info_json, "`framefix info`: defaults and correction methods, as JSON text");
}

}  // namespace framefix::python
