// Where the windows go: the sidebar on the left, the 3D view right of it; with a target's
// timeline open, that area tiled into the domain view, the 3D view, the graph and event log strip
// and the timeline (AppState::Tiles).
#pragma once
#include <imgui.h>

#include "app_state.h"

namespace hlens::gui {

// Sets state.sidebar_width and state.view (and state.tiles) for a display of that size (window
// coordinates).
void layout(AppState& s, float display_w, float display_h);

// Places the next window on a tile of the tiled layout (layout()): its position is fixed; a
// dimension with lo < hi is the user's to drag (its size comes from imgui.ini, else the tile's),
// a dimension with lo == hi is pinned. Call before ImGui::Begin.
void place_tile(const AppState::Tile& t);
constexpr int kTileFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
// place_tile(t), then ImGui::Begin with a close button that clears `shown`. False when the window
// is not visible (ImGui::End is then done); else call ImGui::End after its contents.
bool begin_tile(const char* title, const AppState::Tile& t, bool& shown, int flags = 0);

}  // namespace hlens::gui
