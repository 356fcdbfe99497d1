// The sidebar's "Distances" section: h(A,B), h(B,A) with their certified intervals and witnesses
// (each with the checkbox of its marker in the 3D view), and the Hausdorff distance.
#include "panels.h"

#include <cstdio>

#include <imgui.h>

#include "ui.h"

namespace hlens::gui {

void draw_distances_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Distances", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!s.computed) {
        ImGui::TextDisabled(s.computing ? "computing..." : "not computed");
        return;
    }
    for (int d = 0; d < 2; ++d) {
        const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
        ImGui::PushID(d);
        ImGui::PushStyleColor(ImGuiCol_CheckMark, ImGui::ColorConvertU32ToFloat4(kWitnessColor[d]));
        ImGui::Checkbox("##witness", &s.show_witness[d]);
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("show the witness point and segment");
        ImGui::SameLine();
        ImGui::Text("h(%s,%s) = %.15g", kSide[d], kSide[1 - d], r.distance);
        if (ImGui::BeginTable("interval", 2, ImGuiTableFlags_SizingFixedFit)) {
            ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 4.5f * em());
            row("lower", fmt("%.17g", r.lower), "certified: the true h is at least this");
            row("upper", fmt("%.17g", r.upper), "certified: the true h is at most this");
            char t[96];
            std::snprintf(t, sizeof t, "triangle %u of %s", r.target, kSide[d]);
            row("witness", t, "the target triangle where h is attained (from_point)");
            ImGui::EndTable();
        }
        ImGui::PopID();
    }
    const bool ab = s.result.a_to_b.distance >= s.result.b_to_a.distance;
    ImGui::Separator();
    ImGui::Text("Hausdorff = %.15g", s.result.hausdorff);
    ImGui::SameLine();
    ImGui::TextDisabled(ab ? "h(A,B)" : "h(B,A)");
}

}  // namespace hlens::gui
