// hlens.Result, hlens.OneSided and hlens.BatchFailure: a distance report (app/report.h, the
// CLI's JSON) as attributes, with per-triangle arrays.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <hlens/hausdorff.h>
#include <hlens/mesh.h>

#include "json_value.h"
#include "report.h"

namespace hlens::py_bindings {

namespace py = pybind11;

struct OneSided {
    Value report;                  // the CLI's "a_to_b" or "b_to_a" object
    py::array target_max;          // float64 per triangle of the measured mesh
    py::array target_exact;        // bool per triangle: target_max is exact (else an upper bound)
    py::object target_mean, target_rms;  // with stats: float64 per triangle; otherwise None
};

struct Result {
    Value report;                  // the CLI's whole JSON object
    py::object a_to_b, b_to_a;     // OneSided; b_to_a is None when one-sided
};

struct BatchFailure {
    Value report;                  // {"index", "path", "error"}: the CLI's batch error line
};

// Needs the GIL (it makes numpy arrays). With opt.stats, each direction's statistics are in its
// report and its per-triangle mean and RMS in target_mean and target_rms.
Result make_result(const TriangleMesh& A, const TriangleMesh& B, const HausdorffResult& r,
                   const DistanceReportOptions& opt);

void bind_result(py::module_& m);

}  // namespace hlens::py_bindings
