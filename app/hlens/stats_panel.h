// The sidebar's "Statistics" section: the exact surface statistics of both directions (area,
// mean, RMS, percentiles, the histogram as a plot), computed on request with progress and Cancel,
// and the export of the error map.
#pragma once
#include "app_state.h"

namespace hlens::gui {

void draw_stats_section(AppState& s);

}  // namespace hlens::gui
