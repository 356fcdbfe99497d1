// Dear ImGui panels. Sizes are multiples of the font size, so they follow DPI scaling.
// To add a panel (domain view, d^2 graph, timeline, event log, ...): a function here taking the
// AppState, called from draw_panels(); actions go through AppState::req.
#pragma once
#include <glm/glm.hpp>
#include <imgui.h>

#include "app_state.h"
#include "scene.h"

namespace hlens::gui {

// Window background of the error panel: distinctive (the GUI test looks for it).
constexpr float kErrorBg[4] = {0.50f, 0.09f, 0.09f, 1.0f};
// Clear colour of the 3D view (the GUI test checks a corner for it).
constexpr float kClearColor[4] = {0.16f, 0.17f, 0.20f, 1.0f};

// Sets state.sidebar_width and state.view for a display of that size (window coordinates).
void layout(AppState& s, float display_w, float display_h);

// Places the next window on a tile of the tiled layout (layout()): its position is fixed; a
// dimension with lo < hi is the user's to drag (its size comes from imgui.ini, else the tile's),
// a dimension with lo == hi is pinned. Call before ImGui::Begin.
void place_tile(const AppState::Tile& t);
constexpr int kTileFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;

// The centroid of the selected target of the current direction and its reach (the largest
// distance from the centroid to a point of T', world units); false without a selected target.
bool selected_target_ball(const AppState& s, Vec3& centroid, double& reach);

// The sidebar (files, progress, distances, direction, colour map, meshes, target, help) and, when
// there are errors, the error panel over the view.
void draw_panels(AppState& s);

// Drawn into the 3D view with ImGui's background draw list: witness points and segments, the
// outline of the selected target and its maximum, a hint line. `mvp` maps scene-local coordinates.
void draw_view_overlay(const AppState& s, const Scene& scene, const glm::mat4& mvp);

}  // namespace hlens::gui
