// The tolerance in the domain view: the domain mesh at the current step cut at T (tolerance_cut.h),
// the part above T shaded (each domain's colour mixed with red), the exact curve d = T drawn
// thick in each domain, and the area above T of the target in the corner.
#pragma once
#include <functional>

#include <imgui.h>

#include "app_state.h"

namespace hlens::gui {

// Draws into `dl` (the canvas from c0 to c1, frame -> screen by `to_screen`); `shade`: fill the
// pieces (off while the overlay colours the domains). Recomputes s.view_cut when the step or T
// changed; does nothing without a tolerance.
void draw_tolerance_in_domain_view(AppState& s, ImDrawList* dl, ImVec2 c0, ImVec2 c1,
                                   const std::function<ImVec2(Vec2)>& to_screen, bool shade);

}  // namespace hlens::gui
