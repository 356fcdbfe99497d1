// The graph of d^2 over T' at the stepper's current step, in its own orbitable window: a fine
// triangulation of T' (in the target's frame) lifted by the exact d^2 (TargetSolver::direct_d2),
// each triangle coloured by the domain it lies in (the domain view's label colours), the domain
// mesh's arcs drawn on the surface and the current maximum marked. Rendered into an offscreen
// framebuffer shown with ImGui::Image; left-drag orbits, the wheel zooms.
#pragma once

namespace hlens::gui {

struct AppState;
// Only while the timeline is open, a target is stepped and s.stepper.graph_open.
void draw_graph_view(AppState& s);

}  // namespace hlens::gui
