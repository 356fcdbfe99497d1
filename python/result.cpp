#include "result.h"

#include <cstdint>
#include <utility>

#include "convert.h"

namespace hlens::py_bindings {

namespace {

OneSided make_one_sided(const OneSidedResult& r, const Value& report) {
    OneSided o;
    o.report = report;
    o.target_max = py::array_t<double>((py::ssize_t)r.target_max.size(), r.target_max.data());
    py::array_t<bool> exact((py::ssize_t)r.target_exact.size());
    for (size_t i = 0; i < r.target_exact.size(); ++i) exact.mutable_at(i) = r.target_exact[i] != 0;
    o.target_exact = exact;
    return o;
}

// Read-only attributes that read the report's fields (None when absent, as for "units").
template <class T>
void report_fields(py::class_<T>& c, std::initializer_list<std::pair<const char*, const char*>> fields) {
    for (const auto& [name, doc] : fields) {
        std::string key = name;
        c.def_property_readonly(
            name, [key](const T& o) { const Value* v = find_field(o.report, key); return v ? to_python(*v) : py::none(); },
            doc);
    }
}

template <class T>
void to_dict(py::class_<T>& c, const char* doc) {
    c.def("to_dict", [](const T& o) { return to_python(o.report); }, doc);
}

}  // namespace

Result make_result(const TriangleMesh& A, const TriangleMesh& B, const HausdorffResult& r,
                   const DistanceReportOptions& opt) {
    Result res;
    res.report = distance_json(A, B, r, opt);
    res.a_to_b = py::cast(make_one_sided(r.a_to_b, *find_field(res.report, "a_to_b")));
    res.b_to_a = opt.one_sided ? py::none() : py::cast(make_one_sided(r.b_to_a, *find_field(res.report, "b_to_a")));
    return res;
}

void bind_result(py::module_& m) {
    py::class_<OneSided> one(m, "OneSided", "One direction of a comparison, h(A,B) (a_to_b) or h(B,A) (b_to_a).");
    report_fields(one, {
        {"distance", "the one-sided distance h(from, to)"},
        {"relative", "distance / diagonal (of the union of both meshes' bounding boxes); None if that is 0"},
        {"lower", "certified lower bound: lower <= h"},
        {"upper", "certified upper bound: h <= upper"},
        {"target", "witness triangle of the measured mesh (where h is attained)"},
        {"from_point", "witness point [x, y, z] on the measured mesh"},
        {"to_point", "its nearest point on the other mesh"},
        {"exact_targets", "triangles whose maximum was computed exactly"},
        {"exact_solves", "exact constructions run (fast mode: pieces and whole triangles)"},
        {"seconds", "time of this direction"},
    });
    one.def_readonly("target_max", &OneSided::target_max,
                     "numpy float64 array: per triangle of the measured mesh, its largest distance to the other "
                     "mesh; exact where target_exact, otherwise an upper bound below the result (fast mode)");
    one.def_readonly("target_exact", &OneSided::target_exact, "numpy bool array: target_max is exact");
    to_dict(one, "The same fields as the CLI's JSON object for this direction (without the arrays).");
    one.def("__repr__", [](const OneSided& o) { return "OneSided(" + to_json(o.report) + ")"; });

    py::class_<Result> res(m, "Result",
                           "The result of hlens.distance(): the content of `hlens-cli distance --json` as "
                           "attributes, and per-triangle maxima as numpy arrays.");
    report_fields(res, {
        {"hausdorff", "the Hausdorff distance max(h(A,B), h(B,A)) (None when one-sided)"},
        {"relative", "hausdorff / diagonal (None when one-sided)"},
        {"diagonal", "diagonal of the bounding box of both meshes together"},
        {"a", "{'path', 'vertices', 'triangles'} of A (vertices: those used by triangles)"},
        {"b", "the same for B"},
        {"seconds", "total time"},
        {"mode", "'fast' or 'paper'"},
        {"threads", "worker threads used"},
        {"units", "the unit label given, or None"},
        {"tolerance", "the tolerance given, or None"},
        {"exceeds", "with a tolerance: whether the distance (h(A,B) when one-sided) exceeds it"},
        {"index", "batch only: position of the file in the list"},
    });
    res.def_readonly("a_to_b", &Result::a_to_b, "OneSided: h(A,B)");
    res.def_readonly("b_to_a", &Result::b_to_a, "OneSided: h(B,A), or None when one-sided");
    res.def_property_readonly("ok", [](const Result&) { return true; }, "True (a BatchFailure has False)");
    res.def_property_readonly(
        "path", [](const Result& r) { return to_python(*find_field(*find_field(r.report, "b"), "path")); },
        "B's path ('' for arrays): in a batch, the file compared");
    to_dict(res, "A dict with the same keys and numbers as `hlens-cli distance --json` (a batch result: as one line "
                 "of `hlens-cli batch --json`).");
    res.def("__repr__", [](const Result& r) { return "Result(" + to_json(r.report) + ")"; });

    py::class_<BatchFailure> fail(m, "BatchFailure", "A file of hlens.batch() that could not be read or compared.");
    report_fields(fail, {
        {"index", "position of the file in the list"},
        {"path", "the file"},
        {"error", "the message, as hlens-cli prints it"},
    });
    fail.def_property_readonly("ok", [](const BatchFailure&) { return false; }, "False");
    to_dict(fail, "{'index', 'path', 'error'}: the line `hlens-cli batch --json` prints for this file.");
    fail.def("__repr__", [](const BatchFailure& f) { return "BatchFailure(" + to_json(f.report) + ")"; });
}

}  // namespace hlens::py_bindings
