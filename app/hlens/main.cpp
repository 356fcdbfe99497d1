// hlens: the interactive debugger of Hausdorff Lens (GLFW + Dear ImGui + OpenGL 3.3 core).
//
// One straight main loop, as in Dear ImGui's examples/example_glfw_opengl3/main.cpp:
//   1. events  2. harvest background jobs  3. new ImGui frame  4. mouse/keyboard for the 3D view
//   5. panels  6. act on the panels' requests  7. render  8. screenshots  9. swap
// Loading and computing run on background threads (compute.h); the loop only polls them.
//
// Interactive runs keep the floating windows' layout in ~/.config/hlens/imgui.ini
// ($XDG_CONFIG_HOME/hlens/); the sidebar, target and error windows are placed every frame.
// Headless (--screenshot PATH): vsync off, no imgui.ini; the loop waits for the computation (and
// the trace of --target, and the exact colour map's fill-in unless --exact-colormap on|off), lets
// ImGui settle for a few frames, reads the back buffer into a PNG before swapping, prints the state
// as one JSON line on stdout and exits (0, or 2 on bad input).
#include <algorithm>
#include <array>
#include <chrono>
#include <cfloat>
#include <cinttypes>
#include <memory>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <glm/glm.hpp>

#include "app_state.h"
#include "args.h"
#include "camera.h"
#include "case_export.h"
#include "cases.h"
#include "colormap.h"
#include "compute.h"
#include "gl.h"
#include "json_value.h"
#include "report.h"
#include "panels.h"
#include "picking.h"
#include "scene.h"
#include "screenshot.h"
#include "stats_flow.h"
#include "target_maxima.h"

#ifndef HLENS_ASSET_DIR
#define HLENS_ASSET_DIR "assets"
#endif

namespace fs = std::filesystem;
using namespace hlens;
using namespace hlens::gui;

namespace {

// Files dropped on the window (GLFW calls this from glfwPollEvents, on the main thread).
std::vector<std::string> g_dropped;
void on_drop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// The window moved to a screen with another content scale (GLFW calls this from glfwPollEvents).
float g_content_scale = 0;   // 0: no change pending
void on_content_scale(GLFWwindow*, float sx, float) { g_content_scale = std::max(1.0f, sx); }

// Fonts and sizes for a content scale: everything else is sized in multiples of the font size.
// Called before the first frame and between frames when the scale changes (rebuilding the font
// atlas and its texture, and the style from scratch so sizes are not scaled twice).
void apply_dpi_scale(float scale, bool rebuild_texture) {
    ImGuiIO& io = ImGui::GetIO();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 0;
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    io.Fonts->Clear();
    ImFontConfig font;
    font.SizePixels = std::round(13.0f * scale);
    io.Fonts->AddFontDefault(&font);
    if (rebuild_texture) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
}

// Ctrl-C or a polite kill ends the loop as closing the window does (the layout is saved).
volatile std::sig_atomic_t g_quit = 0;
void on_signal(int) { g_quit = 1; }

void glfw_error(int code, const char* what) { std::fprintf(stderr, "hlens: GLFW error %d: %s\n", code, what); }

// Settings of interactive runs live in ~/.config/hlens/ (never the current directory).
std::string config_file(const char* name) {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    fs::path dir = xdg && *xdg ? fs::path(xdg) / "hlens" : home && *home ? fs::path(home) / ".config" / "hlens" : fs::path();
    if (dir.empty()) return "";
    std::error_code ec;
    fs::create_directories(dir, ec);
    return ec ? "" : (dir / name).string();
}

// Recently opened files: ~/.config/hlens/recent.txt, one path a line, newest first.
std::vector<std::string> load_recent(const std::string& file) {
    std::vector<std::string> r;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && r.size() < 12;)
        if (!line.empty()) r.push_back(line);
    return r;
}
void remember(std::vector<std::string>& recent, const std::string& path, const std::string& file) {
    std::error_code ec;
    fs::path abs = fs::absolute(path, ec);
    const std::string p = ec ? path : abs.lexically_normal().string();
    recent.erase(std::remove(recent.begin(), recent.end(), p), recent.end());
    recent.insert(recent.begin(), p);
    if (recent.size() > 12) recent.resize(12);
    if (file.empty()) return;
    std::ofstream out(file);
    for (const std::string& r : recent) out << r << "\n";
}

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// ---- The exact colour map (per direction): fast mode's exact values, then the fill-in's.

// The colour map's range: the values shown (exact maxima known so far, never a bound; or the
// means or RMS). It follows them while the user has not moved it (or always, with `reset`).
void refresh_range(AppState& s, int d, const std::vector<double>& values, bool reset) {
    ColourRange& r = s.range[d];
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (double v : values)
        if (v >= 0) lo = std::min(lo, v), hi = std::max(hi, v);
    const bool follow = reset || !r.valid || (r.lo == r.data_lo && r.hi == r.data_hi);
    r.valid = lo <= hi;
    if (!r.valid) return;
    r.data_lo = (float)lo;
    r.data_hi = (float)hi;
    if (follow) {
        r.lo = r.data_lo;
        r.hi = r.data_hi;
    }
}

// Direction d's colour map on the GPU and its range, after its values changed.
void show_values(AppState& s, Scene& scene, int d, bool reset) {
    const std::vector<double> v = colour_values(s, d);
    scene.set_values(d, v);
    scene.set_maxima(d, s.exact[d].value);
    refresh_range(s, d, v, reset);
}

// Direction d's map as fast mode left it: exact where it solved the triangle, unknown elsewhere.
void init_exact(AppState& s, int d) {
    const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
    ExactMap& m = s.exact[d];
    m = ExactMap{};
    m.value.assign(r.target_max.size(), -1.0);
    for (size_t t = 0; t < m.value.size(); ++t)
        if (t < r.target_exact.size() && r.target_exact[t] && r.target_max[t] >= 0) {
            m.value[t] = r.target_max[t];
            ++m.exact;
        }
}

// A newly known exact value (from the fill-in or a finished trace); false if it was known.
bool set_exact(AppState& s, int d, uint32_t t, double v) {
    ExactMap& m = s.exact[d];
    if (t >= m.value.size() || m.value[t] >= 0 || !(v >= 0)) return false;
    m.value[t] = v;
    ++m.exact;
    return true;
}

// The best known maximum over target t of direction d: exact if known, else fast mode's bound.
double target_value(const AppState& s, int d, long t, bool& exact) {
    const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
    exact = s.exact[d].known(t);
    if (exact) return s.exact[d].value[t];
    return t >= 0 && (size_t)t < r.target_max.size() ? r.target_max[t] : NAN;
}

