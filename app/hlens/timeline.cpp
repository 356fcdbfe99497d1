// The timeline of the stepped target: first / back / forward / next insertion / last, play at
// a speed, go to a step, what the 3D view and the strip show; the current event, the state's
// counts and the search radius after each insertion so far.
#include "timeline.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app_state.h"
#include "event_text.h"
#include "gl.h"
#include "layout.h"
#include "ui.h"

namespace hlens::gui {

namespace {

// A button with its tooltip.
bool tool_button(const char* label, const char* tooltip) {
    const bool pressed = ImGui::Button(label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    return pressed;
}

// The buttons and checkboxes (they wrap to more rows in a narrow window).
void toolbar(Stepper& st) {
    if (tool_button("|<", "first: before any event")) st.jump(-1);
    ImGui::SameLine();
    if (tool_button("<", "one event back (Left; replays from the start)")) st.back();
    ImGui::SameLine();
    if (tool_button(">", "one event forward (Right)")) st.forward();
    ImGui::SameLine();
    if (tool_button(">>", "to the end of the next insertion")) st.next_insertion();
    ImGui::SameLine();
    if (tool_button(">|", "last: the finished target")) st.to_end();
    ImGui::SameLine();
    if (ImGui::Button(st.playing ? "Pause" : "Play ", ImVec2(4 * em(), 0))) st.playing = !st.playing;
    same_line_if_fits(9 * em() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("ev/s").x);
    ImGui::SetNextItemWidth(9 * em());
    ImGui::SliderFloat("ev/s", &st.speed, 1, 500, "%.0f", ImGuiSliderFlags_Logarithmic);
    same_line_if_fits(7 * em() + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize("Go to step").x + 2 * ImGui::GetStyle().FramePadding.x);
    ImGui::SetNextItemWidth(7 * em());
    bool go = ImGui::InputInt("##jump", &st.jump_input, 1, 100, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    go = ImGui::Button("Go to step") || go;
    if (go) st.jump(std::max(-1, st.jump_input));
    same_line_if_fits(checkbox_width("regions"));
    ImGui::Checkbox("regions", &st.show_regions);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("outline the seven regions of the source being inserted");
    same_line_if_fits(checkbox_width("voxels & radius"));
    ImGui::Checkbox("voxels & radius", &st.show_voxels);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("3D view: voxels seen so far (green visited, yellow pending, grey culled)\n"
                          "and the search radius envelope: a sphere around the centroid of T' of\n"
                          "radius r + (farthest corner from the centroid), enclosing every point\n"
                          "within r of T' (%ld visited, %ld pending, %ld culled)",
                          st.vox_visited, st.vox_pending, st.vox_culled);
    same_line_if_fits(checkbox_width("event log"));
    ImGui::Checkbox("event log", &st.event_log);
    same_line_if_fits(checkbox_width("graph"));
    ImGui::Checkbox("graph", &st.graph_open);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the graph of d^2 over T' at this step (drag orbits, wheel zooms)");
}

// Keys (Left/Right step, Space plays) and playing: events at st.speed a second.
void keys_and_playing(Stepper& st) {
    // (not while a text field, or another widget, has the keyboard)
    ImGuiIO& io = ImGui::GetIO();
    if (!io.WantTextInput && !io.WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) st.back();
        if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) st.forward();
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) st.playing = !st.playing;
    }
    if (st.playing) {   // (headless: ImGui's clock runs 1/60 s a frame)
        st.play_accum += io.DeltaTime * st.speed;
        int n = std::min(1000, (int)st.play_accum);
        st.play_accum -= n;
        if (n > 0) st.jump(st.step + n);
        if (st.at_end) st.playing = false;
    } else {
        st.play_accum = 0;
    }
}

// The current event and the state's counts: three lines.
void status_lines(const Stepper& st) {
    if (st.current)
        ImGui::Text("step %ld  %s  (insertion %d)", st.step, event_name(st.current->kind), st.current->insertion);
    else
        ImGui::Text("step -  before the first event");
    if (st.at_end) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "  finished");
    }
    ImGui::TextDisabled("%s", st.current ? event_summary(*st.current).c_str() : "");
    const double mx = st.max_sq();
    const double r = st.search_radius();
    ImGui::Text("insertions %d   domains %d   arcs %d   vertices %d   max %s   search radius %s", st.insertions(),
                st.live_domains, st.live_arcs, st.live_vertices,
                std::isfinite(mx) ? std::to_string(std::sqrt(mx)).c_str() : "inf",
                std::isfinite(r) ? std::to_string(r).c_str() : "inf");
}

// The search radius after each insertion up to the current step (right of the text, if it fits).
void radius_plot(Stepper& st) {
    st.radius_plot.clear();
    {
        const auto& ev = st.solver->events();
        for (long i = 0; i <= std::min<long>(st.step, (long)ev.size() - 1); ++i) {
            const Event& e = ev[i];
            if (e.insertion < 1 || !std::isfinite(e.radius)) continue;
            if ((int)st.radius_plot.size() < e.insertion) st.radius_plot.resize(e.insertion, (float)e.radius);
            st.radius_plot[e.insertion - 1] = (float)e.radius;
        }
    }
    // The plot goes right of the three lines of text when it fits, else below them.
    const float plot_w = 22 * em();
    if (!st.radius_plot.empty()) {
        const float lh = ImGui::GetTextLineHeightWithSpacing();
        const bool beside = ImGui::GetWindowContentRegionMax().x > plot_w + 48 * em();
        if (beside) ImGui::SetCursorPos(ImVec2(ImGui::GetWindowContentRegionMax().x - plot_w, ImGui::GetCursorPosY() - 3 * lh));
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "search radius %.4g", st.radius_plot.back());
        ImGui::PlotLines("##radius", st.radius_plot.data(), (int)st.radius_plot.size(), 0, overlay, 0.0f, FLT_MAX,
                         ImVec2(beside ? plot_w : std::max(plot_w, ImGui::GetContentRegionAvail().x), 3 * lh - ImGui::GetStyle().ItemSpacing.y));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("search radius after each insertion, up to the current step");
    }
}

}  // namespace

void draw_timeline(AppState& s) {
    Stepper& st = s.stepper;
    if (!st.open || !st.active()) return;
    char title[96];
    std::snprintf(title, sizeof title, "Timeline: target %ld of %s###timeline", st.target, st.side == 0 ? "A" : "B");
    if (!begin_tile(title, s.tiles.timeline, st.open)) return;
    toolbar(st);
    keys_and_playing(st);
    status_lines(st);
    radius_plot(st);
    // The height all this needs: the layout gives the timeline tile that much from the next frame.
    s.tiles.timeline_need = ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y - ImGui::GetStyle().ItemSpacing.y;
    ImGui::End();
}

}  // namespace hlens::gui
