// The construction's events and labels as text, for the timeline, the domain view's tooltips and
// the event log.
#pragma once
#include <string>

#include <hlens/target_solver.h>

namespace hlens::gui {

// One line with the event's main fields.
std::string event_summary(const Event& e);
// "T 12, edge 01", or "no source (d^2 = inf)" for the infinite domain.
std::string label_text(const DomainLabel& l, bool infinite);
// "(x, y)" with 4 significant digits.
std::string vec_text(Vec2 p);

}  // namespace hlens::gui