// Sample pixels of the measured mesh for the headless state: up to `per_kind` triangles not yet
// exact and as many exact ones, each with a pixel (image coordinates, from the top-left) and a
// radius `clear` >= 2 such that the square of that radius around it shows only that triangle: no
// edge of it (lines are kept 2 pixels away), no other mesh in front, no panel, witness marker or
// hint text over it. The triangles with the largest such squares first (radius up to `max_clear`).
// "value" is the value the colour map shows there (max, mean or RMS; null: not yet exact).
std::string probes_json(const AppState& s, const std::vector<int>& ids, const int vp[4], int fb_h, const glm::mat4& mvp,
                        const Scene& scene, float fbs, int max_clear, int per_kind) {
    const int d = s.direction, w = vp[2], h = vp[3];
    const int kmax = max_clear + 2;
    // Excluded (image coordinates): the target panel, the witness markers (segment, points and
    // label, as draw_view_overlay draws them, with a margin), the hint line.
    const float fs = ImGui::GetFontSize() * fbs;
    std::vector<std::array<float, 4>> rects;   // x0, y0, x1, y1
    std::vector<std::array<float, 4>> segments;
    const ViewRect& tw = s.target_window;
    rects.push_back({tw.x * fbs, tw.y * fbs, (tw.x + tw.w) * fbs, (tw.y + tw.h) * fbs});
    rects.push_back({0, (s.view.y + s.view.h - 2.2f * ImGui::GetFontSize()) * fbs, 1e9f, 1e9f});
    if (s.computed)
        for (int dd = 0; dd < 2; ++dd) {
            if (!s.show_witness[dd]) continue;
            const OneSidedResult& r = dd == 0 ? s.result.a_to_b : s.result.b_to_a;
            float q[2][2];
            bool ok = true;
            for (int k = 0; k < 2 && ok; ++k) {
                glm::vec4 c = mvp * glm::vec4(scene.local(k == 0 ? r.from_point : r.to_point), 1.0f);
                ok = c.w > 1e-7f;
                q[k][0] = vp[0] + (0.5f + 0.5f * c.x / c.w) * w;
                q[k][1] = fb_h - vp[1] - (0.5f + 0.5f * c.y / c.w) * h;
            }
            if (!ok) continue;
            segments.push_back({q[0][0], q[0][1], q[1][0], q[1][1]});
            const float rr = 0.38f * fs;   // the label's box (draw_view_overlay)
            const ImVec2 ls = ImGui::CalcTextSize("h(A,B)");
            rects.push_back({q[0][0] + 1.6f * rr - 4, q[0][1] - 2.6f * rr - 2, q[0][0] + 1.6f * rr + ls.x * fbs + 4,
                             q[0][1] - 2.6f * rr + ls.y * fbs + 2});
        }
    auto excluded = [&](float x, float y, int m) {
        for (const auto& b : rects)
            if (x >= b[0] - m && x < b[2] + m && y >= b[1] - m && y < b[3] + m) return true;
        for (const auto& g : segments) {   // within a marker's radius (plus the square) of the segment
            const float dx = g[2] - g[0], dy = g[3] - g[1], len2 = dx * dx + dy * dy;
            const float u = len2 > 0 ? std::clamp(((x - g[0]) * dx + (y - g[1]) * dy) / len2, 0.0f, 1.0f) : 0.0f;
            if (std::hypot(x - g[0] - u * dx, y - g[1] - u * dy) < 0.6f * fs + 1.5f * m) return true;
        }
        return false;
    };
    struct Best { int k = 0, x = 0, y = 0; };   // the largest clear square of a triangle (first found)
    std::map<int, Best> best;
    const long sel = s.selected[d];
    for (int y = 0; y < h; y += 2)
        for (int x = 0; x < w; x += 2) {
            const int t = ids[(size_t)y * w + x];
            if (t < 0 || t == sel) continue;
            // Grow the square ring by ring while it stays inside the view and on triangle t.
            int k = 0;
            for (bool ok = true; ok && k < kmax && x - k - 1 >= 0 && y - k - 1 >= 0 && x + k + 1 < w && y + k + 1 < h;) {
                const int r = k + 1;
                for (int i = -r; i <= r && ok; ++i)
                    ok = ids[(size_t)(y - r) * w + x + i] == t && ids[(size_t)(y + r) * w + x + i] == t &&
                         ids[(size_t)(y + i) * w + x - r] == t && ids[(size_t)(y + i) * w + x + r] == t;
                if (ok) k = r;
            }
            const int ix = vp[0] + x, iy = fb_h - 1 - (vp[1] + y);
            if (k < 4 || excluded((float)ix, (float)iy, k)) continue;
            Best& b = best[t];
            if (k > b.k) b = Best{k, ix, iy};
        }
    std::vector<std::pair<int, int>> order;   // (-clear, triangle)
    for (const auto& [t, b] : best) order.emplace_back(-b.k, t);
    std::sort(order.begin(), order.end());
    const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
    const std::vector<double> shown = colour_values(s, d);   // the colour map's value (max, mean or RMS)
    std::string j = "[";
    int taken[2] = {0, 0};
    for (const auto& [negk, t] : order) {
        const bool exact = s.exact[d].known(t);
        if (taken[exact] >= per_kind) continue;
        ++taken[exact];
        const Best& b = best[t];
        if (j.size() > 1) j += ", ";
        j += "{\"triangle\": " + std::to_string(t) + ", \"exact\": " + (exact ? "true" : "false") +
             ", \"value\": " + ((size_t)t < shown.size() && shown[t] >= 0 ? json_number(shown[t]) : "null") +
             ", \"bound\": " + ((size_t)t < r.target_max.size() ? json_number(r.target_max[t]) : "null") +
             ", \"pixel\": [" + std::to_string(b.x) + ", " + std::to_string(b.y) + "], \"clear\": " + std::to_string(b.k - 2) + "}";
    }
    return j + "]";
}

// The statistics as hlens-cli distance --stats --json reports them per direction (report.h).
std::string stats_json(const AppState& s) {
    const StatsView& v = s.stats;
    Value o = Value::object().add("wanted", Value::boolean(v.wanted)).add("ready", Value::boolean(v.ready()));
    o.add("tolerance", v.ready() && v.tolerance >= 0 ? Value::number(v.tolerance) : Value());
    for (int d = 0; d < 2 && v.ready(); ++d) {
        Value dir = Value::object();
        add_stats_json(dir, *v.dir[d], v.tolerance);
        o.add(d == 0 ? "a_to_b" : "b_to_a", std::move(dir));
    }
    return to_json(o);
}

