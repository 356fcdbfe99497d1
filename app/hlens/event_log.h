// The event log of the selected target: every event of its construction, one line each, filtered
// by kind; a click on a line jumps the timeline there.
#pragma once

namespace hlens::gui {

struct AppState;
// Only with the timeline open and s.stepper.event_log.
void draw_event_log(AppState& s);

}  // namespace hlens::gui
