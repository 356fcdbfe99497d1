// The JSON reports shared by hlens-cli and the Python module `hlens`: the result of a distance
// computation (`distance --json`, one line of `batch --json`, hlens.Result.to_dict()) and the
// events of one target (`trace --json`, hlens.trace()). Building them in one place keeps the
// fields and the numbers of the CLI and of Python identical.
#pragma once
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <hlens/bounds.h>
#include <hlens/hausdorff.h>
#include <hlens/mesh.h>
#include <hlens/surface_stats.h>
#include <hlens/target_solver.h>

#include "json_value.h"

namespace hlens {

// What a distance report says besides the result itself.
struct DistanceReportOptions {
    bool one_sided = false;   // h(A,B) only: b_to_a, hausdorff and its relative value are left out
    Mode mode = Mode::Fast;
    int threads = 1;          // the worker threads actually used
    std::string units;        // a label passed through as "units" (left out when empty)
    double tolerance = -1;    // >= 0: add "tolerance" and "exceeds" (the reported distance > tolerance)
    // hlens-cli distance --tolerance: the verdict "within_tolerance" in place of "exceeds", and
    // without statistics "stopped_early": false (stopped_early_json is the early stop)
    bool verdict = false;
    // --stats: the exact surface statistics per direction (a_to_b, then b_to_a), added to that
    // direction's object (add_stats_json); null: none
    const std::vector<SurfaceStats>* stats = nullptr;
};

// The largest number of bins of a histogram (--histogram N, hlens.distance(histogram=N)).
constexpr int kMaxHistogramBins = 100000;

// The surface statistics of each direction (a_to_b, then b_to_a; a_to_b only when one-sided) of
// the result `r` of A against B, as --stats reports them: surface_stats() with `base`'s options
// (threads, percentiles, histogram_bins, tolerance, cancel) and the direction's distance as its
// known maximum. base.progress, if set, is called with the fraction of both directions together.
// `grid`: the pair's voxel grids (A = grid.mesh(0), B = grid.mesh(1)).
std::vector<SurfaceStats> direction_stats(const VoxelGrid& grid, const HausdorffResult& r, bool one_sided,
                                          const StatsOptions& base);

// The distance of A and B as hausdorff(A, B) computes and times it (its seconds include building the
// grids), keeping the grids for what follows (the early verdict, --verify, --stats).
struct IndexedPair {
    IndexedPair(const TriangleMesh& A, const TriangleMesh& B, int threads);
    HausdorffResult distance(const HausdorffOptions& opt, bool one_sided) const;
    const VoxelGrid grid;
    const double grid_seconds;  // the time building `grid` took

private:
    IndexedPair(const TriangleMesh& A, const TriangleMesh& B, int threads, std::chrono::steady_clock::time_point start);
};

// The diagonal that "relative" values divide by: of the union of both meshes' bounding boxes (as
// metro and MeshLab report it).
double report_diagonal(const TriangleMesh& A, const TriangleMesh& B);

// The distance reported against the tolerance: the Hausdorff distance, or h(A,B) when one-sided.
double reported_distance(const HausdorffResult& r, bool one_sided);

Value mesh_json(const TriangleMesh& m);
Value one_sided_json(const OneSidedResult& r, double diagonal);
// {"a", "b", "a_to_b", ["b_to_a", "hausdorff", "relative"], "seconds", "mode", "threads",
//  "diagonal", ["units"], ["tolerance", "exceeds" | "within_tolerance", ["stopped_early"]]}
Value distance_json(const TriangleMesh& A, const TriangleMesh& B, const HausdorffResult& r,
                    const DistanceReportOptions& opt);
// The fields --stats adds to one direction's object: area, mean, rms, percentiles, [histogram],
// [area_above, fraction_above] (with a tolerance), stats_error, stats_seconds, [sliver_*].
void add_stats_json(Value& direction, const SurfaceStats& s, double tolerance);
// hlens-cli distance --tolerance without --stats, stopped at once by `sb`, a vertex of mesh `side`
// (0: A, 1: B) farther than the tolerance from the other mesh: {"a", "b", "tolerance",
// "within_tolerance": false, "stopped_early": true, "direction", "point", "triangle", "lower",
// "diagonal", ["units"]}.
Value stopped_early_json(const TriangleMesh& A, const TriangleMesh& B, int side, const SampledBound& sb,
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

// The error map of one direction as ASCII PLY: the measured mesh M, every vertex with its distance,
// every face with its max, mean and RMS distance; "quality" (max on faces) is the scalar field
// MeshLab reads. Throws std::runtime_error when the file cannot be written.
void write_error_ply(const std::string& path, const TriangleMesh& M, const SurfaceStats& s);
// hlens-cli --export-errors PATH.ply: PATH-ab.ply (A, stats[0]) and PATH-ba.ply (B, stats[1]), or
// PATH.ply alone when one-sided. Returns the paths written.
std::vector<std::string> write_error_maps(const std::string& path, const TriangleMesh& A, const TriangleMesh& B,
                                          const std::vector<SurfaceStats>& stats, bool one_sided);
Value curve_json(const Quadratic2& q);

}  // namespace hlens