// The tolerance: the measured mesh's area above it (exact with the statistics at T, "bound": the
// triangles whose maximum exceeds it), the selected target's (its domain mesh cut at T), and
// points on the curve d = T as the domain view draws it (else of the target's final mesh), world
// coordinates.
std::string tolerance_json(const AppState& s) {
    if (s.tolerance < 0) return "null";
    const MeshAbove m = mesh_above(s, s.direction);
    Value o = Value::object().add("value", Value::number(s.tolerance));
    o.add("mesh", Value::object()
                      .add("area", Value::number(m.area))
                      .add("area_above", m.exact >= 0 ? Value::number(m.exact) : Value())
                      .add("fraction_above", m.exact >= 0 ? Value::number(m.fraction) : Value())
                      .add("triangles_above", Value::integer((long long)m.triangles))
                      .add("bound", Value::number(m.bound)));
    const ToleranceCut& t = s.target_cut;
    o.add("target", t.t >= 0 ? Value::object().add("area", Value::number(t.area)).add("area_above", Value::number(t.area_above)) : Value());
    const bool view = s.stepper.open && s.stepper.active() && s.view_cut.t >= 0;
    const ToleranceCut& c = view ? s.view_cut : t;
    if (view) o.add("view", Value::object().add("area", Value::number(c.area)).add("area_above", Value::number(c.area_above)));
    Value pts = Value::array();
    for (const Vec3& p : c.samples) pts.push(Value::array().push(Value::number(p.x)).push(Value::number(p.y)).push(Value::number(p.z)));
    o.add("curve_arcs", Value::integer((long long)c.curve.size())).add("curve", std::move(pts));
    return to_json(o);
}

