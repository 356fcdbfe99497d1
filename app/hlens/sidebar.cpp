// The sidebar: the files, the computation's progress, then one section after another (each in
// its own file, declared in panels.h), and the last status message.
#include "panels.h"

#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "stats_panel.h"
#include "tolerance_panel.h"
#include "ui.h"

namespace hlens::gui {

namespace {

void files_section(AppState& s) {
    for (int side = 0; side < 2; ++side) {
        ImGui::Text("%s:", kSide[side]);
        ImGui::SameLine();
        ImGui::TextUnformatted(s.name[side].c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.path[side].c_str());
        if (s.scene) {
            const TriangleMesh& m = s.scene->mesh[side];
            ImGui::SameLine();
            ImGui::TextDisabled("%zu tri, %zu vert", m.num_triangles(), m.num_used_vertices());
        }
    }
}

void progress_section(AppState& s) {
    if (s.computing) {
        char overlay[128];
        if (s.progress >= 0)
            std::snprintf(overlay, sizeof overlay, "%s  %.0f%%  %.1f s", s.phase.c_str(), 100 * s.progress, s.elapsed);
        else
            std::snprintf(overlay, sizeof overlay, "%s  %.1f s", s.phase.c_str(), s.elapsed);
        float frac = s.progress >= 0 ? (float)s.progress : (float)std::fmod(s.elapsed * 0.5, 1.0);
        ImGui::ProgressBar(frac, ImVec2(-6 * em(), 0), overlay);
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(-1, 0))) s.req.cancel = true;
    } else if (s.computed) {
        ImGui::TextDisabled("Computed in %.2f s", s.result.seconds);
        ImGui::SameLine(ImGui::GetContentRegionAvail().x - 6 * em());
        if (ImGui::Button("Recompute", ImVec2(-1, 0))) s.req.recompute = true;
    } else if (s.cancelled) {
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "Cancelled");
        ImGui::SameLine(ImGui::GetContentRegionAvail().x - 6 * em());
        if (ImGui::Button("Recompute", ImVec2(-1, 0))) s.req.recompute = true;
    } else if (!s.errors.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "Not loaded (see the error panel)");
    }
}

void direction_section(AppState& s) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Measure");
    ImGui::SameLine();
    int dir = s.direction;
    if (ImGui::RadioButton("A to B", &dir, 0)) s.req.set_direction = 0;
    ImGui::SameLine();
    if (ImGui::RadioButton("B to A", &dir, 1)) s.req.set_direction = 1;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the measured mesh carries the colour map and the targets");
}

}  // namespace

void draw_sidebar(AppState& s) {
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(s.sidebar_width, ImGui::GetIO().DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("Hausdorff Lens", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    files_section(s);
    progress_section(s);
    draw_distances_section(s);
    ImGui::Separator();
    direction_section(s);
    draw_colormap_section(s);
    draw_stats_section(s);
    draw_tolerance_section(s);
    draw_meshes_section(s);
    draw_open_section(s);
    draw_cases_section(s);
    draw_help_section();
    if (!s.status.empty()) {
        ImGui::Separator();
        ImGui::TextDisabled("%s", s.status.c_str());
    }
    ImGui::End();
}

}  // namespace hlens::gui
