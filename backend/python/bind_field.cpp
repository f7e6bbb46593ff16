#include <optional>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "framefix/core/error.h"
#include "framefix/frame_field/frame_field.h"
#include "framefix/singularities/singularity_graph.h"

namespace py = pybind11;

namespace framefix::python {
namespace {

FeatureSet feature_set(const std::vector<EdgeFeature>& edges) {
    FeatureSet f;
    f.edges = edges;
    return f;
}

}  // namespace

py::dict summary_dict(const SingularitySummary& s) {
    py::dict d;
    d["curves"] = s.curves;
    d["valence3"] = s.valence3;
    d["valence5"] = s.valence5;
    d["curves_3_5"] = s.curves_3_5;
    d["nodes"] = s.nodes;
    d["invalid_nodes"] = s.invalid_nodes;
    d["meshable"] = s.meshable;
    return d;
}

void bind_field(py::module_& m) {
    py::class_<FrameField>(m, "FrameField", "One frame per mesh vertex")
        .def_readonly("coefficients", &FrameField::coefficients, "#V x 9 SH band-4 coefficients")
        .def_readonly("axes", &FrameField::axes, "#V x 9: axes a1, a2, a3 per vertex")
        .def_readonly("distance", &FrameField::distance, "#V distance to the frame manifold")
        .def_property_readonly("constraint_kind",
                               [](const FrameField& f) {
                                   Eigen::VectorXi k(int(f.kind.size()));
                                   for (size_t i = 0; i < f.kind.size(); ++i) k(int(i)) = int(f.kind[i]);
                                   return k;
                               },
                               "#V: 0 free, 1 normal-aligned, 2 fixed")
        .def_readonly("energy", &FrameField::energy)
        .def_readonly("initial_energy", &FrameField::initial_energy)
        .def_readonly("energy_history", &FrameField::energy_history)
        .def_readonly("change_history", &FrameField::change_history, "|q_k - q_k-1|_M / |q_k|_M per MBO iteration")
        .def_readonly("iterations", &FrameField::iterations)
        .def_readonly("floor_iteration", &FrameField::floor_iteration)
        .def_readonly("iteration_cap", &FrameField::iteration_cap)
        .def_readonly("converged", &FrameField::converged)
        .def_readonly("extrapolations", &FrameField::extrapolations)
        .def_readonly("solver", &FrameField::solver);

    m.def(
        "solve_frame_field",
        [](const TetMesh& mesh, const std::vector<EdgeFeature>& features, std::optional<int> max_iterations,
           int threads, bool extrapolate, int large_mesh_vertices) {
            const TetTopology topo = build_topology(mesh);
            const Constraints c = boundary_constraints(mesh, feature_set(features));
            FieldOptions o;
            if (max_iterations) {  // an explicit cap is a hard cap, also on large meshes
                o.max_iterations = *max_iterations;
                o.floor_iterations = 0;
            }
            o.threads = threads;
            o.extrapolate = extrapolate;
            o.large_mesh_vertices = large_mesh_vertices;
            return solve_frame_field(mesh, topo, c, o);
        },
        py::arg("mesh"), py::arg("features"), py::arg("max_iterations") = py::none(), py::arg("threads") = 0,
        py::arg("extrapolate") = false, py::arg("large_mesh_vertices") = FieldOptions().large_mesh_vertices,
        py::call_guard<py::gil_scoped_release>(), "Boundary-aligned smooth frame field (linear init + MBO)");

    py::class_<SingularCurve>(m, "SingularCurve")
        .def_readonly("id", &SingularCurve::id)
        .def_property_readonly("kind", [](const SingularCurve& c) { return std::string(to_string(c.kind)); })
        .def_readonly("points", &SingularCurve::points, "polyline, #P x 3")
        .def_readonly("faces", &SingularCurve::faces)
        .def_readonly("valences", &SingularCurve::valences)
        .def_readonly("length", &SingularCurve::length)
        .def_readonly("closed", &SingularCurve::closed)
        .def_readonly("stable_direction", &SingularCurve::stable_direction)
        .def_property_readonly("ends", [](const SingularCurve& c) { return std::make_pair(c.ends[0], c.ends[1]); })
        .def("__repr__", [](const SingularCurve& c) {
            return "<SingularCurve " + std::to_string(c.id) + " " + to_string(c.kind) + ">";
        });
    py::class_<SingularNode>(m, "SingularNode")
        .def_readonly("id", &SingularNode::id)
        .def_readonly("position", &SingularNode::position)
        .def_readonly("boundary", &SingularNode::boundary)
        .def_readonly("n3", &SingularNode::n3)
        .def_readonly("n5", &SingularNode::n5)
        .def_readonly("valid", &SingularNode::valid)
        .def_readonly("crossing", &SingularNode::crossing);
    py::class_<SingularityGraph>(m, "SingularityGraph")
        .def_readonly("curves", &SingularityGraph::curves)
        .def_readonly("nodes", &SingularityGraph::nodes)
        .def_readonly("face_valence", &SingularityGraph::face_valence)
        .def_property_readonly("summary", [](const SingularityGraph& g) { return summary_dict(g.summary); });

    m.def(
        "extract_singularities",
        [](const TetMesh& mesh, const FrameField& field, const std::string& holonomy, int threads, bool along, bool surface_ends) {
            SingularityOptions o;
            o.surface_end_labels = surface_ends;
            o.labels_along_curves = along;
            if (holonomy == "edges") o.holonomy = Holonomy::Edges;
            else if (holonomy != "triangles")
                throw Error("singularities", "holonomy is '" + holonomy + "'; use 'triangles' or 'edges'");
            o.threads = threads;
            return extract_singularities(mesh, build_topology(mesh), field, o);
        },
        py::arg("mesh"), py::arg("field"), py::arg("holonomy") = "triangles", py::arg("threads") = 0,
        py::arg("labels_along_curves") = true, py::arg("surface_end_labels") = true,
        py::call_guard<py::gil_scoped_release>(),
        "Singular curves, nodes and 3-5 curves of a frame field; holonomy 'triangles' (default) or 'edges'");
}

}  // namespace framefix::python
