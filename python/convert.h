// Conversions between Python objects and the core's types for the module `hlens`.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include <hlens/hausdorff.h>
#include <hlens/mesh.h>

#include "json_value.h"

namespace hlens::py_bindings {

namespace py = pybind11;

// Vertices (n, 3) of any real or integer dtype and triangles (m, 3) of any integer dtype, in
// either memory order, or nested lists: a mesh named `name` ("A" or "B"), checked as make_mesh
// checks it. Bad input throws MeshError ("<name>: ..."), which the module raises as ValueError.
TriangleMesh mesh_from_arrays(py::handle vertices, py::handle triangles, const std::string& name);

// The mesh as numpy arrays: float64 (n, 3) and int64 (m, 3).
py::tuple mesh_to_arrays(const TriangleMesh& m);

// A report value as plain Python data (dict, list, int, float, str, bool, None); numbers that are
// not finite become None, as the CLI writes null.
py::object to_python(const Value& v);

Mode parse_mode(const std::string& mode);
int check_threads(int threads, const char* what);
// None -> -1 (no tolerance); otherwise a finite number >= 0 (ValueError with the CLI's message).
double parse_tolerance(const py::object& tolerance);
// str or os.PathLike -> str.
std::string fspath(py::handle path);

}  // namespace hlens::py_bindings
