// The event log panel: every event of the selected target's construction, one line each, filtered
// by kind. The whole stream comes from the target's trace (TraceJob records it); a click on a line
// jumps the timeline there (Stepper::jump, as "Go to step"), and the current step's line is
// highlighted and scrolled into view whenever the step changes.
#include "event_log.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "app_state.h"
#include "event_text.h"
#include "layout.h"
#include "stepper.h"
#include "ui.h"

namespace hlens::gui {

namespace {
constexpr int kNumKinds = (int)EventKind::TargetFinished + 1;

// Filter by kind: a combo of checkboxes.
void kind_filter(Stepper& st) {
    int n_on = 0;
    for (int k = 0; k < kNumKinds; ++k) n_on += st.kind_shown[k];
    char preview[48];
    std::snprintf(preview, sizeof preview, n_on == kNumKinds ? "all kinds" : "%d of %d kinds", n_on, kNumKinds);
    ImGui::SetNextItemWidth(12 * em());
    if (ImGui::BeginCombo("filter", preview)) {
        if (ImGui::SmallButton("all")) {
            for (int k = 0; k < kNumKinds; ++k) st.kind_shown[k] = true;
            st.log_dirty = true;
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("none")) {
            for (int k = 0; k < kNumKinds; ++k) st.kind_shown[k] = false;
            st.log_dirty = true;
        }
        for (int k = 0; k < kNumKinds; ++k)
            if (ImGui::Checkbox(event_name((EventKind)k), &st.kind_shown[k])) st.log_dirty = true;
        ImGui::EndCombo();
    }
}

// The rows that pass the filter, rebuilt when the filter or the stream changed.
void refresh_rows(Stepper& st, const TargetSolver* full) {
    const std::vector<Event>& ev = full->events();
    if (st.log_dirty || st.log_source != (const void*)full || st.log_source_size != ev.size()) {
        st.log_rows.clear();
        for (size_t i = 0; i < ev.size(); ++i)
            if (st.kind_shown[(int)ev[i].kind]) st.log_rows.push_back((long)i);
        st.log_source = full;
        st.log_source_size = ev.size();
        st.log_dirty = false;
        st.log_scrolled_step = -2;
    }
    st.log_shown = (long)st.log_rows.size();
    st.log_total = (long)ev.size();
}

// The rows (only those on screen are laid out); the step clicked, else -2.
long event_rows(Stepper& st, const std::vector<Event>& ev) {
    ImGui::BeginChild("rows", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
    const float line_h = ImGui::GetTextLineHeightWithSpacing();
    if (st.log_scrolled_step != st.step) {   // bring the current step's line (or the nearest before it) into view
        st.log_scrolled_step = st.step;
        auto it = std::upper_bound(st.log_rows.begin(), st.log_rows.end(), st.step);
        const long row = (long)(it - st.log_rows.begin()) - 1;
        if (row >= 0) {
            const float y = row * line_h, top = ImGui::GetScrollY(), h = ImGui::GetWindowHeight();
            if (y < top || y + line_h > top + h) ImGui::SetScrollY(std::max(0.0f, y - 0.5f * h));
        }
    }
    long jump_to = -2;
    st.log_current_y = -1;
    st.log_row_h = line_h;
    ImGuiListClipper clipper;
    clipper.Begin((int)st.log_rows.size(), line_h);
    char line[320];
    while (clipper.Step())
        for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
            const Event& e = ev[st.log_rows[r]];
            std::snprintf(line, sizeof line, "%5ld  %-20s %s##%ld", e.step, event_name(e.kind), event_summary(e).c_str(), e.step);
            if (ImGui::Selectable(line, e.step == st.step)) jump_to = e.step;
            if (e.step == st.step) {   // where the current line is, for the headless JSON line
                st.log_current_y = 0.5f * (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y);
                st.log_row_x = ImGui::GetItemRectMin().x + 2 * em();
            }
        }
    clipper.End();
    ImGui::EndChild();
    return jump_to;
}

}  // namespace

void draw_event_log(AppState& s) {
    Stepper& st = s.stepper;
    st.log_shown = st.log_total = 0;
    if (!st.open || !st.event_log || !st.active()) return;
    const int d = st.side;
    const TargetSolver* full = s.trace[d] && s.trace[d]->target == (uint32_t)st.target && s.trace[d]->solver
                                   ? s.trace[d]->solver.get()
                                   : nullptr;
    if (!begin_tile("Event log", s.tiles.log, st.event_log)) return;
    if (!s.tiles.graph_on) s.tiles.strip_h = ImGui::GetWindowSize().y;   // the strip's top edge is the log's
    if (!full) {
        ImGui::TextDisabled(s.trace_running ? "tracing the target..." : "no event stream");
        ImGui::End();
        return;
    }
    const std::vector<Event>& ev = full->events();

    kind_filter(st);
    refresh_rows(st, full);
    ImGui::SameLine();
    ImGui::TextDisabled("%ld of %ld", st.log_shown, st.log_total);
    const long jump_to = event_rows(st, ev);
    ImGui::End();
    if (jump_to != -2) st.jump(jump_to);   // the "Go to step" path
}

}  // namespace hlens::gui
