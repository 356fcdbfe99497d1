// The timeline panel of the stepped target (timeline.cpp): the stepping model's controls.
#pragma once

namespace hlens::gui {

struct AppState;
// Only while s.stepper.open and a target is stepped; at the bottom of the tiled layout.
void draw_timeline(AppState& s);

}  // namespace hlens::gui
