// The target panel: the selected target T' (index, its maximum, exact or a bound), "Step through"
// and its trace's summary, in its own window at the top-right of the 3D view.
#include "panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui.h"

namespace hlens::gui {

namespace {

void target_contents(AppState& s) {
    const int d = s.direction;
    const long n = (long)s.scene->mesh[d].num_triangles();
    int index = (int)s.selected[d];
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("index");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(8 * em());
    if (ImGui::InputInt("##index", &index, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (index >= 0 && index < n) s.req.select = index;
    }
    ImGui::SameLine();
    if (ImGui::Button("Clear", ImVec2(-1, 0))) s.req.select = -1;
    if (s.selected[d] < 0) {
        ImGui::TextDisabled("Click a triangle of %s.", kSide[d]);
        return;
    }
    const long t = s.selected[d];
    if (ImGui::BeginTable("target", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 6 * em());
        const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
        if (s.computed && s.exact[d].known(t)) {
            row("target_max", fmt("%.17g", s.exact[d].value[t]), "max distance over T' (exact)");
            row("", (size_t)t < r.target_exact.size() && r.target_exact[t] ? "exact" : "exact (colour map fill-in)");
        } else if (s.computed && (size_t)t < r.target_max.size()) {
            row("target_max", fmt("%.17g", r.target_max[t]),
                "fast mode skipped this target: an upper bound, below the result;\n"
                "its exact value comes with the exact colour map (or the trace below)");
            row("", "upper bound (not yet exact)");
        }
        ImGui::EndTable();
    }
    if (ImGui::Button(s.stepper.open ? "Close timeline" : "Step through (timeline & domain view)", ImVec2(-1, 0)))
        s.stepper.open = !s.stepper.open;
    ImGui::TextUnformatted("Trace (TargetSolver)");
    if (s.trace_running && (!s.trace[d] || s.trace[d]->target != (uint32_t)t)) {
        ImGui::SameLine();
        ImGui::TextDisabled("running...");
        return;
    }
    if (!s.trace[d] || s.trace[d]->target != (uint32_t)t) return;
    const TraceSummary& tr = *s.trace[d];
    if (!tr.error.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "failed: %s", tr.error.c_str());
        return;
    }
    if (s.tiles.on) {   // the timeline is open: one line, to leave the small 3D view visible
        ImGui::SameLine();
        ImGui::TextDisabled("%d ins., %.3f s", tr.insertions, tr.seconds);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the whole construction: %d insertions, %d domains, %d arcs, %d vertices;\nmax %.17g",
                              tr.insertions, tr.domains, tr.arcs, tr.vertices, tr.max);
        return;
    }
    if (ImGui::BeginTable("trace", 4, ImGuiTableFlags_SizingFixedFit)) {
        auto cell = [](const char* k, long v) {
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", k);
            ImGui::TableNextColumn();
            ImGui::Text("%ld", v);
        };
        cell("insertions", tr.insertions);
        cell("domains", tr.domains);
        cell("arcs", tr.arcs);
        cell("vertices", tr.vertices);
        ImGui::EndTable();
    }
    if (ImGui::BeginTable("tracemax", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 6 * em());
        row("max", fmt("%.17g", tr.max), "sqrt of the maximum of d^2 over T'");
        row("time", fmt("%.3f s", tr.seconds));
        ImGui::EndTable();
    }
    if (tr.degenerate) ImGui::TextDisabled("degenerate target: handled as its edges");
    if (tr.cancelled) ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "cancelled");
}

}  // namespace

// The target panel: its own window at the top-right of the view, so it stays visible whatever the
// sidebar's scroll position (the domain view, timeline and event log will sit next to it).
void draw_target_window(AppState& s) {
    if (!s.scene) return;
    const int d = s.direction;
    const ViewRect& v = s.view;
    const float w = std::min((s.tiles.on ? 17 : 19) * em(), 0.5f * v.w);
    ImGui::SetNextWindowPos(ImVec2(v.x + v.w - 0.5f * em(), v.y + 0.5f * em()), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowSize(ImVec2(w, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.88f);
    char title[64];
    std::snprintf(title, sizeof title, "Target T' (a triangle of %s)###target", kSide[d]);
    ImGui::Begin(title, nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    target_contents(s);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    s.target_window = ViewRect{pos.x, pos.y, size.x, size.y};
    ImGui::End();
}

}  // namespace hlens::gui
