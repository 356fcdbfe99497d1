// The JSON reports shared by hlens-cli and the Python module `hlens`: the result of a distance
// computation (`distance --json`, one line of `batch --json`, hlens.Result.to_dict()) and the
// events of one target (`trace --json`, hlens.trace()). Building them in one place keeps the
// fields and the numbers of the CLI and of Python identical.
#pragma once
#include <string>

#include "hausdorff.h"
#include "json_value.h"
#include "mesh.h"
#include "target_solver.h"

namespace hlens {

// What a distance report says besides the result itself.
struct DistanceReportOptions {
    bool one_sided = false;   // h(A,B) only: b_to_a, hausdorff and its relative value are left out
    Mode mode = Mode::Fast;
    int threads = 1;          // the worker threads actually used
    std::string units;        // a label passed through as "units" (left out when empty)
    double tolerance = -1;    // >= 0: add "tolerance" and "exceeds" (the reported distance > tolerance)
};

// The diagonal that "relative" values divide by: of the union of both meshes' bounding boxes (as
// metro and MeshLab report it).
double report_diagonal(const TriangleMesh& A, const TriangleMesh& B);

// The distance reported against the tolerance: the Hausdorff distance, or h(A,B) when one-sided.
double reported_distance(const HausdorffResult& r, bool one_sided);

Value mesh_json(const TriangleMesh& m);
Value one_sided_json(const OneSidedResult& r, double diagonal);
// {"a", "b", "a_to_b", ["b_to_a", "hausdorff", "relative"], "seconds", "mode", "threads",
//  "diagonal", ["units"], ["tolerance", "exceeds"]}
Value distance_json(const TriangleMesh& A, const TriangleMesh& B, const HausdorffResult& r,
                    const DistanceReportOptions& opt);

// One event of target `target` with the fields meaningful for its kind. Every event has event,
// step, insertion (sources inserted so far) and radius (the search radius then, null while infinite).
Value event_json(const Event& e, const TargetFrame& frame, long long target);
// The readable form of event_json: "  step  event  key=value ..." (step and event name lead).
std::string event_text(const Value& v);
// The last line of a trace: the target's maximum and the size of its domain mesh. `steps` is the
// number of events seen.
Value trace_final_json(const TargetSolver& ts, long steps);
Value label_json(const DomainLabel& l);
Value curve_json(const Quadratic2& q);

}  // namespace hlens
