// The sidebar's "Cases" section: the built-in degenerate cases (cases.h), optionally
// near-degenerate, and "Export case" of the selected target.
#include "panels.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "cases.h"

namespace hlens::gui {

void draw_cases_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Cases")) return;
    const auto& cases = builtin_cases();
    s.case_choice = std::clamp(s.case_choice, 0, (int)cases.size() - 1);
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##case", cases[s.case_choice].name)) {
        for (int i = 0; i < (int)cases.size(); ++i) {
            if (ImGui::Selectable(cases[i].name, i == s.case_choice)) s.case_choice = i;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", cases[i].description);
        }
        ImGui::EndCombo();
    }
    ImGui::TextWrapped("%s", cases[s.case_choice].description);
    ImGui::Checkbox("near-degenerate", &s.case_near);
    if (s.case_near) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        ImGui::SliderFloat("##eps", &s.case_log_eps, -12, -1, "eps 1e%.1f");
    }
    if (ImGui::Button("Load case", ImVec2(-1, 0))) {
        s.req.load_case = cases[s.case_choice].name;
        s.req.case_eps = s.case_near ? std::pow(10.0, (double)s.case_log_eps) : 0.0;
    }
    ImGui::Separator();
    ImGui::TextUnformatted("Export case (selected target)");
    ImGui::SetNextItemWidth(-1);
    ImGui::InputText("##exportdir", &s.export_dir);
    ImGui::BeginDisabled(s.selected[s.direction] < 0 || !s.scene || !s.scene->grid);
    if (ImGui::Button("Export case", ImVec2(-1, 0))) s.req.export_case = true;
    ImGui::EndDisabled();
    if (!s.export_status.empty())
        ImGui::TextColored(s.export_ok ? ImVec4(0.6f, 1, 0.6f, 1) : ImVec4(1, 0.5f, 0.5f, 1), "%s", s.export_status.c_str());
}

}  // namespace hlens::gui
