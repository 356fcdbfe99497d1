#include "state_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include <imgui.h>

#include "exact_map.h"
#include "json_value.h"
#include "report.h"
#include "stats_flow.h"

namespace hlens::gui {

namespace {

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
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

// The exact colour map of the measured mesh, its range and where the colour bar is.
std::string colormap_json(const AppState& s, const std::string& probes) {
    const int d = s.direction;
    const ExactMap& m = s.exact[d];
    const ColourRange& r = s.range[d];
    const char* mode = s.exact_mode == ExactMode::Off ? "off" : s.exact_mode == ExactMode::On ? "on" : "wait";
    const float fx = ImGui::GetIO().DisplayFramebufferScale.x;
    std::string j = ", \"exact_colormap\": {\"mode\": \"" + std::string(mode) + "\", \"color_by\": \"" +
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
    return j;
}

// The timeline's state: "step" is the current event (-1: none yet); the domain view, the graph,
// the overlay and the event log as drawn.
std::string step_json(const Stepper& st) {
    std::string j;
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
    if (const auto d = degenerate_target(st.solver->frame()))
        j += ", \"degenerate_target\": {\"kind\": \"" + std::string(d->kind) + "\", \"height\": " + json_number(d->height) +
             ", \"longest_edge\": " + json_number(d->longest_edge) + "}";
    else
        j += ", \"degenerate_target\": null";
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
    return j;
}

// Where probes must not be (image coordinates): the target panel, the witness markers (segment,
// points and label, as draw_view_overlay draws them, with a margin), the hint line.
struct Excluded {
    float fs = 0;                                // the font size (framebuffer pixels)
    std::vector<std::array<float, 4>> rects;     // x0, y0, x1, y1
    std::vector<std::array<float, 4>> segments;  // the witnesses' segments
    // (x, y) with a margin m: in a rectangle, or within a marker's radius (plus m) of a segment.
    bool contains(float x, float y, int m) const {
        for (const auto& b : rects)
            if (x >= b[0] - m && x < b[2] + m && y >= b[1] - m && y < b[3] + m) return true;
        for (const auto& g : segments) {
            const float dx = g[2] - g[0], dy = g[3] - g[1], len2 = dx * dx + dy * dy;
            const float u = len2 > 0 ? std::clamp(((x - g[0]) * dx + (y - g[1]) * dy) / len2, 0.0f, 1.0f) : 0.0f;
            if (std::hypot(x - g[0] - u * dx, y - g[1] - u * dy) < 0.6f * fs + 1.5f * m) return true;
        }
        return false;
    }
};

Excluded excluded_zones(const AppState& s, const int vp[4], int fb_h, const glm::mat4& mvp, const Scene& scene, float fbs) {
    Excluded e;
    e.fs = ImGui::GetFontSize() * fbs;
    const float fs = e.fs;
    const int w = vp[2], h = vp[3];
    std::vector<std::array<float, 4>>& rects = e.rects;
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
            e.segments.push_back({q[0][0], q[0][1], q[1][0], q[1][1]});
            const float rr = 0.38f * fs;   // the label's box (draw_view_overlay)
            const ImVec2 ls = ImGui::CalcTextSize("h(A,B)");
            rects.push_back({q[0][0] + 1.6f * rr - 4, q[0][1] - 2.6f * rr - 2, q[0][0] + 1.6f * rr + ls.x * fbs + 4,
                             q[0][1] - 2.6f * rr + ls.y * fbs + 2});
        }
    return e;
}

}  // namespace

std::string probes_json(const AppState& s, const std::vector<int>& ids, const int vp[4], int fb_h, const glm::mat4& mvp,
                        const Scene& scene, float fbs, int max_clear, int per_kind) {
    const int d = s.direction, w = vp[2], h = vp[3];
    const int kmax = max_clear + 2;
    const Excluded excluded = excluded_zones(s, vp, fb_h, mvp, scene, fbs);
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
            if (k < 4 || excluded.contains((float)ix, (float)iy, k)) continue;
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
    j += colormap_json(s, probes);
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
    j += st.open && st.active() ? step_json(st) : ", \"step\": null";
    j += "}";
    return j;
}

}  // namespace hlens::gui
