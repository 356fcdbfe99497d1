#include "tolerance_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "stats_flow.h"

namespace hlens::gui {

namespace {

// The selected target's finished domain mesh (its trace) cut at T, recomputed when either changes.
void update_target_cut(AppState& s) {
    const int d = s.direction;
    const long t = s.selected[d];
    const TraceSummary* tr = t >= 0 && s.trace[d] && s.trace[d]->target == (uint32_t)t ? &*s.trace[d] : nullptr;
    const DomainMesh* m = tr && tr->solver && tr->solver->finished() ? tr->solver->domain_mesh() : nullptr;
    if (!m || s.tolerance < 0) {
        s.target_cut = ToleranceCut{};
        s.target_cut_of = nullptr;
        return;
    }
    if (s.target_cut_of == m && s.target_cut.t == s.tolerance) return;
    s.target_cut = cut_at_tolerance(*m, tr->solver->frame(), s.tolerance);
    s.target_cut_of = m;
}

void tolerance_field(AppState& s) {
    bool on = s.tolerance >= 0;
    if (ImGui::Checkbox("T =", &on)) s.tolerance = on ? std::max(0.0, s.tolerance_input) : -1;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("a tolerance: where is the distance above it?");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputDouble("##tolerance", &s.tolerance_input, 0, 0, "%.6g") && on)
        s.tolerance = std::max(0.0, s.tolerance_input);
}

void mesh_numbers(AppState& s) {
    const int d = s.direction;
    const MeshAbove m = mesh_above(s, d);
    const char* side = d == 0 ? "A" : "B";
    if (m.exact >= 0) {
        ImGui::Text("%s: area above T %.6g (%.3g%%)", side, m.exact, 100 * m.fraction);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("exact (the statistics at T): %.17g of %.17g", m.exact, m.area);
    } else {
        ImGui::TextDisabled("%s: exact area above T: with the statistics at T", side);
    }
    ImGui::TextWrapped("%zu triangles of %s have their maximum above T (outlined red): area %.6g (%.3g%%)", m.triangles, side,
                       m.bound, m.area > 0 ? 100 * m.bound / m.area : 0.0);
}

void target_numbers(const AppState& s) {
    const ToleranceCut& c = s.target_cut;
    if (s.selected[s.direction] < 0) return;
    if (c.t < 0) {
        ImGui::TextDisabled("target T': waiting for its construction");
        return;
    }
    ImGui::Text("T' %ld: area above T %.6g (%.3g%%)", s.selected[s.direction], c.area_above,
                c.area > 0 ? 100 * c.area_above / c.area : 0.0);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("its domain mesh cut by the conics d = T (exact areas): %.17g of %.17g", c.area_above, c.area);
}

}  // namespace

void draw_tolerance_section(AppState& s) {
    update_target_cut(s);
    if (!ImGui::CollapsingHeader("Tolerance", ImGuiTreeNodeFlags_DefaultOpen)) return;
    tolerance_field(s);
    if (s.tolerance < 0 || !s.computed) return;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetContentRegionAvail().x);
    mesh_numbers(s);
    target_numbers(s);
    ImGui::PopTextWrapPos();
}

}  // namespace hlens::gui
