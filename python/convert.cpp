#include "convert.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include <hlens/mesh_io.h>

namespace hlens::py_bindings {

namespace {

std::string shape_text(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array as_array(py::handle obj, const std::string& name, const char* what) {
    py::array a;
    try {
        a = py::module_::import("numpy").attr("asarray")(obj);
    } catch (const py::error_already_set&) {
        throw MeshError(name + ": " + what + " cannot be read as an array");
    }
    return a;
}

// (k, 3), or empty (which make_mesh reports as "no triangles" for the triangles).
void check_shape(const py::array& a, const std::string& name, const char* what) {
    if (a.size() == 0 && a.ndim() <= 2) return;
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw MeshError(name + ": " + what + " must have shape (n, 3), got shape " + shape_text(a));
}

std::vector<Vec3> read_vertices(py::handle obj, const std::string& name) {
    py::array a = as_array(obj, name, "vertices");
    const char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw MeshError(name + ": vertices must be real numbers, got dtype " + std::string(py::str(a.dtype())));
    check_shape(a, name, "vertices");
    // float16/32 and integers convert to double exactly; float128 rounds to the nearest double.
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<Vec3> v(a.size() / 3);
    const double* p = d.data();
    for (size_t i = 0; i < v.size(); ++i) v[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    return v;
}

// Indices are checked here, before they are narrowed to 32 bits, with make_mesh's message.
template <class Int>
std::vector<Tri> read_indices(const py::array& a, size_t vertices, const std::string& name) {
    auto d = py::array_t<Int, py::array::c_style | py::array::forcecast>::ensure(a);
    const Int* p = d.data();
    std::vector<Tri> tris(a.size() / 3);
    for (size_t t = 0; t < tris.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Int i = p[3 * t + k];
            bool negative = false;
            if constexpr (std::is_signed_v<Int>) negative = i < 0;
            if (negative || (uint64_t)i >= vertices)
                throw MeshError(name + ": triangle " + std::to_string(t) + ": vertex index " + std::to_string(i) +
                                " out of range (" + std::to_string(vertices) + " vertices)");
            tris[t][k] = (uint32_t)i;
        }
    return tris;
}

std::vector<Tri> read_triangles(py::handle obj, size_t vertices, const std::string& name) {
    py::array a = as_array(obj, name, "triangles");
    check_shape(a, name, "triangles");
    if (a.size() == 0) return {};
    const char kind = a.dtype().kind();
    if (kind == 'i') return read_indices<int64_t>(a, vertices, name);
    if (kind == 'u') return read_indices<uint64_t>(a, vertices, name);
    throw MeshError(name + ": triangles must be integer vertex indices, got dtype " + std::string(py::str(a.dtype())));
}

}  // namespace

TriangleMesh mesh_from_arrays(py::handle vertices, py::handle triangles, const std::string& name) {
    std::vector<Vec3> v = read_vertices(vertices, name);
    std::vector<Tri> t = read_triangles(triangles, v.size(), name);
    return make_mesh(std::move(v), std::move(t), name);
}

py::tuple mesh_to_arrays(const TriangleMesh& m) {
    py::array_t<double> V({(py::ssize_t)m.positions.size(), (py::ssize_t)3});
    py::array_t<int64_t> F({(py::ssize_t)m.triangles.size(), (py::ssize_t)3});
    auto v = V.mutable_unchecked<2>();
    for (size_t i = 0; i < m.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) v(i, k) = m.positions[i][k];
    auto f = F.mutable_unchecked<2>();
    for (size_t i = 0; i < m.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) f(i, k) = m.triangles[i][k];
    return py::make_tuple(V, F);
}

py::object to_python(const Value& v) {
    switch (v.kind) {
        case Value::Null: return py::none();
        case Value::Bool: return py::bool_(v.b);
        case Value::Int: return py::int_(v.i);
        case Value::Num: return std::isfinite(v.d) ? py::object(py::float_(v.d)) : py::object(py::none());
        case Value::Str: return py::str(v.s);
        case Value::Arr: {
            py::list l;
            for (const Value& x : v.items) l.append(to_python(x));
            return std::move(l);
        }
        case Value::Obj: {
            py::dict d;
            for (const auto& [k, x] : v.fields) d[py::str(k)] = to_python(x);
            return std::move(d);
        }
    }
    return py::none();
}

Mode parse_mode(const std::string& mode) {
    if (mode == "fast") return Mode::Fast;
    if (mode == "paper") return Mode::Paper;
    throw py::value_error("unknown mode '" + mode + "' (paper or fast)");
}

int check_threads(int threads, const char* what) {
    if (threads < 0 || threads > 4096)
        throw py::value_error(std::string(what) + " must be between 0 (all cores) and 4096, got " + std::to_string(threads));
    return threads;
}

double parse_tolerance(const py::object& tolerance) {
    if (tolerance.is_none()) return -1;
    // The CLI's messages for --tolerance, without the dashes.
    const std::string text = py::str(tolerance);
    double t = NAN;
    try {
        t = tolerance.cast<double>();
    } catch (const py::cast_error&) {
    }
    if (!std::isfinite(t)) throw py::value_error("tolerance needs a number, got '" + text + "'");
    if (t < 0) throw py::value_error("tolerance must be >= 0, got " + format_double(t, 17));
    return t;
}

std::string fspath(py::handle path) {
    return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

}  // namespace hlens::py_bindings
