#include "capture.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "requests.h"
#include "screenshot.h"
#include "state_json.h"

namespace hlens::gui {

void save_requested_screenshot(AppState& s, int fb_w, int fb_h) {
    if (!s.req.screenshot) return;
    s.req.screenshot = false;
    std::string name = timestamped_png_name();
    s.status = save_framebuffer_png(name, fb_w, fb_h) ? "saved " + name : "could not write " + name;
}

bool picture_ready(Headless& h, const AppState& s, const Options& opt, const Jobs& jobs, const StartTarget& start,
                   const Script& script) {
    const int d = s.direction;
    const long t = s.selected[d];
    const bool errored = !s.errors.empty();
    const bool traced = (t < 0 || (s.trace[d] && s.trace[d]->target == (uint32_t)t)) &&
                        (opt.step == -1 || start.step_applied || errored);
    // --exact-colormap wait (the default): the fill-in of the direction shown has ended
    // (complete, stopped or failed; a stopped run's targets in progress have landed).
    const ExactMap& em = s.exact[d];
    const bool filled = s.exact_mode != ExactMode::Wait || !s.computed ||
                        ((em.complete() || em.stopped || !em.failed.empty()) && !jobs.exact.running());
    // Statistics asked for: they have arrived (or were cancelled, or failed).
    const StatsView& sv = s.stats;
    const bool stats_done = !sv.wanted || !s.computed || ((sv.ready() || sv.cancelled || !sv.failed.empty()) && !jobs.stats.running());
    const bool ready = jobs.compute_done && !jobs.compute.running() &&
                       (errored || (start.target_applied && script.done() && traced && !jobs.trace.running() && filled && stats_done));
    if (!ready) h.settle = 0;
    return ready && ++h.settle > 4;   // a few frames for ImGui windows to size themselves
}

void take_picture(Headless& h, AppState& s, const Options& opt, View3D& view, const ViewParams& params) {
    const bool errored = !s.errors.empty();
    if (!opt.export_dir.empty() && !errored && !export_selected(s)) {
        std::fprintf(stderr, "hlens: %s\n", s.export_status.c_str());
        h.exit_code = 2;
        return;
    }
    const int fb_w = view.fb_w, fb_h = view.fb_h;
    if (!save_framebuffer_png(opt.screenshot, fb_w, fb_h)) {
        std::fprintf(stderr, "hlens: %s: cannot write the PNG\n", opt.screenshot.c_str());
        h.exit_code = 1;
        return;
    }
    h.exit_code = s.errors.empty() ? 0 : 2;
    if (h.exit_code != 0) return;
    std::string probes;   // (after the PNG: the ID pass does not touch the window's buffers)
    const Scene& scene = *view.scene;
    if (scene.loaded() && s.computed) {
        const std::vector<int> ids = view.picker->triangle_ids(scene, params, s.direction, fb_w, fb_h);
        probes = probes_json(s, ids, params.viewport, fb_h, params.mvp, scene, view.fbs_x,
                             (int)std::lround(1.5f * ImGui::GetFontSize() * view.fbs_x), 4);
    }
    std::printf("%s\n", state_json(s, view.camera, scene.origin(), fb_w, fb_h, params.viewport, probes).c_str());
}

}  // namespace hlens::gui
