// Opening meshes: the sidebar's "Open meshes" section (paths, recent files, Load, Swap, the demo
// pair) and the dialog for files dropped on the window.
#include "panels.h"

#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui.h"

namespace hlens::gui {

void draw_open_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Open meshes")) return;
    for (int side = 0; side < 2; ++side) {
        ImGui::PushID(side);
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(kSide[side]);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-4.5f * em());
        ImGui::InputTextWithHint("##path", "path to a mesh (.obj .ply .stl .off .gltf .glb)", &s.edit_path[side]);
        ImGui::SameLine();
        if (ImGui::Button("Recent", ImVec2(-1, 0))) ImGui::OpenPopup("recent");
        if (ImGui::BeginPopup("recent")) {
            if (s.recent.empty()) ImGui::TextDisabled("no recent files");
            for (const std::string& r : s.recent)
                if (ImGui::Selectable(r.c_str())) s.edit_path[side] = r;
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    const bool ok = !s.edit_path[0].empty() && !s.edit_path[1].empty();
    if (!ok) ImGui::BeginDisabled();
    if (ImGui::Button("Load")) {
        s.req.load = true;
        s.req.load_path[0] = s.edit_path[0];
        s.req.load_path[1] = s.edit_path[1];
    }
    if (!ok) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Swap")) std::swap(s.edit_path[0], s.edit_path[1]);
    ImGui::SameLine();
    if (ImGui::Button("Demo pair")) {
        s.edit_path[0] = s.demo_path[0];
        s.edit_path[1] = s.demo_path[1];
    }
    ImGui::TextDisabled("or drop files on the window");
}

// Files dropped on the window: ask which side they are.
void draw_drop_dialog(AppState& s) {
    const char* id = "Load dropped files";
    if (!s.dropped.empty() && !ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    auto load = [&](const std::string& a, const std::string& b) {
        s.req.load = true;
        s.req.load_path[0] = a;
        s.req.load_path[1] = b;
        s.dropped.clear();
        ImGui::CloseCurrentPopup();
    };
    if (s.dropped.size() == 1) {
        ImGui::Text("Open %s as", s.dropped[0].c_str());
        if (ImGui::Button("A", ImVec2(5 * em(), 0))) load(s.dropped[0], s.path[1]);
        ImGui::SameLine();
        if (ImGui::Button("B", ImVec2(5 * em(), 0))) load(s.path[0], s.dropped[0]);
    } else if (s.dropped.size() >= 2) {
        ImGui::Text("A: %s", s.dropped[0].c_str());
        ImGui::Text("B: %s", s.dropped[1].c_str());
        if (s.dropped.size() > 2) ImGui::TextDisabled("(only the first two files are used)");
        if (ImGui::Button("Open", ImVec2(5 * em(), 0))) load(s.dropped[0], s.dropped[1]);
        ImGui::SameLine();
        if (ImGui::Button("Swap", ImVec2(5 * em(), 0))) std::swap(s.dropped[0], s.dropped[1]);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(5 * em(), 0)) || (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))) {
        s.dropped.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace hlens::gui
