#include "jobs.h"

#include <cstdio>

#include "camera.h"
#include "exact_map.h"
#include "settings.h"
#include "stepper.h"
#include <hlens/target_maxima.h>

namespace hlens::gui {

void Jobs::start_compute(AppState& s) {
    exact.cancel();   // its values are for the old meshes (dropped when harvested)
    stats.cancel();   // (the same)
    s.exact[0] = s.exact[1] = ExactMap{};
    s.stats.dir = {};
    s.stats.cancelled = false;
    s.stats.failed.clear();
    s.distances_at = -1;
    if (!first_compute) compute_started = std::chrono::steady_clock::now();
    first_compute = false;
    if (s.case_loaded)
        compute.start(s.case_mesh[0], s.case_mesh[1]);
    else
        compute.start(s.path[0], s.path[1]);
}

void Jobs::cancel_all() {
    compute.cancel();
    trace.cancel();
    exact.cancel();
    stats.cancel();
}

namespace {

// The meshes, as soon as they are loaded (before the distances).
void take_meshes(AppState& s, Jobs& jobs, Scene& scene, bool& need_home) {
    if (auto sc = jobs.compute.take_scene()) {
        s.scene = sc;
        s.trace[0].reset();
        s.trace[1].reset();
        scene.set_meshes(sc->mesh[0], sc->mesh[1]);
        s.up_axis = guess_up_axis(scene.box_lo(), scene.box_hi());
        need_home = true;
    }
}

// The computation's outcome: the errors, or the distances and the colour map fast mode left.
void take_distances(AppState& s, Jobs& jobs, Scene& scene) {
    auto out = jobs.compute.take_result();
    if (!out) return;
    jobs.compute_done = true;
    s.computed = out->computed;
    s.cancelled = out->cancelled;
    for (const LoadError& e : out->errors) {
        const char* title = e.side == 0 ? "Cannot load mesh A" : e.side == 1 ? "Cannot load mesh B" : "Computation failed";
        s.errors.push_back(AppError{title, e.file, e.reason});
        std::fprintf(stderr, "hlens: %s%s%s\n", e.file.c_str(), e.file.empty() ? "" : ": ", e.reason.c_str());
    }
    if (!out->errors.empty()) {
        s.scene.reset();
        scene.clear();
    } else if (!s.headless && !s.demo && !s.case_loaded) {
        remember(s.recent, s.path[1], "");
        remember(s.recent, s.path[0], s.recent_file);
    }
    if (s.computed) {
        // The distances show now; the colour map starts with the triangles fast mode solved
        // exactly, the others "not yet exact" until the fill-in brings their values.
        s.result = std::move(out->result);
        s.distances_at = jobs.since_start();
        for (int d = 0; d < 2; ++d) {
            init_exact(s, d);
            show_values(s, scene, d, true);
        }
    }
}

// The exact colour map: take the fill-in's new values (for these meshes only), then make sure it
// runs for the direction shown while that one is incomplete.
void update_fill_in(AppState& s, Jobs& jobs, Scene& scene) {
    ExactMapJob& exact_job = jobs.exact;
    const bool current = s.scene && exact_job.scene() == s.scene.get() && s.computed;
    auto values = exact_job.take_values();
    const int side = exact_job.side();
    bool changed = false;
    if (current)
        for (const auto& [t, v] : values) changed |= set_exact(s, side, t, v);
    if (exact_job.take_ended() && current && !s.exact[side].complete() && !exact_job.cancelling()) {
        s.exact[side].failed = exact_job.phase();   // ended without being asked to: an error
        std::fprintf(stderr, "hlens: exact colour map: %s\n", s.exact[side].failed.c_str());
    }
    if (changed) {
        show_values(s, scene, side, false);
    }
    for (ExactMap& e : s.exact)
        if (s.computed && e.complete() && e.complete_at < 0) e.complete_at = jobs.since_start();
    const int d = s.direction;
    ExactMap& m = s.exact[d];
    const bool wanted = s.exact_mode != ExactMode::Off && s.computed && s.scene && s.scene->grid && !m.complete() &&
                        !m.stopped && m.failed.empty();
    const bool on_it = exact_job.running() && current && side == d;
    if (exact_job.running() && !on_it && !exact_job.cancelling())
        exact_job.cancel();   // another direction or older meshes: stop it (values found so far stay)
    if (wanted && !exact_job.running()) {   // (a cancelled run is started anew once it has stopped)
        const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
        std::vector<uint8_t> known(m.value.size());
        for (size_t t = 0; t < known.size(); ++t) known[t] = m.value[t] >= 0;
        exact_job.start(s.scene, d, order_by_decreasing_bound(r.target_max, known), s.exact_pace_ms);
    }
}

// A finished trace of the selected target.
void take_trace(AppState& s, Jobs& jobs, Scene& scene) {
    if (auto tr = jobs.trace.take_result())
        if (!tr->cancelled && s.selected[tr->side] == (long)tr->target) {
            // A finished trace is the target's full construction: its maximum is exact.
            if (s.computed && tr->error.empty() && set_exact(s, tr->side, tr->target, tr->max)) {
                show_values(s, scene, tr->side, false);
            }
            s.trace[tr->side] = std::move(*tr);
        }
}

// --target: applied once the meshes are there (out of range is an input error, like hlens-cli's).
void apply_target_option(AppState& s, StartTarget& start) {
    if (start.target_applied || !s.scene) return;
    start.target_applied = true;
    const size_t n = s.scene->mesh[s.direction].num_triangles();
    if ((size_t)start.target < n) {
        s.selected[s.direction] = start.target;
    } else {
        char why[160];
        std::snprintf(why, sizeof why, "target %ld is out of range: mesh %s has %zu triangles", start.target,
                      s.direction == 0 ? "A" : "B", n);
        s.errors.push_back(AppError{"Bad --target", "", why});
        std::fprintf(stderr, "hlens: %s\n", why);
    }
}

// The selected target of the current direction gets its trace (restarted if superseded).
void keep_target_traced(AppState& s, Jobs& jobs) {
    const int d = s.direction;
    const long t = s.selected[d];
    if (s.scene && s.scene->grid && t >= 0 && !(s.trace[d] && s.trace[d]->target == (uint32_t)t) &&
        !(jobs.trace.running() && jobs.trace.side() == d && jobs.trace.target() == t))
        jobs.trace.start(s.scene, d, (uint32_t)t);
}

// --step: open the timeline there, once.
void apply_step_option(AppState& s, StartTarget& start) {
    if (start.step != -1 && s.selected[s.direction] == start.target && !s.stepper.open && s.stepper.pending == -2 &&
        !start.step_applied) {
        start.step_applied = true;
        s.stepper.open = true;
        s.stepper.pending = start.step;
    }
}

}  // namespace

void update_jobs(AppState& s, Jobs& jobs, Scene& scene, bool& need_home, StartTarget& start) {
    take_meshes(s, jobs, scene, need_home);
    take_distances(s, jobs, scene);
    update_fill_in(s, jobs, scene);
    take_trace(s, jobs, scene);
    apply_target_option(s, start);
    keep_target_traced(s, jobs);
    apply_step_option(s, start);
    sync_stepper(s);
    s.computing = jobs.compute.running();
    s.progress = jobs.compute.progress();
    s.phase = jobs.compute.phase();
    s.elapsed = jobs.compute.elapsed_seconds();
    s.trace_running = jobs.trace.running();
    s.exact_running = jobs.exact.running() && s.scene && jobs.exact.scene() == s.scene.get();
    s.exact_side = jobs.exact.side();
}

}  // namespace hlens::gui
