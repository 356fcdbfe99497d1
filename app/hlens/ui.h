// Small helpers shared by the panels: sizes in multiples of the font size (so they follow DPI
// scaling), the sides' names, a label-value table row, rows of toolbar items that wrap.
#pragma once
#include <cstdio>
#include <string>

#include <imgui.h>

namespace hlens::gui {

inline float em() { return ImGui::GetFontSize(); }

inline const char* const kSide[2] = {"A", "B"};
// The witness of h(A,B) and of h(B,A): the sidebar's checkboxes and the 3D view's markers.
inline const ImU32 kWitnessColor[2] = {IM_COL32(255, 150, 40, 255), IM_COL32(70, 200, 255, 255)};

inline std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// A label in the first column of a two-column table row, a value in the second.
inline void row(const char* label, const std::string& value, const char* tooltip = nullptr) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", label);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(value.c_str());
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

// SameLine() when an item `w` wide still fits on the current row, else the item starts a new row.
inline void same_line_if_fits(float w) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w <= right) ImGui::SameLine();
}
inline float checkbox_width(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}

}  // namespace hlens::gui
