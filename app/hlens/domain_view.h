// The 2D domain view of the stepped target (domain_view.cpp): its domain mesh at the current step.
#pragma once

namespace hlens::gui {

struct AppState;
// Only while s.stepper.open and a target is stepped; on the left of the tiled layout.
void draw_domain_view(AppState& s);

}  // namespace hlens::gui
