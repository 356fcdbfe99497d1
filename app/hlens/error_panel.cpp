// The error panel over the 3D view: every error (loading, computing, bad input) with its file and
// reason; "Dismiss" clears them.
#include "panels.h"

#include <algorithm>

#include <imgui.h>

#include "ui.h"

namespace hlens::gui {

void draw_error_panel(AppState& s) {
    if (s.errors.empty()) return;
    const ViewRect& v = s.view;
    ImGui::SetNextWindowPos(ImVec2(v.x + 0.5f * v.w, v.y + 0.4f * v.h), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(34 * em(), v.w - 2 * em()), 0), ImGuiCond_Always);
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(kErrorBg[0], kErrorBg[1], kErrorBg[2], kErrorBg[3]));
    ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.70f, 0.15f, 0.15f, 1));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.70f, 0.15f, 0.15f, 1));
    ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1, 0.5f, 0.5f, 1));
    ImGui::Begin("Error", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    for (size_t i = 0; i < s.errors.size(); ++i) {
        const AppError& e = s.errors[i];
        if (i) ImGui::Separator();
        ImGui::TextUnformatted(e.title.c_str());
        if (!e.file.empty()) {
            ImGui::TextDisabled("File:");
            ImGui::SameLine();
            ImGui::TextWrapped("%s", e.file.c_str());
        }
        ImGui::TextDisabled("Reason:");
        ImGui::SameLine();
        ImGui::TextWrapped("%s", e.reason.c_str());
    }
    if (!s.headless) {
        ImGui::Spacing();
        if (ImGui::Button("Dismiss")) s.req.clear_errors = true;
    }
    ImGui::End();
    ImGui::PopStyleColor(4);
}

}  // namespace hlens::gui
