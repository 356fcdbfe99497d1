// The loop's screenshot step, after rendering and before the buffers are swapped (the back buffer
// is then what was just drawn): F12's PNG, and in headless runs (--screenshot PATH) the picture,
// once everything it shows has arrived, with the state behind it printed as one JSON line.
#pragma once
#include "app_state.h"
#include "args.h"
#include "jobs.h"
#include "script_input.h"
#include "view3d.h"

namespace hlens::gui {

// F12 (s.req.screenshot): hlens-<time>.png in the current directory; s.status says how it went.
void save_requested_screenshot(AppState& s, int fb_w, int fb_h);

struct Headless {
    int settle = 0;               // frames the picture has been ready for
    int exit_code = -1;           // -1: still running; 0, or 1 (cannot write), 2 (bad input)
};

// Headless: true when the picture can be taken this frame: the computation has ended, and unless
// it failed, --target is applied, the script has played, the target is traced (and stepped, with
// --step), the exact colour map has filled in (--exact-colormap wait) and the statistics asked
// for have arrived; then a few frames more for ImGui windows to size themselves.
bool picture_ready(Headless& h, const AppState& s, const Options& opt, const Jobs& jobs, const StartTarget& start,
                   const Script& script);
// Exports the case (--export-case), writes the PNG, prints the state line; sets h.exit_code.
void take_picture(Headless& h, AppState& s, const Options& opt, View3D& view, const ViewParams& params);

}  // namespace hlens::gui
