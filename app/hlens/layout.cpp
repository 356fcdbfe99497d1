#include "layout.h"

#include <algorithm>
#include <cmath>

#include "ui.h"

namespace hlens::gui {

void place_tile(const AppState::Tile& t) {
    ImGui::SetNextWindowPos(ImVec2(t.r.x, t.r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(t.r.w, t.r.h), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(t.lo_w, t.lo_h), ImVec2(t.hi_w, t.hi_h));
}

bool begin_tile(const char* title, const AppState::Tile& t, bool& shown, int flags) {
    place_tile(t);
    bool open = true;
    const bool visible = ImGui::Begin(title, &open, kTileFlags | flags);
    shown = open;
    if (!visible) ImGui::End();
    return visible;
}

void layout(AppState& s, float display_w, float display_h) {
    const float e = em();
    s.sidebar_width = std::min(std::round(23 * e), std::round(0.6f * display_w));
    const ViewRect area{s.sidebar_width, 0, std::max(1.0f, display_w - s.sidebar_width), std::max(1.0f, display_h)};
    AppState::Tiles& t = s.tiles;
    const Stepper& st = s.stepper;
    t.on = st.open && st.active();
    t.graph_on = t.on && st.graph_open;
    t.log_on = t.on && st.event_log;
    if (!t.on) {
        s.view = area;
        return;
    }
    // A tile's free dimension: the chosen size (or the default) within [lo, hi].
    auto pick = [](float chosen, float def, float lo, float hi) {
        hi = std::max(lo, hi);
        return std::max(lo, std::min(chosen > 0 ? chosen : def, hi));
    };
    auto pinned = [](AppState::Tile& tile) {
        tile.lo_w = tile.hi_w = tile.r.w;
        tile.lo_h = tile.hi_h = tile.r.h;
    };
    // Timeline at the bottom, full width (pinned).
    // (as tall as its contents were on the last frame: its toolbar wraps in narrow windows)
    const float tl_h = std::min(std::round(t.timeline_need > 0 ? std::max(5 * e, t.timeline_need) : 8.5f * e), 0.45f * area.h);
    t.timeline.r = ViewRect{area.x, area.y + area.h - tl_h, area.w, tl_h};
    pinned(t.timeline);
    // Domain view on the left above it; its right edge is the user's.
    const float up_h = std::max(1.0f, area.h - tl_h);
    const float dv_lo = std::min(24 * e, 0.5f * area.w), dv_hi = area.w - std::min(16 * e, 0.3f * area.w);
    const float dv_w = pick(t.domain_w, std::min(0.55f * area.w, up_h + 13 * e), dv_lo, dv_hi);
    t.domain.r = ViewRect{area.x, area.y, dv_w, up_h};
    pinned(t.domain);
    t.domain.lo_w = dv_lo, t.domain.hi_w = std::max(dv_lo, dv_hi);
    // The 3D view on the right, above a strip with the graph (left) and the event log (right).
    ViewRect right{area.x + dv_w, area.y, std::max(1.0f, area.w - dv_w), up_h};
    if (t.graph_on || t.log_on) {
        const float sh_lo = std::min(8 * e, 0.3f * right.h), sh_hi = right.h - std::min(8 * e, 0.3f * right.h);
        const float sh = pick(t.strip_h, 0.45f * right.h, sh_lo, sh_hi);
        const float y = right.y + right.h - sh;
        float gw = t.log_on ? 0 : right.w;
        const float gw_lo = std::min(12 * e, 0.3f * right.w), gw_hi = right.w - std::min(12 * e, 0.3f * right.w);
        if (t.graph_on && t.log_on) gw = pick(t.graph_w, 0.55f * right.w, gw_lo, gw_hi);
        t.graph.r = ViewRect{right.x, y, gw, sh};
        t.log.r = ViewRect{right.x + gw, y, right.w - gw, sh};
        pinned(t.graph);
        pinned(t.log);
        // The strip's top edge belongs to the graph when it is open, else to the event log; the
        // graph's right edge too when the log shares the strip.
        AppState::Tile& top = t.graph_on ? t.graph : t.log;
        top.lo_h = sh_lo, top.hi_h = std::max(sh_lo, sh_hi);
        if (t.graph_on && t.log_on) t.graph.lo_w = gw_lo, t.graph.hi_w = std::max(gw_lo, gw_hi);
        right.h = std::max(1.0f, right.h - sh);
    }
    s.view = right;
}

}  // namespace hlens::gui
