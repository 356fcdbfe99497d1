// The background jobs (compute.h) as the main loop drives them: the computation of the pair, the
// selected target's trace, the exact colour map's fill-in and the statistics. Each frame the loop
// takes what they have finished into the AppState (update_jobs) and starts what is missing; the
// views never touch the jobs (they ask through AppState::req).
#pragma once
#include <chrono>

#include "app_state.h"
#include "compute.h"
#include "scene.h"

namespace hlens::gui {

struct Jobs {
    ComputeJob compute;
    TraceJob trace;
    ExactMapJob exact;            // the exact colour map's fill-in (one direction at a time)
    StatsJob stats;               // the exact surface statistics, on request
    bool compute_done = false;    // the computation of the current pair has ended (result taken)

    // Times in the state are from start-up for the first pair, from the request for later ones.
    explicit Jobs(std::chrono::steady_clock::time_point program_start) : compute_started(program_start) {}
    double since_start() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - compute_started).count();
    }
    bool busy() const { return compute.running() || trace.running(); }
    bool filling() const { return exact.running() || stats.running(); }
    // Loads and computes the pair of s (files or a built-in case), dropping what the other jobs
    // had for the previous one.
    void start_compute(AppState& s);
    // Stops every job (before the meshes they read go away).
    void cancel_all();

private:
    std::chrono::steady_clock::time_point compute_started;
    bool first_compute = true;
};

// --target and --step: applied once, when the meshes are there.
struct StartTarget {
    long target = -1, step = -1;  // as given (-1: not given)
    bool target_applied = false, step_applied = false;
    StartTarget(long t, long st) : target(t), step(st), target_applied(t < 0) {}
};

// Takes the jobs' results into s (the meshes into `scene`, setting `need_home` for the camera;
// the distances; the exact values; the trace), applies --target and --step, keeps the selected
// target traced and the stepper on it, and copies the computation's progress into s.
void update_jobs(AppState& s, Jobs& jobs, Scene& scene, bool& need_home, StartTarget& start);

}  // namespace hlens::gui
