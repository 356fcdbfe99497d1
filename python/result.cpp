#include "result.h"

#include <cstdint>
#include <utility>

#include "convert.h"

namespace hlens::py_bindings {

namespace {

// Per triangle of `s`: f(its TriangleStats), as a float64 array; None without statistics.
template <class F>
py::object per_triangle(const SurfaceStats* s, F f) {
    if (!s) return py::none();
    py::array_t<double> a((py::ssize_t)s->triangles.size());
    for (size_t i = 0; i < s->triangles.size(); ++i) a.mutable_at(i) = f(s->triangles[i]);
    return std::move(a);
}

// One direction; `stats` is its statistics, or null.
OneSided make_one_sided(const OneSidedResult& r, const Value& report, const SurfaceStats* stats) {
    OneSided o;
    o.report = report;
    o.target_max = py::array_t<double>((py::ssize_t)r.target_max.size(), r.target_max.data());
    py::array_t<bool> exact((py::ssize_t)r.target_exact.size());
    for (size_t i = 0; i < r.target_exact.size(); ++i) exact.mutable_at(i) = r.target_exact[i] != 0;
    o.target_exact = exact;
    o.target_mean = per_triangle(stats, [](const TriangleStats& t) { return t.mean(); });
    o.target_rms = per_triangle(stats, [](const TriangleStats& t) { return t.rms(); });
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
    auto stats = [&](size_t side) { return opt.stats && side < opt.stats->size() ? &(*opt.stats)[side] : nullptr; };
    res.a_to_b = py::cast(make_one_sided(r.a_to_b, *find_field(res.report, "a_to_b"), stats(0)));
    res.b_to_a = opt.one_sided ? py::none()
                               : py::cast(make_one_sided(r.b_to_a, *find_field(res.report, "b_to_a"), stats(1)));
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
        // stats=True (None otherwise), as `hlens-cli distance --stats`
        {"area", "stats: area of the measured mesh (sliver triangles left out)"},
        {"mean", "stats: area-weighted mean distance"},
        {"rms", "stats: root mean square distance"},
        {"percentiles", "stats: {'50', '90', '95', '99'}: the distance below which that share of the area lies"},
        {"histogram", "stats with histogram=N: {'edges': N+1 distances, 'area': N areas}"},
        {"area_above", "stats with a tolerance: the area farther than the tolerance"},
        {"fraction_above", "stats with a tolerance: area_above / area"},
        {"stats_error", "stats: {'area', 'integral_d2', 'integral_d_estimate', 'percentile'}: error bounds"},
        {"stats_seconds", "stats: {'first_pass', 'percentiles', 'percentile_passes', 'rerun_targets'}"},
        {"sliver_triangles", "stats: triangles too thin for a domain mesh, left out (None if there are none)"},
        {"sliver_area", "stats: their area (None if there are none)"},
    });
    one.def_readonly("target_max", &OneSided::target_max,
                     "numpy float64 array: per triangle of the measured mesh, its largest distance to the other "
                     "mesh; exact where target_exact, otherwise an upper bound below the result (fast mode)");
    one.def_readonly("target_exact", &OneSided::target_exact, "numpy bool array: target_max is exact");
    one.def_readonly("target_mean", &OneSided::target_mean,
                     "stats: numpy float64 array, per triangle of the measured mesh its mean distance to the other "
                     "mesh (0 for a sliver triangle); None without stats");
    one.def_readonly("target_rms", &OneSided::target_rms,
                     "stats: numpy float64 array, per triangle its RMS distance (0 for a sliver); None without stats");
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
