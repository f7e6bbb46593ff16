#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "framefix/pipeline/block_stage.h"
#include "framefix/pipeline/correction.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/report.h"

namespace py = pybind11;

namespace framefix::python {
namespace {

AnalysisOptions make_options(double size, double size_factor, int threads) {
    AnalysisOptions o;
    o.mesh.size = size;
    o.size_factor = size_factor;
    o.threads = threads;
    return o;
}

}  // namespace

void bind_pipeline(py::module_& m) {
    py::class_<AnalysisResult>(m, "Analysis", "Every intermediate of a run, plus its report")
        .def_readonly("input_path", &AnalysisResult::input_path)
        .def_readonly("input_kind", &AnalysisResult::input_kind)
        .def_readonly("mesh", &AnalysisResult::mesh)
        .def_property_readonly("features", [](const AnalysisResult& r) { return r.features.edges; })
        .def_property_readonly("field", [](const AnalysisResult& r) -> py::object {
            return r.has_field ? py::cast(r.field) : py::none();
        })
        .def_property_readonly("singularities", [](const AnalysisResult& r) -> py::object {
            return r.has_singularities ? py::cast(r.singularities) : py::none();
        })
        .def_property_readonly("report_json", [](const AnalysisResult& r) { return report_json(r); })
        .def("write_outputs", [](const AnalysisResult& r, const std::string& dir) { return write_outputs(r, dir); },
             py::arg("folder"))
        .def_property_readonly("human_summary", [](const AnalysisResult& r) { return human_summary(r); });

    // A corrected analysis: the corrected result plus what the correction did.
    struct Corrected {
        AnalysisResult result;
        Correction correction;
    };
    py::class_<Corrected>(m, "Corrected", "A corrected analysis (result = after, correction = what changed)")
        .def_readonly("result", &Corrected::result)
        .def_property_readonly("method", [](const Corrected& c) { return c.correction.method; })
        .def_property_readonly("snapped_paths", [](const Corrected& c) {
            std::vector<Points> out;
            for (const auto& p : c.correction.snap.paths) out.push_back(p.points);
            return out;
        })
        .def_property_readonly("rotated_fraction", [](const Corrected& c) { return c.correction.rotated_fraction; })
        .def_property_readonly("report_json", [](const Corrected& c) { return report_json(c.result, &c.correction); })
        .def("write_outputs",
             [](const Corrected& c, const std::string& dir) { return write_outputs(c.result, dir, &c.correction); },
             py::arg("folder"))
        .def_property_readonly("human_summary", [](const Corrected& c) { return human_summary(c.result, &c.correction); });
    // Analysis, correction and blocks of one part.
    struct BlockRun {
        AnalysisResult result;
        Correction correction;
        bool corrected = false;
        BlockDecomposition blocks;
    };
    py::class_<BlockRun>(m, "BlockRun", "A block decomposition (result = analysed and corrected part)")
        .def_readonly("result", &BlockRun::result)
        .def_property_readonly("tet_block", [](const BlockRun& b) { return b.blocks.tet_block; }, "#T block id per tet")
        .def_property_readonly("count", [](const BlockRun& b) { return b.blocks.count; })
        .def_property_readonly("valid", [](const BlockRun& b) { return b.blocks.valid; })
        .def_property_readonly("report_json", [](const BlockRun& b) {
            return report_json(b.result, b.corrected ? &b.correction : nullptr, &b.blocks);
        })
        .def("write_outputs",
             [](const BlockRun& b, const std::string& dir) {
                 return write_outputs(b.result, dir, b.corrected ? &b.correction : nullptr, &b.blocks);
             },
             py::arg("folder"))
        .def_property_readonly("human_summary", [](const BlockRun& b) {
            return human_summary(b.result, b.corrected ? &b.correction : nullptr, &b.blocks);
        });
    m.def(
        "blocks_file",
        [](const std::string& path, const std::string& method, double size, double size_factor, int threads) {
            const auto o = make_options(size, size_factor, threads);
            BlockRun b{analyze(path, o), {}, method != "none", {}};
            if (b.corrected) {
                CorrectionOptions co;
                co.method = method;
                b.correction = correct(b.result, co, o);
            }
            b.blocks = decompose(b.result, b.corrected ? &b.correction : nullptr, o);
            return b;
        },
        py::arg("path"), py::arg("method") = "snap", py::arg("size") = 0.0, py::arg("size_factor") = 1.0,
        py::arg("threads") = 0, py::call_guard<py::gil_scoped_release>());
    m.def(
        "correct_file",
        [](const std::string& path, const std::string& method, double size, double size_factor, int threads) {
            check_correction_method(method);
            const auto o = make_options(size, size_factor, threads);
            Corrected c{analyze(path, o), {}};
            CorrectionOptions co;
            co.method = method;
            c.correction = correct(c.result, co, o);
            return c;
        },
        py::arg("path"), py::arg("method") = "snap", py::arg("size") = 0.0, py::arg("size_factor") = 1.0,
        py::arg("threads") = 0, py::call_guard<py::gil_scoped_release>());

    m.def(
        "mesh_part",
        [](const std::string& path, double size, double size_factor, int threads) {
            return mesh_part(path, make_options(size, size_factor, threads));
        },
        py::arg("path"), py::arg("size") = 0.0, py::arg("size_factor") = 1.0, py::arg("threads") = 0,
        py::call_guard<py::gil_scoped_release>());
    m.def(
        "analyze_file",
        [](const std::string& path, double size, double size_factor, int threads) {
            return analyze(path, make_options(size, size_factor, threads));
        },
        py::arg("path"), py::arg("size") = 0.0, py::arg("size_factor") = 1.0, py::arg("threads") = 0,
        py::call_guard<py::gil_scoped_release>());
    m.def(
        "analyze_shape",
        [](const BrepModel& shape, double size, double size_factor, int threads) {
            const auto o = make_options(size, size_factor, threads);
            AnalysisResult r = mesh_model(shape, o);
            analyze_mesh(r, o);
            return r;
        },
        py::arg("shape"), py::arg("size") = 0.0, py::arg("size_factor") = 1.0, py::arg("threads") = 0,
        py::call_guard<py::gil_scoped_release>());
}

}  // namespace framefix::python
