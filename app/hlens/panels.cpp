#include "panels.h"

#include "domain_view.h"
#include "event_log.h"
#include "graph.h"
#include "timeline.h"

namespace hlens::gui {

void draw_panels(AppState& s) {
    draw_sidebar(s);
    draw_target_window(s);
    draw_domain_view(s);
    draw_graph_view(s);
    draw_timeline(s);
    draw_event_log(s);
    draw_help_window(s);
    draw_error_panel(s);
    draw_drop_dialog(s);
}

}  // namespace hlens::gui