// The state behind a headless picture, one JSON line.
std::string state_json(const AppState& s, const Camera& cam, const Vec3& origin, int fb_w, int fb_h, const int vp[4],
                       const std::string& probes) {
    const int d = s.direction;
    const long t = s.selected[d];
    const TraceSummary* tr = t >= 0 && s.trace[d] && s.trace[d]->target == (uint32_t)t ? &*s.trace[d] : nullptr;
    std::string j = "{\"direction\": \"";
    j += d == 0 ? "ab" : "ba";
    j += "\", \"target\": " + (t >= 0 ? std::to_string(t) : std::string("null"));
    bool t_exact = false;
    const double t_value = t >= 0 && s.computed ? target_value(s, d, t, t_exact) : NAN;
    // target_max: the exact maximum over the target once known (fast mode, fill-in or trace),
    // before that fast mode's upper bound (target_exact false).
    j += ", \"target_max\": " + (t >= 0 && s.computed ? json_number(t_value) : "null");
    j += ", \"target_exact\": " + std::string(t >= 0 && s.computed && std::isfinite(t_value) ? (t_exact ? "true" : "false") : "null");
    j += ", \"insertions\": " + (tr ? std::to_string(tr->insertions) : std::string("null"));
    j += ", \"domains\": " + (tr ? std::to_string(tr->domains) : std::string("null"));
    j += ", \"arcs\": " + (tr ? std::to_string(tr->arcs) : std::string("null"));
    j += ", \"vertices\": " + (tr ? std::to_string(tr->vertices) : std::string("null"));
    j += ", \"trace_max\": " + (tr ? json_number(tr->max) : std::string("null"));
    j += ", \"a_to_b\": " + (s.computed ? json_number(s.result.a_to_b.distance) : "null");
    j += ", \"b_to_a\": " + (s.computed ? json_number(s.result.b_to_a.distance) : "null");
    j += ", \"hausdorff\": " + (s.computed ? json_number(s.result.hausdorff) : "null");
    j += ", \"units\": " + (s.units.empty() ? std::string("null") : to_json(Value::string(s.units)));
    // Seconds from start-up until the distances showed (null: not yet).
    j += ", \"distances_at\": " + (s.distances_at >= 0 ? json_number(s.distances_at) : "null");
    {   // The exact colour map of the measured mesh, its range and where the colour bar is.
        const ExactMap& m = s.exact[d];
        const ColourRange& r = s.range[d];
        const char* mode = s.exact_mode == ExactMode::Off ? "off" : s.exact_mode == ExactMode::On ? "on" : "wait";
        const float fx = ImGui::GetIO().DisplayFramebufferScale.x;
        j += ", \"exact_colormap\": {\"mode\": \"" + std::string(mode) + "\", \"color_by\": \"" +
             colour_by_name(s.colour_by) + "\", \"shows\": \"" + (s.stats.ready() ? colour_by_name(s.colour_by) : "max") + "\", \"exact\": " + std::to_string(m.exact) +
             ", \"triangles\": " + std::to_string(m.value.size()) + ", \"complete\": " + (m.complete() ? "true" : "false") +
             ", \"running\": " + (s.exact_running && s.exact_side == d ? "true" : "false") +
             ", \"stopped\": " + (m.stopped ? "true" : "false") + ", \"complete_at\": " + (m.complete_at >= 0 ? json_number(m.complete_at) : "null") +
             ", \"shown\": " + (s.show_colormap && r.valid ? "true" : "false") +
             ", \"lo\": " + (r.valid ? json_number(r.lo) : "null") + ", \"hi\": " + (r.valid ? json_number(r.hi) : "null") +
             ", \"bar\": [" + std::to_string((int)std::lround(s.colour_bar_rect[0] * fx)) + ", " +
             std::to_string((int)std::lround(s.colour_bar_rect[1] * fx)) + ", " +
             std::to_string((int)std::lround(s.colour_bar_rect[2] * fx)) + ", " +
             std::to_string((int)std::lround(s.colour_bar_rect[3] * fx)) + "]" +
             ", \"hi_label\": " + to_json(Value::string(s.colour_bar_hi_label));
        if (!probes.empty()) j += ", \"probes\": " + probes;
        j += "}";
    }
    j += ", \"stats\": " + stats_json(s);
    j += ", \"tolerance\": " + tolerance_json(s);
    if (!s.errors_status.empty()) {
        Value w = Value::array();
        for (const std::string& p : s.errors_written) w.push(Value::string(p));
        j += ", \"error_maps\": " + to_json(Value::object().add("ok", Value::boolean(s.errors_ok)).add("written", std::move(w)));
    }
    j += ", \"camera\": {\"yaw\": " + json_number(cam.yaw) + ", \"pitch\": " + json_number(cam.pitch) +
         ", \"distance\": " + json_number(cam.distance) + ", \"pivot\": [" + json_number(cam.pivot.x) + ", " +
         json_number(cam.pivot.y) + ", " + json_number(cam.pivot.z) + "], \"origin\": [" + json_number(origin.x) + ", " +
         json_number(origin.y) + ", " + json_number(origin.z) + "]}";   // pivot + origin: world coordinates
    j += ", \"size\": [" + std::to_string(fb_w) + ", " + std::to_string(fb_h) + "]";
    // The 3D view: x, y from the top, width, height (framebuffer pixels).
    j += ", \"viewport\": [" + std::to_string(vp[0]) + ", " + std::to_string(fb_h - vp[1] - vp[3]) + ", " +
         std::to_string(vp[2]) + ", " + std::to_string(vp[3]) + "]";
    if (s.case_loaded) j += ", \"case\": \"" + s.case_name + "\", \"epsilon\": " + json_number(s.case_eps);
    if (s.export_ok) j += ", \"exported\": true";
    j += ", \"help\": " + std::string(s.help_open ? "true" : "false");
    j += ", \"font_size\": " + json_number(ImGui::GetFontSize()) + ", \"sidebar\": " + json_number(s.sidebar_width);
    if (s.tiles.on) {   // the tiled layout (window coordinates): x, y, w, h
        auto rect = [](const ViewRect& r) {
            return "[" + json_number(r.x) + ", " + json_number(r.y) + ", " + json_number(r.w) + ", " + json_number(r.h) + "]";
        };
        j += ", \"tiles\": {\"domain\": " + rect(s.tiles.domain.r) + ", \"timeline\": " + rect(s.tiles.timeline.r);
        if (s.tiles.graph_on) j += ", \"graph\": " + rect(s.tiles.graph.r);
        if (s.tiles.log_on) j += ", \"log\": " + rect(s.tiles.log.r);
        j += ", \"view\": " + rect(s.view) + "}";
    }
    const Stepper& st = s.stepper;
    if (st.open && st.active()) {   // the timeline's state: "step" is the current event (-1: none yet)
        j += ", \"step\": " + std::to_string(st.step);
        j += ", \"step_finished\": " + std::string(st.at_end ? "true" : "false");
        j += ", \"step_event\": " + (st.current ? "\"" + std::string(event_name(st.current->kind)) + "\"" : std::string("null"));
        j += ", \"step_state\": {\"insertions\": " + std::to_string(st.insertions()) +
             ", \"domains\": " + std::to_string(st.live_domains) + ", \"arcs\": " + std::to_string(st.live_arcs) +
             ", \"vertices\": " + std::to_string(st.live_vertices) +
             ", \"max\": " + json_number(std::sqrt(st.max_sq())) +
             ", \"search_radius\": " + json_number(st.search_radius()) +
             ", \"highlighted\": " + std::to_string(st.inserted_sources().size()) +
             ", \"inserting\": " + std::to_string(st.inserting()) +
             ", \"radius_plot\": " + std::to_string(st.radius_plot.size()) + "}";
        j += ", \"playing\": " + std::string(st.playing ? "true" : "false");
        j += ", \"voxels\": {\"visited\": " + std::to_string(st.vox_visited) + ", \"pending\": " +
             std::to_string(st.vox_pending) + ", \"culled\": " + std::to_string(st.vox_culled) + "}";
        const float fx = ImGui::GetIO().DisplayFramebufferScale.x;   // window -> framebuffer
        j += ", \"domain_view\": [" + std::to_string((int)std::lround(st.view_rect[0] * fx)) + ", " +
             std::to_string((int)std::lround(st.view_rect[1] * fx)) + ", " + std::to_string((int)std::lround(st.view_rect[2] * fx)) +
             ", " + std::to_string((int)std::lround(st.view_rect[3] * fx)) + "]";
        j += ", \"domain_zoom\": " + json_number(st.zoom) + ", \"domain_pan\": [" + json_number(st.pan_x) + ", " +
             json_number(st.pan_y) + "], \"corners_on_screen\": [";
        for (int k = 0; k < 3; ++k)
            j += std::string(k ? ", " : "") + json_number(st.corner_screen[k][0]) + ", " + json_number(st.corner_screen[k][1]);
        j += "]";
        if (const DomainMesh* m = st.mesh()) {
            if (st.hover_arc >= 0 && (size_t)st.hover_arc < m->edges().size())
                j += ", \"hover\": {\"arc\": " + std::to_string(st.hover_arc) + ", \"kind\": \"" +
                     arc_kind_name(m->edges()[st.hover_arc].kind) + "\"}";
            else if (st.hover_face >= 0 && (size_t)st.hover_face < m->faces().size())
                j += ", \"hover\": {\"face\": " + std::to_string(st.hover_face) + ", \"source\": " +
                     std::to_string(m->faces()[st.hover_face].label.source) + ", \"region\": \"" +
                     region_name(m->faces()[st.hover_face].label.region) + "\"}";
        }
        if (st.show_overlay && st.overlay_revision == st.revision)
            j += ", \"overlay\": {\"samples\": " + std::to_string(st.overlay_samples) + ", \"disagree\": " +
                 std::to_string(st.overlay_disagree) + ", \"ignored\": " + std::to_string(st.overlay_ignored) +
                 ", \"ties\": " + std::to_string(st.overlay_ties) +
                 ", \"gpu\": " + (st.overlay_gpu ? "true" : "false") + "}";
        if (st.graph_open && st.graph_revision != 0)
            j += ", \"graph\": {\"samples\": " + std::to_string(st.graph_samples) + ", \"z_max\": " + json_number(st.graph_z_max) +
                 ", \"grid_max\": " + json_number(st.graph_grid_max) + ", \"max_sq\": " + json_number(st.max_sq()) +
                 ", \"yaw\": " + json_number(st.graph_yaw) + ", \"pitch\": " + json_number(st.graph_pitch) +
                 ", \"zoom\": " + json_number(st.graph_zoom) + ", \"rect\": [" + std::to_string((int)st.graph_rect[0]) + ", " +
                 std::to_string((int)st.graph_rect[1]) + ", " + std::to_string((int)st.graph_rect[2]) + ", " +
                 std::to_string((int)st.graph_rect[3]) + "]}";
        if (st.event_log)
            j += ", \"event_log\": {\"shown\": " + std::to_string(st.log_shown) + ", \"total\": " + std::to_string(st.log_total) +
                 ", \"current_x\": " + json_number(st.log_row_x) + ", \"current_y\": " + json_number(st.log_current_y) +
                 ", \"row_h\": " + json_number(st.log_row_h) + "}";
    } else {
        j += ", \"step\": null";
    }
    j += "}";
    return j;
}

