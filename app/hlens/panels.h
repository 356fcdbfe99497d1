// The debugger's Dear ImGui windows, one entry point each, in one file each (named below). Each
// reads the AppState and edits it; what needs OpenGL or the job threads goes through
// AppState::req for the main loop to act on. Sizes are multiples of the font size (ui.h em()),
// so they follow DPI scaling. To add a panel: a file with its entry point, declared here (or in
// its own header), called from draw_panels() or draw_sidebar().
#pragma once
#include "app_state.h"

namespace hlens::gui {

// Window background of the error panel: distinctive (the GUI test looks for it).
constexpr float kErrorBg[4] = {0.50f, 0.09f, 0.09f, 1.0f};
// Clear colour of the 3D view (the GUI test checks a corner for it).
constexpr float kClearColor[4] = {0.16f, 0.17f, 0.20f, 1.0f};

// Every window, in drawing order (panels.cpp): the sidebar, the target panel, the stepping views
// (domain view, graph, timeline, event log), the Help window, the error panel, the drop dialog.
void draw_panels(AppState& s);

// The sidebar (sidebar.cpp) and its sections.
void draw_sidebar(AppState& s);
void draw_distances_section(AppState& s);   // distances_panel.cpp
void draw_colormap_section(AppState& s);    // colormap_panel.cpp
void draw_meshes_section(AppState& s);      // meshes_panel.cpp
void draw_open_section(AppState& s);        // open_panel.cpp
void draw_cases_section(AppState& s);       // cases_panel.cpp
void draw_help_section();                   // help_panel.cpp
// (and draw_stats_section, stats_panel.h; draw_tolerance_section, tolerance_panel.h)

// Windows over the 3D view.
void draw_target_window(AppState& s);       // target_panel.cpp
void draw_help_window(AppState& s);         // help_panel.cpp (F1)
void draw_error_panel(AppState& s);         // error_panel.cpp
void draw_drop_dialog(AppState& s);         // open_panel.cpp: files dropped on the window

}  // namespace hlens::gui
