// The sidebar's "Meshes" section: per mesh its visibility, colour, draw mode and opacity; the up
// axis and "Reset view".
#include "panels.h"

#include <imgui.h>

#include "ui.h"

namespace hlens::gui {

void draw_meshes_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Meshes", ImGuiTreeNodeFlags_DefaultOpen)) return;
    static const char* modes[] = {"Solid", "Solid+edges", "Wireframe"};
    for (int side = 0; side < 2; ++side) {
        MeshStyle& st = s.style[side];
        ImGui::PushID(side);
        ImGui::Checkbox(kSide[side], &st.visible);
        ImGui::SameLine();
        ImGui::ColorEdit3("##color", st.color, ImGuiColorEditFlags_NoInputs);
        if (side == s.direction && s.show_colormap && s.range[side].valid && ImGui::IsItemHovered())
            ImGui::SetTooltip("colour used when the colour map is off");
        ImGui::SameLine();
        int mode = (int)st.mode;
        ImGui::SetNextItemWidth(8.6f * em());
        if (ImGui::Combo("##mode", &mode, modes, 3)) {
            st.mode = (DrawMode)mode;
            st.touched = true;
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        if (ImGui::SliderFloat("##opacity", &st.opacity, 0.05f, 1.0f, "opacity %.2f")) st.touched = true;
        ImGui::PopID();
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Up axis");
    ImGui::SameLine();
    int up = s.up_axis;
    ImGui::RadioButton("+Y", &up, 1);
    ImGui::SameLine();
    ImGui::RadioButton("+Z", &up, 2);
    if (up != s.up_axis) {
        s.up_axis = up;
        s.req.home = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset view (Home)", ImVec2(-1, 0))) s.req.home = true;
}

}  // namespace hlens::gui
