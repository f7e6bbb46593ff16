#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "framefix/brep/brep_model.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/pipeline/mesh_attempts.h"

namespace py = pybind11;

namespace framefix::python {

void bind_mesh(py::module_& m) {
    py::class_<TetMesh>(m, "TetMesh", "Tet mesh with B-rep tags; arrays are numpy (copies)")
        .def_readonly("points", &TetMesh::points, "#V x 3 float64")
        .def_readonly("tets", &TetMesh::tets, "#T x 4 int32, positively oriented")
        .def_readonly("boundary_faces", &TetMesh::boundary_faces, "#B x 3, outward")
        .def_readonly("face_tags", &TetMesh::face_tags, "#B B-rep face index (1-based)")
        .def_readonly("feature_edges", &TetMesh::feature_edges, "#E x 2 mesh edges on feature curves")
        .def_readonly("edge_tags", &TetMesh::edge_tags, "#E B-rep edge index (1-based)")
        .def_readonly("corner_vertices", &TetMesh::corner_vertices, "mesh vertex of each B-rep vertex")
        .def_readonly("size", &TetMesh::size)
        .def_property_readonly("num_vertices", &TetMesh::num_vertices)
        .def_property_readonly("num_tets", &TetMesh::num_tets)
        .def("__repr__", [](const TetMesh& t) {
            return "<framefix.TetMesh " + std::to_string(t.num_vertices()) + " vertices, " + std::to_string(t.num_tets()) + " tets>";
        });

    py::class_<MeshQuality>(m, "MeshQuality")
        .def_readonly("min_volume", &MeshQuality::min_volume)
        .def_readonly("edge_fraction_in_range", &MeshQuality::edge_fraction_in_range)
        .def_readonly("median_edge", &MeshQuality::median_edge)
        .def_readonly("edges", &MeshQuality::edges);
    m.def("mesh_quality", &mesh_quality, py::arg("mesh"));

    m.def(
        "tetrahedralize",
        [](const BrepModel& shape, double size) {
            MeshOptions o;
            o.size = size > 0 ? size : default_size(shape, o.target_tets);
            const FeatureSet features = classify_features(shape);
            return mesh_brep(shape, features, o).tets;
        },
        py::arg("shape"), py::arg("size") = 0.0, py::call_guard<py::gil_scoped_release>(),
        "Near-uniform tet mesh of the solid at edge length size (0: about 50k tets)");
}

}  // namespace framefix::python
