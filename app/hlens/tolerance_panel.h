// The sidebar's "Tolerance" section: the tolerance field (--tolerance T) and the area above T for
// the measured mesh (exact once the statistics are computed at T; the triangles whose maximum
// exceeds T, outlined in the 3D view, bound it) and for the selected target (its domain mesh cut
// at T, tolerance_cut.h). Keeps s.target_cut up to date.
#pragma once
#include "app_state.h"

namespace hlens::gui {

void draw_tolerance_section(AppState& s);

}  // namespace hlens::gui
