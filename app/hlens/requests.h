// Acting on what the views asked for this frame (AppState::req): the jobs (cancel, recompute,
// statistics, the exact colour map's fill-in), a new pair (files or a built-in case), exports,
// the camera, the direction and the selection. The views only set requests; this is where they
// reach the jobs, the GPU and the camera.
#pragma once
#include <string>

#include "app_state.h"
#include "args.h"
#include "jobs.h"
#include "view3d.h"

namespace hlens::gui {

// False when the run must end: a headless --export-errors failed (`exit_code` is then 2).
// s.req.screenshot is kept for the screenshot step.
bool act_on_requests(AppState& s, Jobs& jobs, View3D& view, const Options& opt, int& exit_code);

// The measured mesh d; its style follows (solid, the other a wireframe) unless the user set it.
void set_direction(AppState& s, int d);
// Replaces A and B by a built-in case (the caller recomputes). False: unknown name.
bool load_builtin_case(AppState& s, const std::string& name, double eps);
// "Export case": the selected target and its relevant sources as two OBJ files in s.export_dir.
bool export_selected(AppState& s);

}  // namespace hlens::gui
