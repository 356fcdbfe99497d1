// The Python module `hlens` (pybind11): load, distance, batch, trace and TargetSolver.
// Bad input raises ValueError with the CLI's message; computations release the GIL and stop on
// Ctrl-C (blocking.h).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <thread>

#include <hlens/mesh_io.h>

#include "batch.h"
#include "blocking.h"
#include "convert.h"
#include "result.h"
#include "trace.h"

namespace py = pybind11;
using namespace hlens;
using namespace hlens::py_bindings;

namespace {

// histogram=: 0 (none) or, with stats, a number of bins as --histogram takes (the CLI's messages).
int check_histogram(bool stats, int histogram) {
    if (histogram < 0 || histogram > kMaxHistogramBins)
        throw py::value_error("histogram must be between 1 and " + std::to_string(kMaxHistogramBins) + ", got " +
                              std::to_string(histogram));
    if (histogram > 0 && !stats) throw py::value_error("histogram needs stats");
    return histogram;
}

// What stats=True computes: surface_stats() per direction, as `hlens-cli distance --stats`.
StatsOptions stats_options(int threads, int histogram, double tolerance) {
    StatsOptions o;
    o.threads = threads;
    o.histogram_bins = histogram;
    o.tolerance = tolerance;
    return o;
}

// job.fraction from the core's progress callbacks (called from worker threads): the distance
// takes [0, split] of the run, the statistics (when asked for) the rest; it only ever grows.
class ProgressSplit {
public:
    ProgressSplit(Job& job, bool one_sided, double split) : job_(job), one_sided_(one_sided), split_(split) {}

    // hausdorff() reports each direction from 0 to 1, a->b first: a fraction falling back well
    // below the last one means b->a began (as the CLI's progress bar reads it).
    void distance(double f) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (f < last_ - 0.5) direction_ = 1;
        last_ = f;
        raise(split_ * (one_sided_ ? f : (direction_ + f) / 2));
    }
    void stats(double f) {
        std::lock_guard<std::mutex> lock(mutex_);
        raise(split_ + (1 - split_) * f);
    }

private:
    void raise(double overall) {
        if (overall > job_.fraction) job_.fraction = overall;
    }
    Job& job_;
    const bool one_sided_;
    const double split_;
    std::mutex mutex_;
    int direction_ = 0;
    double last_ = 0;
};

DistanceReportOptions report_options(bool one_sided, Mode mode, int threads, const py::object& units,
                                     double tolerance) {
    DistanceReportOptions o;
    o.one_sided = one_sided;
    o.mode = mode;
    o.threads = threads > 0 ? threads : (int)std::max(1u, std::thread::hardware_concurrency());
    o.units = units.is_none() ? "" : units.cast<std::string>();
    o.tolerance = tolerance;
    return o;
}

py::tuple load(py::handle path, bool weld) {
    const std::string p = fspath(path);
    LoadOptions lo;
    lo.weld = weld;
    TriangleMesh m;
    run_blocking([&](Job&) { m = load_mesh(p, lo); }, py::none());
    return mesh_to_arrays(m);
}

Result distance(py::handle VA, py::handle FA, py::handle VB, py::handle FB, bool one_sided, const std::string& mode,
                int threads, bool stats, py::object tolerance, int histogram, py::object progress, py::object units) {
    const int bins = check_histogram(stats, histogram);
    const TriangleMesh A = mesh_from_arrays(VA, FA, "A"), B = mesh_from_arrays(VB, FB, "B");
    HausdorffOptions opt;
    opt.mode = parse_mode(mode);
    opt.threads = check_threads(threads, "threads");
    DistanceReportOptions ro = report_options(one_sided, opt.mode, threads, units, parse_tolerance(tolerance));
    HausdorffResult r;
    std::vector<SurfaceStats> st;
    run_blocking(
        [&](Job& job) {
            // The statistics (the full construction of every triangle) take most of the time.
            ProgressSplit split(job, one_sided, stats ? 0.05 : 1.0);
            opt.cancel = &job.cancel;
            opt.progress = [&](double f) { split.distance(f); };
            const IndexedPair pair(A, B, opt.threads);  // for the distance and the statistics
            r = pair.distance(opt, one_sided);
            if (!stats) return;
            StatsOptions so = stats_options(opt.threads, bins, ro.tolerance);
            so.cancel = &job.cancel;
            so.progress = [&](double f) { split.stats(f); };
            st = direction_stats(pair.grid, r, one_sided, so);
        },
        progress);
    if (stats) ro.stats = &st;
    return make_result(A, B, r, ro);
}