// Scripted input as one mouse state per frame.
struct MouseFrame {
    float x, y;
    bool down;
    int key = -1;        // a GLFW key held down during this frame
    bool right = false;  // the right button is down
    float wheel = 0;     // wheel steps this frame
};
std::vector<MouseFrame> script_frames(const std::vector<InputAction>& actions) {
    std::vector<MouseFrame> f;
    for (const InputAction& a : actions) {
        if (a.kind == InputAction::Key) {
            MouseFrame k = f.empty() ? MouseFrame{-1, -1, false} : f.back();
            k.down = false;
            k.key = a.key;
            f.push_back(k);
            k.key = -1;
            f.push_back(k);
        } else if (a.kind == InputAction::Drag || a.kind == InputAction::RightDrag) {
            const bool left = a.kind == InputAction::Drag;
            auto at = [&](float x, float y, bool down) {
                MouseFrame m{x, y, left && down};
                m.right = !left && down;
                return m;
            };
            f.push_back(at(a.x0, a.y0, false));
            f.push_back(at(a.x0, a.y0, true));
            for (int i = 1; i <= 8; ++i) f.push_back(at(a.x0 + (a.x1 - a.x0) * i / 8, a.y0 + (a.y1 - a.y0) * i / 8, true));
            f.push_back(at(a.x1, a.y1, false));
        } else if (a.kind == InputAction::Wheel) {
            f.push_back({a.x0, a.y0, false});
            MouseFrame w{a.x0, a.y0, false};
            w.wheel = a.x1;
            f.push_back(w);
        } else if (a.kind == InputAction::Hover || a.kind == InputAction::Wait) {
            MouseFrame m = a.kind == InputAction::Hover ? MouseFrame{a.x0, a.y0, false}
                                                        : (f.empty() ? MouseFrame{-1, -1, false} : f.back());
            m.down = m.right = false;
            m.key = -1;
            m.wheel = 0;
            for (int i = 0; i < (int)a.x1; ++i) f.push_back(m);
            continue;
        } else {
            f.push_back({a.x0, a.y0, false});
            for (int k = 0; k < (a.kind == InputAction::DoubleClick ? 2 : 1); ++k) {
                f.push_back({a.x0, a.y0, true});
                f.push_back({a.x0, a.y0, false});
            }
        }
        MouseFrame rest = f.back();
        rest.wheel = 0;
        f.push_back(rest);
    }
    return f;
}

void set_direction(AppState& s, int d) {
    s.direction = d;
    // The measured mesh solid, the other one a wireframe that does not tint the colour map,
    // unless the user set them.
    if (!s.style[d].touched) {
        s.style[d].mode = DrawMode::SolidEdges;
        s.style[d].opacity = 1.0f;
    }
    if (!s.style[1 - d].touched) {
        s.style[1 - d].mode = DrawMode::Wireframe;
        s.style[1 - d].opacity = 0.6f;
    }
}

// Replaces A and B by a built-in case (the caller recomputes). False: unknown name.
bool load_builtin_case(AppState& s, const std::string& name, double eps) {
    TriangleMesh a, b;
    double hand = 0;
    if (!make_case(name, eps, a, b, hand)) return false;
    s.case_loaded = true;
    s.case_name = name;
    s.case_eps = eps;
    s.case_mesh[0] = std::move(a);
    s.case_mesh[1] = std::move(b);
    for (int side = 0; side < 2; ++side) {
        s.path[side] = s.edit_path[side] = "";
        s.name[side] = "case " + name + (side == 0 ? " A" : " B");
    }
    s.demo = false;
    s.errors.clear();
    s.selected[0] = s.selected[1] = -1;
    s.trace[0].reset();
    s.trace[1].reset();
    s.scene.reset();
    return true;
}

// "Export case": the selected target and its relevant sources as two OBJ files in s.export_dir.
bool export_selected(AppState& s) {
    const int d = s.direction;
    const long t = s.selected[d];
    s.export_ok = false;
    if (t < 0 || !s.scene || !s.scene->grid) {
        s.export_status = "no target selected";
        return false;
    }
    const fs::path dir = s.export_dir.empty() ? fs::path(".") : fs::path(s.export_dir);
    const std::string base = "hlens-case-" + std::to_string(t);
    const std::string tp = (dir / (base + "-target.obj")).string(), sp = (dir / (base + "-sources.obj")).string();
    try {
        export_case(*s.scene->grid, d, (uint32_t)t, tp, sp);
        s.export_status = "wrote " + tp + "\nand " + sp;
        s.export_ok = true;
    } catch (const std::exception& e) {
        s.export_status = std::string("export failed: ") + e.what();
    }
    return s.export_ok;
}

}  // namespace

