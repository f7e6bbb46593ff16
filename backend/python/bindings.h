#pragma once
#include <pybind11/pybind11.h>

namespace framefix {
struct SingularitySummary;
}

namespace framefix::python {

// The summary of a singularity graph as report.json writes it.
pybind11::dict summary_dict(const SingularitySummary& summary);

void bind_errors(pybind11::module_& m);
void bind_brep(pybind11::module_& m);
void bind_mesh(pybind11::module_& m);
void bind_field(pybind11::module_& m);
void bind_pipeline(pybind11::module_& m);

}  // namespace framefix::python
