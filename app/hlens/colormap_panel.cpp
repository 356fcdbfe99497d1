// The sidebar's colour map section: its range (following the exact values known, until moved),
// the colour bar, the exact colour map's fill-in (legend of the "not yet exact" triangles,
// progress, Cancel / Continue) and what is shown per triangle (max, mean or RMS).
#include "panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "colormap.h"
#include "ui.h"

namespace hlens::gui {

namespace {

// 12,345
std::string with_commas(size_t n) {
    std::string d = std::to_string(n), out;
    for (size_t i = 0; i < d.size(); ++i) {
        if (i && (d.size() - i) % 3 == 0) out += ',';
        out += d[i];
    }
    return out;
}

// A swatch of the "not yet exact" hatch, as the 3D view draws it (mesh.frag.glsl): the two greys in
// diagonal stripes of period hatch_period(font size) along x.
void hatch_swatch(float w, float h) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    auto grey = [](float g) {
        const int v = (int)std::lround(g * 255);
        return IM_COL32(v, v, v, 255);
    };
    dl->AddRectFilled(p, ImVec2(p.x + w, p.y + h), grey(kNotExactGrey[0]));
    dl->PushClipRect(p, ImVec2(p.x + w, p.y + h), true);
    const float period = hatch_period(em());
    for (float x = p.x - h - period; x < p.x + w + period; x += period)   // lines of slope +1 (screen)
        dl->AddLine(ImVec2(x + 0.25f * period, p.y), ImVec2(x + 0.25f * period + h, p.y + h), grey(kNotExactGrey[1]),
                    0.5f * period / std::sqrt(2.0f));
    dl->PopClipRect();
    dl->AddRect(p, ImVec2(p.x + w, p.y + h), IM_COL32(0, 0, 0, 255));
    ImGui::Dummy(ImVec2(w, h));
}

void colour_bar(AppState& s, const ColourRange& r) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 p = ImGui::GetCursorScreenPos();
    float w = ImGui::GetContentRegionAvail().x, h = 1.1f * em();
    s.colour_bar_rect[0] = p.x, s.colour_bar_rect[1] = p.y, s.colour_bar_rect[2] = w, s.colour_bar_rect[3] = h;
    const auto& table = colormap_table();
    const int n = 64;
    for (int i = 0; i < n; ++i) {
        auto c0 = table[(size_t)i * (kColormapSize - 1) / n];
        auto c1 = table[(size_t)(i + 1) * (kColormapSize - 1) / n];
        ImU32 a = IM_COL32(c0[0], c0[1], c0[2], 255), b = IM_COL32(c1[0], c1[1], c1[2], 255);
        float x0 = p.x + w * i / n, x1 = p.x + w * (i + 1) / n;
        dl->AddRectFilledMultiColor(ImVec2(x0, p.y), ImVec2(x1, p.y + h), a, b, b, a);
    }
    dl->AddRect(p, ImVec2(p.x + w, p.y + h), IM_COL32(0, 0, 0, 255));
    ImGui::Dummy(ImVec2(w, h));
    // Tick labels: low, middle, high.
    char lo[32], mid[32], hi[32];
    std::snprintf(lo, sizeof lo, "%.4g", r.lo);
    std::snprintf(mid, sizeof mid, "%.4g", 0.5 * (r.lo + r.hi));
    std::snprintf(hi, sizeof hi, "%.4g", r.hi);
    float y = ImGui::GetCursorPosY();
    float x0 = ImGui::GetCursorPosX();
    ImGui::TextUnformatted(lo);
    ImGui::SetCursorPos(ImVec2(x0 + 0.5f * (w - ImGui::CalcTextSize(mid).x), y));
    ImGui::TextUnformatted(mid);
    s.colour_bar_hi_label = s.units.empty() ? std::string(hi) : std::string(hi) + " " + s.units;
    ImGui::SetCursorPos(ImVec2(x0 + w - ImGui::CalcTextSize(s.colour_bar_hi_label.c_str()).x, y));
    ImGui::TextUnformatted(s.colour_bar_hi_label.c_str());
}

