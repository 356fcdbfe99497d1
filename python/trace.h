// hlens.trace() and hlens.TargetSolver: the construction for one target triangle, event by event,
// with its domain mesh for plotting.
#pragma once
#include <pybind11/pybind11.h>

namespace hlens::py_bindings {

void bind_trace(pybind11::module_& m);

}  // namespace hlens::py_bindings
