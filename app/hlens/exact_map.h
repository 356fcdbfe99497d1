// The exact colour map per direction (AppState::exact, ::range): fast mode's exact values first,
// then the fill-in's and finished traces'; the range follows the values shown.
#pragma once
#include <cstdint>
#include <vector>

#include "app_state.h"
#include "scene.h"

namespace hlens::gui {

// Direction d's colour map on the GPU and its range (following the values shown while the user
// has not moved it, or always with `reset`), after its values changed.
void show_values(AppState& s, Scene& scene, int d, bool reset);
// Direction d's map as fast mode left it: exact where it solved the triangle, unknown elsewhere.
void init_exact(AppState& s, int d);
// A newly known exact value (from the fill-in or a finished trace); false if it was known.
bool set_exact(AppState& s, int d, uint32_t t, double v);
// The best known maximum over target t of direction d: exact if known, else fast mode's bound.
double target_value(const AppState& s, int d, long t, bool& exact);

}  // namespace hlens::gui
