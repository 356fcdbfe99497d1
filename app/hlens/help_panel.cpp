// Every mouse action and keyboard shortcut: the sidebar's "Help" section and the Help window (F1).
#include "panels.h"

#include <imgui.h>

#include "ui.h"

namespace hlens::gui {

namespace {

// Every mouse action and keyboard shortcut (the sidebar's Help section and the F1 window).
// Shortcuts are ignored while a text field has the keyboard (io.WantTextInput).
void help_text() {
    ImGui::TextDisabled("3D view");
    ImGui::BulletText("left-drag: orbit");
    ImGui::BulletText("right-drag, middle-drag or shift+left-drag: pan");
    ImGui::BulletText("wheel: zoom");
    ImGui::BulletText("click: pick the target T' (click the background: clear)");
    ImGui::BulletText("double-click: recentre there");
    ImGui::TextDisabled("Domain view (timeline)");
    ImGui::BulletText("right-drag: pan   wheel: zoom");
    ImGui::BulletText("double-click: fit   hover: the domain's label");
    ImGui::TextDisabled("Graph of d^2");
    ImGui::BulletText("left-drag: orbit   wheel: zoom");
    ImGui::TextDisabled("Event log");
    ImGui::BulletText("click a row: jump to that step");
    ImGui::TextDisabled("Keys (not while typing in a text field)");
    ImGui::BulletText("Home: reset the view");
    ImGui::BulletText("F: frame the target and the sphere of its largest distance (also on opening its timeline)");
    ImGui::BulletText("F12: save hlens-<time>.png");
    ImGui::BulletText("F1: this help in a window");
    ImGui::BulletText("Left / Right: one event back / forward (timeline)");
    ImGui::BulletText("Space: play / pause (timeline)");
    ImGui::BulletText("Escape: cancel the dropped-files dialog");
    ImGui::TextDisabled("Other");
    ImGui::BulletText("drop files on the window: open them as A and B");
    ImGui::BulletText("grey, hatched triangles: not yet exact (the exact colour map is filling in)");
    ImGui::TextDisabled("'voxels & radius' (timeline): voxels seen so far");
    ImGui::TextDisabled("(green visited, yellow pending, grey culled) and a");
    ImGui::TextDisabled("sphere of radius r + reach of T' around its centroid,");
    ImGui::TextDisabled("enclosing all points within the search radius r of T'.");
}

}  // namespace

void draw_help_section() {
    if (!ImGui::CollapsingHeader("Help")) return;
    help_text();
}

void draw_help_window(AppState& s) {
    if (!s.help_open) return;
    ImGui::SetNextWindowPos(ImVec2(s.view.x + 2 * em(), s.view.y + 2 * em()), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Help (F1)", &s.help_open, ImGuiWindowFlags_AlwaysAutoResize)) help_text();
    ImGui::End();
}

}  // namespace hlens::gui
