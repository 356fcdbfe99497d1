// Background jobs of the debugger: loading + the whole-mesh computation, the exact colour map's
// fill-in, and one target's trace.
//
// Each job runs on its own std::thread; the UI thread only polls (progress(), phase(), take_*()),
// so the window stays responsive. Results are handed over once, by value or shared_ptr, under a
// mutex; nothing else is shared with the worker except the cancel flag and the progress atomics.
#pragma once
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <hlens/hausdorff.h>
#include <hlens/mesh.h>
#include <hlens/surface_stats.h>
#include <hlens/target_maxima.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>

namespace hlens::gui {

// Both meshes and the voxel grid over them. Heap-allocated and never moved: the grid (and every
// TargetSolver built on it) points into mesh[0] and mesh[1].
struct LoadedScene {
    TriangleMesh mesh[2];
    std::unique_ptr<VoxelGrid> grid;
    Box3 bounds() const {
        Box3 b = mesh[0].bounds();
        b.add(mesh[1].bounds());
        return b;
    }
};

struct LoadError {
    int side = -1;          // 0: A, 1: B, -1: not about one file
    std::string file;       // the path as given
    std::string reason;     // the MeshError message without the leading "<path>: "
};

struct ComputeOutput {
    std::vector<LoadError> errors;   // non-empty: loading failed, nothing else is valid
    HausdorffResult result;          // h(A,B), h(B,A), hausdorff (valid when computed)
    bool computed = false;
    bool cancelled = false;
};

// A background thread with a cancel flag, a progress fraction and a phase text.
class Worker {
public:
    Worker() = default;
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;
    virtual ~Worker();

    bool running() const { return running_.load(); }
    void cancel() { cancel_.store(true); }
    bool cancelling() const { return cancel_.load(); }
    double progress() const { return progress_.load(); }   // 0..1, or < 0 when unknown
    std::string phase() const;
    double elapsed_seconds() const;

protected:
    void launch(std::function<void()> body);   // cancels and joins a previous run first
    void stop();                               // cancel and join (call from derived destructors)
    void set_phase(std::string s);
    void set_progress(double f) { progress_.store(f); }
    const std::atomic<bool>& cancel_flag() const { return cancel_; }
    // A result slot's value, once, after the run has ended (empty while it runs).
    template <class T> std::optional<T> take_when_ended(std::optional<T>& slot) {
        if (running()) return std::nullopt;
        std::lock_guard<std::mutex> lock(mutex_);
        std::optional<T> r = std::move(slot);
        slot.reset();
        return r;
    }
    mutable std::mutex mutex_;                 // guards the derived class's results and phase_

private:
    std::thread thread_;
    std::atomic<bool> running_{false}, cancel_{false};
    std::atomic<double> progress_{-1};
    std::string phase_;
    std::chrono::steady_clock::time_point start_;
};

// Loads A and B, builds the voxel grid, then h(A,B) and h(B,A) (one_sided twice on that grid: the
// same computation as hlens::hausdorff(), split so the progress bar can name the direction and the
// grid can be kept for the target solver).
class ComputeJob : public Worker {
public:
    ~ComputeJob() override { stop(); }
    void start(const std::string& path_a, const std::string& path_b);
    // The same with meshes made in memory (the built-in cases): no loading.
    void start(const TriangleMesh& a, const TriangleMesh& b);
    // The meshes and grid, once, as soon as they are ready (before the distances are).
    std::shared_ptr<const LoadedScene> take_scene();
    // The outcome, once, when the job has ended.
    std::optional<ComputeOutput> take_result();

private:
    void start_impl(const std::string& path_a, const std::string& path_b, std::shared_ptr<std::array<TriangleMesh, 2>> given);
    std::shared_ptr<const LoadedScene> scene_;
    std::optional<ComputeOutput> result_;
};

// The exact colour map's fill-in: after the fast distances are shown, the exact maximum over every
// target of mesh `side` that fast mode skipped (exact_target_maxima, target_maxima.h), largest
// upper bound first. Values are handed over as they come (take_values, polled every frame), so
// the picture fills in while the job runs; cancelling keeps the values found so far.
class ExactMapJob : public Worker {
public:
    ~ExactMapJob() override { stop(); }
    // `order`: the targets still to solve, in order. Replaces (cancels) a previous run.
    // `pace_ms`: a wait after each target (--exact-map-pace, for tests).
    void start(std::shared_ptr<const LoadedScene> scene, int side, std::vector<uint32_t> order, int pace_ms = 0);
    int side() const { return side_; }
    const LoadedScene* scene() const { return scene_.get(); }
    size_t total() const { return total_; }
    size_t solved() const { return solved_.load(); }
    // The exact values found since the last call: (target, max distance).
    std::vector<std::pair<uint32_t, double>> take_values();
    // The run has ended (finished or cancelled); true once per run, after its last values.
    bool take_ended();

private:
    std::shared_ptr<const LoadedScene> scene_;   // keeps the grid alive while the job runs
    std::vector<std::pair<uint32_t, double>> values_;
    std::atomic<size_t> solved_{0};
    size_t total_ = 0;
    int side_ = 0;
    bool ended_ = false;
};

// The exact surface statistics of both directions (core/surface_stats.h: every target's full
// construction, integrated), on request: h(A,B) then h(B,A), with the same options as
// `hlens-cli distance A B --stats --histogram kStatsBins [--tolerance T]`, so the numbers agree.
constexpr int kStatsBins = 20;
struct StatsOutput {
    std::array<std::shared_ptr<const SurfaceStats>, 2> dir;   // both set, or none (cancelled / failed)
    double tolerance = -1;        // the tolerance they were computed with (< 0: none)
    std::string error;
};

class StatsJob : public Worker {
public:
    ~StatsJob() override { stop(); }
    // `distance[d]`: the one-sided distances (StatsOptions::known_max). Replaces a previous run.
    void start(std::shared_ptr<const LoadedScene> scene, const double distance[2], double tolerance);
    const LoadedScene* scene() const { return scene_.get(); }
    // The outcome, once, when the run has ended.
    std::optional<StatsOutput> take_result();

private:
    std::shared_ptr<const LoadedScene> scene_;
    std::optional<StatsOutput> result_;
};

// One target T' of mesh `side` against the other mesh: what the target panel shows.
struct TraceSummary {
    int side = 0;
    uint32_t target = 0;
    int insertions = 0, domains = 0, arcs = 0, vertices = 0;
    double max = 0;               // sqrt(max d^2 over T')
    Vec3 max_point;
    bool degenerate = false;
    bool cancelled = false;
    double seconds = 0;
    std::string error;
    // The finished solver, kept for the panels to come (domain view, stepping, event log).
    std::shared_ptr<TargetSolver> solver;
};

class TraceJob : public Worker {
public:
    ~TraceJob() override { stop(); }
    void start(std::shared_ptr<const LoadedScene> scene, int side, uint32_t target);
    std::optional<TraceSummary> take_result();
    int side() const { return side_; }
    long target() const { return target_; }

private:
    std::shared_ptr<const LoadedScene> scene_;   // keeps the grid alive while the solver runs
    std::optional<TraceSummary> result_;
    int side_ = 0;
    long target_ = -1;
};

}  // namespace hlens::gui