int main(int argc, char** argv) {
    const auto program_start = std::chrono::steady_clock::now();
    // ---- 0. Command line
    Options opt;
    try {
        opt = parse_args(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "hlens: %s\n%s", e.what(), usage_text());
        return 2;
    }
    if (opt.help) {
        std::fputs(usage_text(), stdout);
        return 0;
    }
    AppState s;
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
    const std::string recent_file = s.headless ? "" : config_file("recent.txt");
    if (!recent_file.empty()) s.recent = load_recent(recent_file);
    s.style[0].color[0] = 0.86f, s.style[0].color[1] = 0.62f, s.style[0].color[2] = 0.42f;
    s.style[1].color[0] = 0.55f, s.style[1].color[1] = 0.66f, s.style[1].color[2] = 0.88f;
    set_direction(s, opt.direction);
    s.stepper.event_log = opt.event_log;
    s.stepper.graph_open = opt.graph;
    s.stepper.show_overlay = opt.overlay;
    if (!opt.case_name.empty() && !load_builtin_case(s, opt.case_name, opt.epsilon)) {
        std::fprintf(stderr, "hlens: unknown case '%s'\n%s", opt.case_name.c_str(), usage_text());
        return 2;
    }
    if (!opt.export_dir.empty()) s.export_dir = opt.export_dir;
    s.exact_mode = opt.exact_colormap == 0   ? ExactMode::Off
                   : opt.exact_colormap == 1 ? ExactMode::On
                   : opt.exact_colormap == 2 ? ExactMode::Wait
                   : s.headless              ? ExactMode::Wait
                                             : ExactMode::On;

    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);

    // ---- 1. Window and OpenGL 3.3 core context
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        std::fprintf(stderr, "hlens: cannot initialise GLFW (no display? try: xvfb-run -a -s \"-screen 0 1600x1000x24\" hlens ...)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, s.headless ? GLFW_FALSE : GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, s.headless ? GLFW_FALSE : GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(opt.width, opt.height, "Hausdorff Lens", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "hlens: cannot create an OpenGL 3.3 core window\n");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    if (!s.headless) glfwSetDropCallback(window, on_drop);
    glfwSwapInterval(s.headless ? 0 : 1);

    // ---- 2. Dear ImGui: style, DPI scaling, backends
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    static std::string ini;   // must outlive the context
    ini = !opt.layout_file.empty() ? opt.layout_file : s.headless ? "" : config_file("imgui.ini");
    io.IniFilename = ini.empty() ? nullptr : ini.c_str();
    float dpi = 1.0f;
    if (!s.headless) {
        float sx = 1, sy = 1;
        glfwGetWindowContentScale(window, &sx, &sy);
        dpi = std::max(1.0f, sx);
    }
    apply_dpi_scale(dpi, false);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    glfwSetWindowContentScaleCallback(window, on_content_scale);
    long frame = 0;

    // ---- 3. Renderer, picking, background jobs
    // (unique_ptr: both hold GL objects, so they are released before the context is destroyed)
    auto scene_ptr = std::make_unique<Scene>();
    auto picker_ptr = std::make_unique<Picker>();
    Scene& scene = *scene_ptr;
    Picker& picker = *picker_ptr;
    std::string gl_error;
    if (!scene.init(gl_error) || !picker.init(gl_error)) {
        std::fprintf(stderr, "hlens: %s\n", gl_error.c_str());
        return 1;
    }
    Camera camera;
    ComputeJob compute;
    TraceJob trace;
    ExactMapJob exact_job;   // the exact colour map's fill-in (one direction at a time)
    StatsJob stats_job;      // the exact surface statistics, on request
    // Times in the state are from start-up for the first pair, from the request for later ones.
    auto compute_started = program_start;
    bool first_compute = true;
    auto since_start = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - compute_started).count(); };
    auto start_compute = [&]() {
        exact_job.cancel();   // its values are for the old meshes (dropped when harvested)
        stats_job.cancel();   // (the same)
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
    };
    start_compute();
    long focused_key = -1;   // the stepped target the camera was last framed on
    bool need_home = false, target_applied = opt.target < 0, compute_done = false;
    bool press_in_view[3] = {false, false, false};
    bool press_was_double = false;   // the press of a double-click: its release does not pick
    const std::vector<MouseFrame> script = script_frames(opt.input);
    size_t script_pos = 0;
    int settle = 0, redraw = 3, exit_code = -1;
    bool step_applied = false;

    while (!glfwWindowShouldClose(window) && !g_quit) {
        // ---- 1. Events (interactive and idle: sleep until something happens)
        // (while only the exact colour map fills in, 10 frames a second show its progress and
        // leave the cores to it; input still wakes the loop at once)
        const bool busy = compute.running() || trace.running(), filling = exact_job.running() || stats_job.running();
        if (s.headless || busy || redraw > 0)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(filling ? 0.1 : 0.25);
        if (s.headless && (busy || filling)) std::this_thread::sleep_for(std::chrono::milliseconds(10));   // leave the cores to the jobs
        // A new content scale (the window moved to another screen; --dpi-scale from frame 3 on).
        if (opt.dpi_scale > 0 && frame == 3) g_content_scale = opt.dpi_scale;
        if (g_content_scale > 0 && g_content_scale != dpi) {
            dpi = g_content_scale;
            apply_dpi_scale(dpi, true);
            redraw = 3;
        }
        g_content_scale = 0;
        ++frame;

        // ---- 2. Harvest background jobs
        if (auto sc = compute.take_scene()) {
            s.scene = sc;
            s.trace[0].reset();
            s.trace[1].reset();
            scene.set_meshes(sc->mesh[0], sc->mesh[1]);
            s.up_axis = guess_up_axis(scene.box_lo(), scene.box_hi());
            need_home = true;
        }
        if (auto out = compute.take_result()) {
            compute_done = true;
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
                remember(s.recent, s.path[0], recent_file);
            }
            if (s.computed) {
                // The distances show now; the colour map starts with the triangles fast mode solved
                // exactly, the others "not yet exact" until the fill-in below brings their values.
                s.result = std::move(out->result);
                s.distances_at = since_start();
                for (int d = 0; d < 2; ++d) {
                    init_exact(s, d);
                    show_values(s, scene, d, true);
                }
            }
        }
        // The exact colour map: take the fill-in's new values (for these meshes only), then make
        // sure it runs for the direction shown while that one is incomplete.
        {
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
                if (s.computed && e.complete() && e.complete_at < 0) e.complete_at = since_start();
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
                exact_job.start(s.scene, d, order_by_decreasing_bound(r.target_max, known));
            }
        }
        if (!g_dropped.empty()) {
            s.dropped = std::move(g_dropped);
            g_dropped.clear();
        }
        if (auto tr = trace.take_result())
            if (!tr->cancelled && s.selected[tr->side] == (long)tr->target) {
                // A finished trace is the target's full construction: its maximum is exact.
                if (s.computed && tr->error.empty() && set_exact(s, tr->side, tr->target, tr->max)) {
                    show_values(s, scene, tr->side, false);
                }
                s.trace[tr->side] = std::move(*tr);
            }
        // --target: applied once the meshes are there (out of range is an input error, like hlens-cli's).
        if (!target_applied && s.scene) {
            target_applied = true;
            const size_t n = s.scene->mesh[s.direction].num_triangles();
            if ((size_t)opt.target < n) {
                s.selected[s.direction] = opt.target;
            } else {
                char why[160];
                std::snprintf(why, sizeof why, "target %ld is out of range: mesh %s has %zu triangles", opt.target,
                              s.direction == 0 ? "A" : "B", n);
                s.errors.push_back(AppError{"Bad --target", "", why});
                std::fprintf(stderr, "hlens: %s\n", why);
            }
        }
        // The selected target of the current direction gets its trace (restarted if superseded).
        {
            const int d = s.direction;
            const long t = s.selected[d];
            if (s.scene && s.scene->grid && t >= 0 && !(s.trace[d] && s.trace[d]->target == (uint32_t)t) &&
                !(trace.running() && trace.side() == d && trace.target() == t))
                trace.start(s.scene, d, (uint32_t)t);
        }
        if (opt.step != -1 && s.selected[s.direction] == opt.target && !s.stepper.open && s.stepper.pending == -2 &&
            !step_applied) {   // --step: open the timeline there, once
            step_applied = true;
            s.stepper.open = true;
            s.stepper.pending = opt.step;
        }
        sync_stepper(s);
        s.computing = compute.running();
        s.progress = compute.progress();
        s.phase = compute.phase();
        s.elapsed = compute.elapsed_seconds();
        s.trace_running = trace.running();
        s.exact_running = exact_job.running() && s.scene && exact_job.scene() == s.scene.get();
        s.exact_side = exact_job.side();

        // ---- 3. Start the Dear ImGui frame
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        // Headless: ImGui's clock advances a fixed 1/60 s per frame, so what depends on it (the
        // double-click interval, fades) does not depend on how fast this machine renders.
        if (s.headless) io.DeltaTime = 1.0f / 60.0f;
        // Headless scripted input replaces the backend's mouse state, once the results are in.
        // Frames are consecutive once started (a click's trace must not delay the next input).
        const bool script_running = script_pos < script.size() && compute_done && target_applied &&
                                    (script_pos > 0 || !trace.running());
        // After the script the mouse stays where it ended, buttons up (a hover lasts until the picture).
        const bool script_over = s.headless && !script.empty() && script_pos >= script.size();
        if (script_running || script_over) {
            MouseFrame f = script_running ? script[script_pos++] : MouseFrame{script.back().x, script.back().y, false};
            io.MousePos = f.x < 0 ? ImVec2(-FLT_MAX, -FLT_MAX) : ImVec2(f.x, f.y);
            for (bool& b : io.MouseDown) b = false;
            io.MouseDown[0] = f.down;
            io.MouseDown[1] = f.right;
            io.MouseWheel = f.wheel;
            for (bool& k : io.KeysDown) k = false;
            if (f.key >= 0) io.KeysDown[f.key] = true;
        }
        ImGui::NewFrame();
        int fb_w = 0, fb_h = 0;
        glfwGetFramebufferSize(window, &fb_w, &fb_h);
        layout(s, io.DisplaySize.x, io.DisplaySize.y);
        const float fbs_x = io.DisplayFramebufferScale.x, fbs_y = io.DisplayFramebufferScale.y;
        // The 3D view's rectangle in framebuffer pixels (GL counts rows from the bottom).
        const int vx = (int)std::lround(s.view.x * fbs_x), vw = std::max(1, (int)std::lround(s.view.w * fbs_x));
        const int vh = std::max(1, (int)std::lround(s.view.h * fbs_y));
        const int vy = std::max(0, fb_h - (int)std::lround((s.view.y + s.view.h) * fbs_y));
        const float aspect = float(vw) / float(vh);
        camera.up_axis = s.up_axis;
        if (need_home && scene.loaded()) {
            camera.frame(scene.box_lo(), scene.box_hi(), aspect);
            need_home = false;
        }
        bool input = io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 || ImGui::IsAnyMouseDown() ||
                     io.InputQueueCharacters.Size > 0;
        for (bool k : io.KeysDown) input = input || k;
        redraw = input || s.stepper.playing ? 3 : std::max(0, redraw - 1);

        auto view_params = [&]() {
            ViewParams p;
            p.mvp = camera.projection(aspect) * camera.view();
            p.eye = camera.eye();
            p.viewport[0] = vx;
            p.viewport[1] = vy;
            p.viewport[2] = vw;
            p.viewport[3] = vh;
            p.style[0] = s.style[0];
            p.style[1] = s.style[1];
            p.measured = s.direction;
            p.use_map = s.show_colormap && s.range[s.direction].valid;
            p.lo = s.range[s.direction].lo;
            p.hi = s.range[s.direction].hi;
            p.selected = (int)s.selected[s.direction];
            p.hatch = std::round(hatch_period(ImGui::GetFontSize()) * fbs_x);
            p.tolerance = s.computed ? (float)s.tolerance : -1.0f;
            p.outline = std::max(1.5f, 0.12f * ImGui::GetFontSize() * fbs_x);
            return p;
        };

        // ---- 4. Mouse and keyboard for the 3D view, only when ImGui does not want them
        {
            const ImVec2 m = io.MousePos;
            const bool over_view = !io.WantCaptureMouse && s.view.contains(m.x, m.y) && scene.loaded();
            for (int b = 0; b < 3; ++b)
                if (ImGui::IsMouseClicked(b)) press_in_view[b] = over_view;
            if (ImGui::IsMouseClicked(0)) press_was_double = ImGui::IsMouseDoubleClicked(0);
            // (no mouse: ImGui's position is -FLT_MAX, which does not convert to int)
            const bool mouse_ok = ImGui::IsMousePosValid(&m);
            const int px = mouse_ok ? (int)(m.x * fbs_x) : -1, py = mouse_ok ? fb_h - 1 - (int)(m.y * fbs_y) : -1;
            if (press_in_view[0] && ImGui::IsMouseDown(0)) {
                if (io.KeyShift)
                    camera.pan(io.MouseDelta.x * fbs_x, io.MouseDelta.y * fbs_y, (float)vh);
                else
                    camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
            }
            if ((press_in_view[1] && ImGui::IsMouseDown(1)) || (press_in_view[2] && ImGui::IsMouseDown(2)))
                camera.pan(io.MouseDelta.x * fbs_x, io.MouseDelta.y * fbs_y, (float)vh);
            if (over_view && io.MouseWheel != 0) camera.zoom(io.MouseWheel);
            if (over_view && ImGui::IsMouseDoubleClicked(0)) {   // recentre on the surface point there
                PickHit hit = picker.pick(scene, view_params(), 3u, fb_w, fb_h, px, py);
                if (hit.mesh >= 0) camera.pivot = hit.point;
            }
            // A click picks when it ends, and only if the mouse did not travel (not the end of a drag).
            const float thr = io.MouseDragThreshold;
            if (ImGui::IsMouseReleased(0) && press_in_view[0] && !press_was_double &&
                io.MouseDragMaxDistanceSqr[0] < thr * thr && s.view.contains(m.x, m.y)) {
                PickHit hit = picker.pick(scene, view_params(), 1u << s.direction, fb_w, fb_h, px, py);
                s.req.select = hit.mesh == s.direction ? hit.triangle : -1;
            }
            for (int b = 0; b < 3; ++b)
                if (ImGui::IsMouseReleased(b)) press_in_view[b] = false;
            if (!io.WantCaptureKeyboard && !io.WantTextInput) {   // never while typing in a text field
                if (ImGui::IsKeyPressed(GLFW_KEY_F1, false)) s.help_open = !s.help_open;
                if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) s.req.home = true;
                if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) s.req.focus = true;
                if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) s.req.screenshot = true;
            }
        }

        // ---- 5. Panels and the view overlay
        const ViewParams params = view_params();
        draw_panels(s);
        draw_view_overlay(s, scene, params.mvp);

        // ---- 6. Act on the panels' requests
        Requests req = s.req;
        s.req = Requests{};
        s.req.screenshot = req.screenshot;   // handled after rendering (step 8)
        if (req.cancel) compute.cancel();
        if (req.exact_cancel && exact_job.running()) {
            exact_job.cancel();
            s.exact[exact_job.side()].stopped = true;
        }
        if (req.exact_resume) {
            s.exact[s.direction].stopped = false;
            s.exact[s.direction].failed.clear();
        }
        if (req.load) {   // a new pair from the file panel or dropped files
            for (int side = 0; side < 2; ++side) {
                s.path[side] = s.edit_path[side] = req.load_path[side];
                s.name[side] = fs::path(s.path[side]).filename().string();
            }
            s.demo = s.path[0] == s.demo_path[0] && s.path[1] == s.demo_path[1];
            s.case_loaded = false;
            s.errors.clear();
            s.selected[0] = s.selected[1] = -1;
            s.trace[0].reset();
            s.trace[1].reset();
            s.scene.reset();
            scene.clear();
            req.recompute = true;
        }
        if (!req.load_case.empty() && load_builtin_case(s, req.load_case, req.case_eps)) {
            scene.clear();
            set_direction(s, 0);
            s.selected[0] = 0;   // target 0 of A
            req.recompute = true;
        }
        if (req.export_case) export_selected(s);
        if (update_stats(s, req, stats_job) || req.colours)
            for (int d = 0; d < 2 && s.computed; ++d) show_values(s, scene, d, true);
        if ((req.export_errors || (s.errors_pending && s.stats.ready())) && s.computed && !export_error_maps(s)) {
            std::fprintf(stderr, "hlens: %s\n", s.errors_status.c_str());
            if (s.headless && !opt.export_errors.empty()) {
                exit_code = 2;
                break;
            }
        }
        if (req.recompute) {
            s.computed = s.cancelled = false;
            s.range[0].valid = s.range[1].valid = false;   // (start_compute clears the exact maps)
            compute_done = false;
            start_compute();
        }
        if (req.home && scene.loaded()) camera.frame(scene.box_lo(), scene.box_hi(), aspect);
        // Opening the timeline of a target (or stepping another one) frames it, with room for the
        // sphere of its largest distance, so the voxels and the search radius are visible.
        {
            const long key = s.stepper.open && s.stepper.active() ? s.stepper.side * (1L << 40) + s.stepper.target : -1;
            if (key != focused_key && key >= 0) req.focus = true;
            focused_key = key;
        }
        Vec3 centroid;
        double reach = 0;
        if (req.focus && scene.loaded() && selected_target_ball(s, centroid, reach)) {
            const int d = s.direction;
            bool exact = false;
            const double tmax = s.computed ? target_value(s, d, s.selected[d], exact) : 0;
            const float half = (float)(1.15 * (reach + (std::isfinite(tmax) ? tmax : 0.0))) + 1e-6f;
            const glm::vec3 g = scene.local(centroid);
            camera.focus(g - glm::vec3(half), g + glm::vec3(half), aspect);
        }
        if (req.clear_errors) s.errors.clear();
        if (req.set_direction >= 0) set_direction(s, req.set_direction);
        if (req.select >= -1) s.selected[s.direction] = req.select;

        // ---- 7. Render: the 3D view, then ImGui on top
        glViewport(0, 0, fb_w, fb_h);
        glClearColor(kClearColor[0], kClearColor[1], kClearColor[2], kClearColor[3]);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        scene.draw(params);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        // ---- 8. Screenshots: read the back buffer before it is swapped
        if (s.req.screenshot) {
            s.req.screenshot = false;
            std::string name = timestamped_png_name();
            s.status = save_framebuffer_png(name, fb_w, fb_h) ? "saved " + name : "could not write " + name;
        }
        if (s.headless) {
            const int d = s.direction;
            const long t = s.selected[d];
            const bool errored = !s.errors.empty();
            const bool traced = (t < 0 || (s.trace[d] && s.trace[d]->target == (uint32_t)t)) &&
                                (opt.step == -1 || step_applied || errored);
            // --exact-colormap wait (the default): the fill-in of the direction shown has ended
            // (complete, stopped or failed; a stopped run's targets in progress have landed).
            const ExactMap& em = s.exact[d];
            const bool filled = s.exact_mode != ExactMode::Wait || !s.computed ||
                                ((em.complete() || em.stopped || !em.failed.empty()) && !exact_job.running());
            // Statistics asked for: they have arrived (or were cancelled, or failed).
            const StatsView& sv = s.stats;
            const bool stats_done = !sv.wanted || !s.computed || ((sv.ready() || sv.cancelled || !sv.failed.empty()) && !stats_job.running());
            const bool ready = compute_done && !compute.running() &&
                               (errored || (target_applied && script_pos >= script.size() && traced && !trace.running() && filled && stats_done));
            if (!ready) settle = 0;
            if (ready && ++settle > 4) {   // a few frames for ImGui windows to size themselves
                if (!opt.export_dir.empty() && !errored && !export_selected(s)) {
                    std::fprintf(stderr, "hlens: %s\n", s.export_status.c_str());
                    exit_code = 2;
                    break;
                }
                if (!save_framebuffer_png(opt.screenshot, fb_w, fb_h)) {
                    std::fprintf(stderr, "hlens: %s: cannot write the PNG\n", opt.screenshot.c_str());
                    exit_code = 1;
                } else {
                    exit_code = s.errors.empty() ? 0 : 2;
                    std::string probes;   // (after the PNG: the ID pass does not touch the window's buffers)
                    if (exit_code == 0 && scene.loaded() && s.computed) {
                        const std::vector<int> ids = picker.triangle_ids(scene, params, d, fb_w, fb_h);
                        probes = probes_json(s, ids, params.viewport, fb_h, params.mvp, scene, fbs_x,
                                             (int)std::lround(1.5f * ImGui::GetFontSize() * fbs_x), 4);
                    }
                    if (exit_code == 0)
                        std::printf("%s\n", state_json(s, camera, scene.origin(), fb_w, fb_h, params.viewport, probes).c_str());
                }
                break;
            }
        }

        // ---- 9. Present
        glfwSwapBuffers(window);
    }

    // ---- Clean-up: stop the jobs first (they may still be reading the meshes)
    compute.cancel();
    trace.cancel();
    exact_job.cancel();
    stats_job.cancel();
    picker_ptr.reset();
    scene_ptr.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    std::fflush(stdout);
    if (s.headless && exit_code < 0) {
        std::fprintf(stderr, "hlens: the window was closed before the screenshot was taken\n");
        return 1;
    }
    return s.headless ? exit_code : 0;
}
