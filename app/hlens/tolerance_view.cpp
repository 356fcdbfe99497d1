#include "tolerance_view.h"

#include <cstdio>
#include <vector>

#include "colormap.h"

namespace hlens::gui {

namespace {

// A domain's colour mixed half with red: "above T".
ImU32 above_colour(ImU32 c) {
    const ImVec4 v = ImGui::ColorConvertU32ToFloat4(c);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(0.45f * v.x + 0.55f * 0.92f, 0.45f * v.y + 0.55f * 0.16f, 0.45f * v.z + 0.55f * 0.14f, 1));
}

void fill_pieces(const ToleranceCut& c, ImDrawList* dl, const std::function<ImVec2(Vec2)>& to_screen) {
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    for (const ToleranceCut::Piece& p : c.pieces) {   // largest outer loop first: holes' faces over it
        if (p.tris.empty()) continue;
        const ImU32 base = domain_label_colour(p.label, p.infinite);
        const ImU32 col = p.above ? above_colour(base) : base;
        dl->PrimReserve((int)p.tris.size(), (int)p.outer.size());
        const ImDrawIdx first = (ImDrawIdx)dl->_VtxCurrentIdx;
        for (const Vec2& q : p.outer) dl->PrimWriteVtx(to_screen(q), uv, col);
        for (int i : p.tris) dl->PrimWriteIdx((ImDrawIdx)(first + i));
    }
}

}  // namespace

void draw_tolerance_in_domain_view(AppState& s, ImDrawList* dl, ImVec2 c0, ImVec2 c1,
                                   const std::function<ImVec2(Vec2)>& to_screen, bool shade) {
    Stepper& st = s.stepper;
    const DomainMesh* m = st.mesh();
    if (s.tolerance < 0 || !m || !st.solver) {
        s.view_cut = ToleranceCut{};
        return;
    }
    if (s.view_cut_revision != st.revision || s.view_cut.t != s.tolerance) {
        s.view_cut = cut_at_tolerance(*m, st.solver->frame(), s.tolerance);
        s.view_cut_revision = st.revision;
    }
    const ToleranceCut& c = s.view_cut;
    if (shade) fill_pieces(c, dl, to_screen);
    std::vector<ImVec2> pts;
    for (const std::vector<Vec2>& arc : c.curve) {
        pts.clear();
        for (const Vec2& q : arc) pts.push_back(to_screen(q));
        dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(0, 0, 0, 255), 0, 5.0f);
        dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(255, 60, 50, 255), 0, 3.0f);
    }
    char text[128];
    std::snprintf(text, sizeof text, "d > T = %.6g: area %.6g (%.3g%% of T')", c.t, c.area_above,
                  c.area > 0 ? 100 * c.area_above / c.area : 0.0);
    const float h = ImGui::GetTextLineHeight(), pad = 0.4f * ImGui::GetFontSize();
    const ImVec2 p(c0.x + pad, c1.y - h - pad), size = ImGui::CalcTextSize(text);
    dl->AddRectFilled(ImVec2(p.x - 0.2f * pad, p.y - 0.2f * pad), ImVec2(p.x + size.x + 0.2f * pad, p.y + h + 0.2f * pad),
                      IM_COL32(20, 20, 24, 220));
    dl->AddText(p, IM_COL32(255, 120, 110, 255), text);
}

}  // namespace hlens::gui
