#include "stats_panel.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui.h"

namespace hlens::gui {

namespace {

const char* kDir[2] = {"h(A,B): A measured against B", "h(B,A): B measured against A"};

void value_row(const char* label, double v, const char* tooltip) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", label);
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%.10g", v);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%.17g", tooltip, v);
}

// The histogram (area per distance bin) as a plot, with the bin under the mouse in a tooltip.
void histogram_plot(const SurfaceStats& st) {
    if (st.histogram_area.empty()) return;
    std::vector<float> a(st.histogram_area.begin(), st.histogram_area.end());
    ImGui::PlotHistogram("##hist", a.data(), (int)a.size(), 0, nullptr, 0.0f, FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 3.5f * em()));
    if (ImGui::IsItemHovered()) {
        const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
        const int k = (int)((ImGui::GetIO().MousePos.x - lo.x) / std::max(1.0f, hi.x - lo.x) * (float)a.size());
        if (k >= 0 && k < (int)a.size())
            ImGui::SetTooltip("distance %.6g .. %.6g: area %.6g (%.2f%%)", st.histogram_edges[k], st.histogram_edges[k + 1],
                              st.histogram_area[k], 100.0 * st.histogram_area[k] / std::max(1e-300, st.area));
    }
    ImGui::TextDisabled("area by distance: %zu bins to %.4g", a.size(), st.histogram_edges.back());
}

void direction_stats(const SurfaceStats& st, int d) {
    ImGui::PushID(d);
    ImGui::TextUnformatted(kDir[d]);
    if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 4.5f * em());
        value_row("area", st.area, "area of the measured mesh (slivers left out)");
        value_row("mean", st.mean(), "mean distance over the surface (area-weighted)");
        value_row("RMS", st.rms(), "root mean square distance (exact integral of d^2)");
        static const char* names[] = {"50%", "90%", "95%", "99%"};
        for (size_t k = 0; k < st.percentiles.size() && k < 4; ++k)
            value_row(names[k], st.percentiles[k], "that share of the area is at most this far (to 1e-9 of the diagonal)");
        ImGui::EndTable();
    }
    histogram_plot(st);
    ImGui::PopID();
}

// Progress with Cancel, or the button that starts (or restarts) the computation.
void stats_controls(AppState& s) {
    const StatsView& v = s.stats;
    if (v.running) {
        char overlay[96];
        std::snprintf(overlay, sizeof overlay, "%s %.0f%%", v.phase.c_str(), 100 * std::max(0.0, v.progress));
        ImGui::ProgressBar((float)std::max(0.0, v.progress), ImVec2(-6 * em(), 0), overlay);
        ImGui::SameLine();
        if (ImGui::Button("Cancel##stats", ImVec2(-1, 0))) s.req.stats_cancel = true;
        return;
    }
    const bool stale = v.ready() && v.tolerance != s.tolerance && s.tolerance >= 0;
    if (!v.ready() || stale) {
        if (ImGui::Button(stale ? "Recompute statistics at the tolerance" : "Compute statistics", ImVec2(-1, 0)))
            s.req.stats_start = true;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("exact mean, RMS, percentiles and histogram of both directions:\n"
                              "every triangle's full construction (slow on large meshes), in the background");
    }
    if (v.cancelled && !v.ready()) ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "statistics cancelled");
    if (!v.failed.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "statistics failed: %s", v.failed.c_str());
}

void export_controls(AppState& s) {
    ImGui::SetNextItemWidth(-7 * em());
    ImGui::InputText("##errors_path", &s.errors_path);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("PATH.ply: writes PATH-ab.ply (A's error map) and PATH-ba.ply (B's)");
    ImGui::SameLine();
    if (ImGui::Button("Export map", ImVec2(-1, 0))) s.req.export_errors = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the error map as hlens-cli --export-errors writes it: per-face max, mean and RMS\n"
                          "distance, per-vertex distance (\"quality\": MeshLab's scalar fields)");
    if (!s.errors_status.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, s.errors_ok ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled) : ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("%s", s.errors_status.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace

void draw_stats_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!s.computed) {
        ImGui::TextDisabled("available once the distances are computed");
        return;
    }
    stats_controls(s);
    if (!s.stats.ready()) return;
    for (int d = 0; d < 2; ++d) direction_stats(*s.stats.dir[d], d);
    export_controls(s);
}

}  // namespace hlens::gui
