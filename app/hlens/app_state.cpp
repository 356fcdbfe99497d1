#include "app_state.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "args.h"
#include "requests.h"
#include "settings.h"

#ifndef HLENS_ASSET_DIR
#define HLENS_ASSET_DIR "assets"
#endif

namespace fs = std::filesystem;

namespace hlens::gui {

bool init_state(AppState& s, const Options& opt) {
    s.headless = !opt.screenshot.empty();
    s.demo = opt.demo;
    s.units = opt.units;
    s.colour_by = (ColourBy)opt.color_by;
    s.tolerance = opt.tolerance;
    s.tolerance_input = std::max(0.0, opt.tolerance);
    s.stats.wanted = opt.stats || s.colour_by != ColourBy::Max || !opt.export_errors.empty();
    if (!opt.export_errors.empty()) s.errors_path = opt.export_errors, s.errors_pending = true;
    s.scripted_input = !opt.input.empty();
    for (int side = 0; side < 2; ++side) {
        s.demo_path[side] = std::string(HLENS_ASSET_DIR) + (side == 0 ? "/demo_a.obj" : "/demo_b.obj");
        s.path[side] = s.edit_path[side] = opt.demo ? s.demo_path[side] : opt.path[side];
        s.name[side] = fs::path(s.path[side]).filename().string();
    }
    s.recent_file = s.headless ? "" : config_file("recent.txt");
    if (!s.recent_file.empty()) s.recent = load_recent(s.recent_file);
    s.style[0].color[0] = 0.86f, s.style[0].color[1] = 0.62f, s.style[0].color[2] = 0.42f;
    s.style[1].color[0] = 0.55f, s.style[1].color[1] = 0.66f, s.style[1].color[2] = 0.88f;
    set_direction(s, opt.direction);
    s.stepper.event_log = opt.event_log;
    s.stepper.graph_open = opt.graph;
    s.stepper.show_overlay = opt.overlay;
    if (!opt.case_name.empty() && !load_builtin_case(s, opt.case_name, opt.epsilon)) {
        std::fprintf(stderr, "hlens: unknown case '%s'\n%s", opt.case_name.c_str(), usage_text());
        return false;
    }
    if (!opt.export_dir.empty()) s.export_dir = opt.export_dir;
    s.exact_pace_ms = opt.exact_pace_ms;
    s.exact_mode = opt.exact_colormap == 0   ? ExactMode::Off
                   : opt.exact_colormap == 1 ? ExactMode::On
                   : opt.exact_colormap == 2 ? ExactMode::Wait
                   : s.headless              ? ExactMode::Wait
                                             : ExactMode::On;
    return true;
}

}  // namespace hlens::gui