// hlens.batch(): an iterator over the pairs as they finish (app/batch.h).
class BatchIterator {
public:
    BatchIterator(TriangleMesh reference, std::vector<std::string> paths, const BatchOptions& bo,
                  DistanceReportOptions ro)
        : reference_(std::make_unique<TriangleMesh>(std::move(reference))), ro_(std::move(ro)) {
        runner_ = std::make_unique<BatchRunner>(*reference_, std::move(paths), bo);
        ro_.threads = runner_->threads_per_pair();
    }

    py::object next() {
        BatchItem item;
        bool got = false;
        while (!got) {
            if (runner_->done()) throw py::stop_iteration();
            try {
                run_blocking([&](Job&) { got = runner_->next(item, std::chrono::milliseconds(100)); }, py::none());
            } catch (py::error_already_set&) {
                runner_->cancel();  // Ctrl-C: the pairs still running stop; later ones are not started
                throw;
            }
        }
        if (!item.ok) {
            BatchFailure f;
            f.report = Value::object()
                           .add("index", Value::integer((long long)item.index))
                           .add("path", Value::string(item.path))
                           .add("error", Value::string(item.error));
            return py::cast(std::move(f));
        }
        DistanceReportOptions ro = ro_;
        if (!item.stats.empty()) ro.stats = &item.stats;
        Result r = make_result(*reference_, item.mesh, item.result, ro);
        r.report.fields.insert(r.report.fields.begin(), {"index", Value::integer((long long)item.index)});
        return py::cast(std::move(r));
    }

private:
    std::unique_ptr<TriangleMesh> reference_;   // declared first: the runner refers to it
    DistanceReportOptions ro_;
    std::unique_ptr<BatchRunner> runner_;
};

BatchIterator batch(py::handle reference, py::iterable paths, bool one_sided, const std::string& mode, int threads,
                    int jobs, bool stats, py::object tolerance, int histogram, bool weld, py::object units) {
    BatchOptions bo;
    bo.stats = stats;
    bo.stats_options = stats_options(0, check_histogram(stats, histogram), parse_tolerance(tolerance));
    bo.mode = parse_mode(mode);
    bo.threads = check_threads(threads, "threads");
    if (jobs < 1 || jobs > 4096) throw py::value_error("jobs must be between 1 and 4096, got " + std::to_string(jobs));
    bo.jobs = jobs;
    bo.one_sided = one_sided;
    bo.load.weld = weld;
    std::vector<std::string> files;
    for (py::handle p : paths) files.push_back(fspath(p));
    const std::string ref_path = fspath(reference);
    TriangleMesh ref;
    run_blocking([&](Job&) { ref = load_mesh(ref_path, bo.load); }, py::none());
    return BatchIterator(std::move(ref), std::move(files), bo,
                         report_options(one_sided, bo.mode, threads, units, parse_tolerance(tolerance)));
}

}  // namespace