// The exact colour map's state for direction d: the legend of the grey triangles, the fill-in's
// progress with Cancel, or why it is not running.
void exact_section(AppState& s) {
    const int d = s.direction;
    const ExactMap& m = s.exact[d];
    const size_t n = m.value.size();
    if (n == 0) return;
    // (once cancelled it shows as stopped, though the targets in progress still finish)
    const bool running = s.exact_running && s.exact_side == d && !m.stopped;
    if (!m.complete()) {
        hatch_swatch(2.2f * em(), 1.1f * em());
        ImGui::SameLine();
        ImGui::TextWrapped("not yet exact: %s of %s triangles (their exact maximum is still unknown; not coloured by a bound)",
                           with_commas(n - m.exact).c_str(), with_commas(n).c_str());
    }
    const std::string counts = with_commas(m.exact) + " / " + with_commas(n) + " triangles";
    auto disabled_wrapped = [](const std::string& text) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", text.c_str());
        ImGui::PopStyleColor();
    };
    const bool stopped = !running && m.stopped && !m.complete() && m.failed.empty() && s.exact_mode != ExactMode::Off;
    if (running || stopped) {   // Cancel and Continue take the same place
        ImGui::TextWrapped("exact colour map: %s", counts.c_str());
        char pct[48];
        std::snprintf(pct, sizeof pct, "%s%.0f%%", stopped ? "stopped at " : "", 100.0 * m.exact / n);
        ImGui::ProgressBar((float)m.exact / (float)n, ImVec2(-6 * em(), 0), pct);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the exact maximum over every triangle the fast computation skipped,\n"
                              "computed in the background, largest upper bound first");
        ImGui::SameLine();
        if (running && ImGui::Button("Cancel##exact", ImVec2(-1, 0))) s.req.exact_cancel = true;
        if (stopped && ImGui::Button("Continue##exact", ImVec2(-1, 0))) s.req.exact_resume = true;
        if (stopped && ImGui::IsItemHovered()) ImGui::SetTooltip("continue filling in the exact colour map");
    } else if (m.complete()) {
        disabled_wrapped("exact colour map: every triangle exact (" + with_commas(n) + ")");
    } else if (!m.failed.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("exact colour map failed: %s", m.failed.c_str());
        ImGui::PopStyleColor();
    } else if (s.exact_mode == ExactMode::Off) {
        disabled_wrapped("exact colour map: off (--exact-colormap off); " + counts + " exact");
    } else {
        disabled_wrapped("exact colour map: " + counts);
    }
}

// What the colour map shows per triangle: the exact maximum, or the mean or RMS distance over
// the triangle (from the statistics, computed when first asked for).
void colour_by_combo(AppState& s) {
    static const char* items[3] = {"max distance", "mean distance", "RMS distance"};
    int c = (int)s.colour_by;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("per triangle");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::Combo("##colour_by", &c, items, 3) && c != (int)s.colour_by) {
        s.colour_by = (ColourBy)c;
        s.req.colours = true;
        if (s.colour_by != ColourBy::Max && !s.stats.ready() && !s.stats.running) s.req.stats_start = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the exact maximum over each triangle, or the exact mean or RMS over it\n"
                                                  "(these need the statistics: every triangle's full construction)");
    if (s.colour_by != ColourBy::Max && !s.stats.ready())
        ImGui::TextDisabled("%s: once the statistics are computed; max until then", items[(int)s.colour_by]);
}

}  // namespace

void draw_colormap_section(AppState& s) {
    const int d = s.direction;
    static const char* kQuantity[3] = {"max", "mean", "RMS"};
    const bool by_stats = s.colour_by != ColourBy::Max && s.stats.ready();
    char title[96];
    std::snprintf(title, sizeof title, "Colour map: %s distance on %s###colormap", kQuantity[by_stats ? (int)s.colour_by : 0], kSide[d]);
    if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    ColourRange& r = s.range[d];
    if (!r.valid) {
        ImGui::TextDisabled("available once h(%s,%s) is computed", kSide[d], kSide[1 - d]);
        return;
    }
    ImGui::Checkbox("show", &s.show_colormap);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-4.5f * em());
    float speed = std::max(1e-6f, (r.data_hi - r.data_lo) * 0.002f);
    ImGui::DragFloatRange2("##range", &r.lo, &r.hi, speed, 0, 0, "%.5g", "%.5g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("colour map range (drag, or double-click to type)");
    ImGui::SameLine();
    if (ImGui::Button("Reset", ImVec2(-1, 0))) {
        r.lo = r.data_lo;
        r.hi = r.data_hi;
    }
    colour_bar(s, r);
    exact_section(s);
    colour_by_combo(s);   // (below: the fill-in's Cancel keeps its place)
}

}  // namespace hlens::gui
