#pragma once
#include <pybind11/pybind11.h>

namespace framefix::python {

void bind_errors(pybind11::module_& m);
void bind_brep(pybind11::module_& m);
void bind_mesh(pybind11::module_& m);
void bind_field(pybind11::module_& m);
void bind_pipeline(pybind11::module_& m);

}  // namespace framefix::python