PYBIND11_MODULE(hlens, m) {
    m.doc() =
        "Hausdorff Lens: the exact Hausdorff distance between triangle meshes (Straub 2007).\n\n"
        "load() reads a mesh file into numpy arrays; distance() compares two meshes given as arrays;\n"
        "batch() compares one reference file with many; trace() and TargetSolver show the construction\n"
        "for one triangle. Results carry the same fields and numbers as hlens-cli's JSON.";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const MeshError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    bind_result(m);

    m.def("load", &load, py::arg("path"), py::arg("weld") = true,
          "load(path, weld=True) -> (V, F)\n\n"
          "Reads .obj .ply .stl .off .gltf .glb as hlens-cli does: V is float64 (n, 3), F int64 (m, 3).\n"
          "weld merges vertices with identical coordinates. Raises ValueError with the CLI's message\n"
          "(\"<path>: ...\") for a missing, unreadable or malformed file.");

    m.def("distance", &distance, py::arg("VA"), py::arg("FA"), py::arg("VB"), py::arg("FB"), py::kw_only(),
          py::arg("one_sided") = false, py::arg("mode") = "fast", py::arg("threads") = 0, py::arg("stats") = false,
          py::arg("tolerance") = py::none(), py::arg("histogram") = 0, py::arg("progress") = py::none(),
          py::arg("units") = py::none(),
          "distance(VA, FA, VB, FB, *, one_sided=False, mode='fast', threads=0, stats=False, tolerance=None,\n"
          "         histogram=0, progress=None, units=None) -> Result\n\n"
          "The exact Hausdorff distance between mesh A (vertices VA (n, 3), triangles FA (m, 3)) and mesh B:\n"
          "h(A,B), h(B,A) and their maximum, each with a certified interval and witness points, as\n"
          "`hlens-cli distance --json` gives them (Result.to_dict() has the same keys and numbers).\n"
          "Vertices: any real or integer dtype; triangles: any integer dtype (0-based indices); C or\n"
          "Fortran order, or nested lists. Bad input (shape, index out of range, NaN, no triangles)\n"
          "raises ValueError (messages start with 'A: ' or 'B: ').\n\n"
          "one_sided: h(A,B) only. mode: 'fast' or 'paper' (same result). threads: 0 = all cores.\n"
          "tolerance: adds Result.exceeds (the distance > tolerance). units: a label passed through.\n"
          "stats: the exact surface statistics of each direction, as `hlens-cli distance --stats`: area,\n"
          "mean, rms, percentiles ('50', '90', '95', '99'), stats_error, stats_seconds (attributes of\n"
          "OneSided and fields of to_dict()), and per triangle OneSided.target_mean and target_rms (numpy).\n"
          "With a tolerance also area_above and fraction_above (where d > tolerance). Slow: the full\n"
          "construction of every triangle (paper mode's time at least).\n"
          "histogram: with stats, N > 0 equal bins from 0 to each direction's distance (histogram:\n"
          "{'edges': N+1, 'area': N}); 0: none.\n"
          "progress: called with a fraction in [0, 1] from this thread while it runs.\n"
          "The GIL is released while it runs; Ctrl-C stops it with KeyboardInterrupt.");

    py::class_<BatchIterator>(m, "BatchIterator", "The results of hlens.batch(), in the order the pairs finish.")
        .def("__iter__", [](BatchIterator& it) -> BatchIterator& { return it; })
        .def("__next__", &BatchIterator::next);
    m.def("batch", &batch, py::arg("reference"), py::arg("paths"), py::kw_only(), py::arg("one_sided") = false,
          py::arg("mode") = "fast", py::arg("threads") = 0, py::arg("jobs") = 1, py::arg("stats") = false,
          py::arg("tolerance") = py::none(), py::arg("histogram") = 0, py::arg("weld") = true,
          py::arg("units") = py::none(),
          "batch(reference, paths, *, one_sided=False, mode='fast', threads=0, jobs=1, stats=False,\n"
          "      tolerance=None, histogram=0, weld=True, units=None) -> iterator of Result | BatchFailure\n\n"
          "Compares the reference file (as A) with each file of `paths` (as B), like `hlens-cli batch`:\n"
          "the reference is read once, `jobs` pairs run at a time (threads is per pair; 0: all cores\n"
          "divided among the jobs), and each item comes out as its pair finishes: a Result (its\n"
          "`index` and `path` say which file) or, for a file that cannot be read, a BatchFailure with\n"
          "its error; the other files go on. A bad reference raises ValueError at once.\n"
          "stats, histogram, tolerance: as for distance(); each Result equals that pair's line of\n"
          "`hlens-cli batch --json` with the same options.");

    bind_trace(m);
}
