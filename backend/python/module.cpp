// framefix._core: the private extension under the pure-Python package `framefix`.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(_core, m) {
    m.doc() = "FrameFix backend (private; use the framefix package)";
    framefix::python::bind_errors(m);
    framefix::python::bind_brep(m);
    framefix::python::bind_mesh(m);
    framefix::python::bind_field(m);
    framefix::python::bind_pipeline(m);
}
