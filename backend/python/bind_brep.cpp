#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "framefix/brep/brep_model.h"
#include "framefix/core/error.h"
#include "framefix/mesh/size_model.h"

namespace py = pybind11;

namespace framefix::python {

void bind_errors(py::module_& m) {
    static py::exception<Error> error(m, "Error");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Error& e) {
            error(e.what());
        }
    });
}

void bind_brep(py::module_& m) {
    py::class_<BrepModel>(m, "Shape", "One CAD solid, immutable")
        .def_readonly("path", &BrepModel::path)
        .def_readonly("kind", &BrepModel::kind)
        .def_readonly("num_faces", &BrepModel::num_faces)
        .def_readonly("num_edges", &BrepModel::num_edges)
        .def_readonly("num_vertices", &BrepModel::num_vertices)
        .def_readonly("bbox_min", &BrepModel::bbox_min)
        .def_readonly("bbox_max", &BrepModel::bbox_max)
        .def_readonly("volume", &BrepModel::volume)
        .def("__repr__", [](const BrepModel& s) {
            return "<framefix.Shape " + std::to_string(s.num_faces) + " faces, " + std::to_string(s.num_edges) + " edges>";
        });

    py::class_<EdgeFeature>(m, "EdgeFeature", "Dihedral-angle class of one B-rep edge")
        .def_readonly("edge", &EdgeFeature::edge, "B-rep edge index, 1-based (FreeCAD Edge<i>)")
        .def_readonly("valence", &EdgeFeature::valence, "0 not a feature, 1 convex, 2 imprint, 3 concave, 4 slit")
        .def_readonly("angle_min_deg", &EdgeFeature::angle_min_deg)
        .def_readonly("angle_max_deg", &EdgeFeature::angle_max_deg)
        .def_readonly("length", &EdgeFeature::length)
        .def_readonly("valence_varies", &EdgeFeature::valence_varies)
        .def_readonly("reason", &EdgeFeature::reason)
        .def("__repr__", [](const EdgeFeature& e) {
            return "<EdgeFeature Edge" + std::to_string(e.edge) + " valence " + std::to_string(e.valence) + ">";
        });

    m.def("load_shape", &load_shape, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "Load exactly one solid from a .step/.stp/.brep/.iges/.igs file");
    m.def("load_brep_string", &load_brep_string, py::arg("brep"), py::call_guard<py::gil_scoped_release>(),
          "Load a solid from a BREP string (FreeCAD: shape.exportBrepToString())");
    m.def("to_brep_string", &to_brep_string, py::arg("shape"));
    m.def("classify_features", [](const BrepModel& s) { return classify_features(s).edges; }, py::arg("shape"),
          py::call_guard<py::gil_scoped_release>(), "One EdgeFeature per B-rep edge");
    m.def("default_size", &default_size, py::arg("shape"), py::arg("target_tets") = kDefaultTargetTets,
          "Edge length giving about target_tets tets");
}

}  // namespace framefix::python
