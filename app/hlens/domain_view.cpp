// The domain view: T' in its own frame, its domain mesh at the current step filled by label (or
// the nearest-feature overlay), the arcs, the regions of the source being inserted, the domains
// the current event is about, the maximum so far and the curve d = T; a tooltip on the arc or
// domain under the mouse and a legend of the labels. Right-drag pans, the wheel zooms, a
// double-click fits T' again.
#include "domain_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <imgui.h>

#include "app_state.h"
#include "event_text.h"
#include "layout.h"
#include "overlay.h"
#include "tolerance_view.h"
#include "ui.h"

namespace hlens::gui {

namespace {

// Frame -> screen: T' fitted into the canvas, then the stepper's zoom and pan (read when used:
// the mouse moves them while the view is drawn).
struct Canvas {
    const Stepper& st;
    ImVec2 c0, c1, size, cc;   // corners, size and centre of the canvas (screen)
    Box2 box;                  // T' (frame)
    double s0 = 1;             // frame -> screen at zoom 1

    Canvas(const Stepper& stepper, const TargetFrame& fr, ImVec2 corner, ImVec2 csize)
        : st(stepper), c0(corner), c1(corner.x + csize.x, corner.y + csize.y), size(csize),
          cc(corner.x + 0.5f * csize.x, corner.y + 0.5f * csize.y) {
        for (const Vec2& c : fr.corners) box.add(c);
        const double bw = std::max(1e-9, box.hi.x - box.lo.x), bh = std::max(1e-9, box.hi.y - box.lo.y);
        s0 = 0.9 * std::min(csize.x / bw, csize.y / bh);
    }
    double scale() const { return s0 * st.zoom; }
    Vec2 centre() const { return Vec2(0.5 * (box.lo.x + box.hi.x) + st.pan_x, 0.5 * (box.lo.y + box.hi.y) + st.pan_y); }
    ImVec2 to_screen(Vec2 p) const {
        Vec2 c = centre();
        return ImVec2(cc.x + (float)((p.x - c.x) * scale()), cc.y - (float)((p.y - c.y) * scale()));
    }
    Vec2 to_frame(ImVec2 q) const {
        Vec2 c = centre();
        return Vec2(c.x + (q.x - cc.x) / scale(), c.y - (q.y - cc.y) / scale());
    }
};

// Right-drag pans, the wheel zooms about the mouse, a double-click fits T'.
void pan_and_zoom(Stepper& st, const Canvas& cv, bool hovered, bool active) {
    if (st.fit) st.zoom = 1, st.pan_x = st.pan_y = 0, st.fit = false;
    ImGuiIO& io = ImGui::GetIO();
    if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
        st.pan_x -= io.MouseDelta.x / cv.scale();
        st.pan_y += io.MouseDelta.y / cv.scale();
    }
    if (hovered && io.MouseWheel != 0) {
        Vec2 before = cv.to_frame(io.MousePos);
        st.zoom = std::clamp(st.zoom * std::pow(1.2f, io.MouseWheel), 0.2f, 1e5f);
        Vec2 after = cv.to_frame(io.MousePos);
        st.pan_x += before.x - after.x;
        st.pan_y += before.y - after.y;
    }
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) st.fit = true;
}

// The domains filled by label, or the overlay's texture in their place. Returns whether the
// overlay is shown.
bool draw_fills(Stepper& st, ImDrawList* dl, const Canvas& cv) {
    // The overlay (nearest feature, independent of the domain mesh) replaces the domain fills.
    if (st.show_overlay) update_overlay(st);
    const bool overlay = st.show_overlay && st.overlay_tex && st.overlay_w > 0;
    if (overlay)
        dl->AddImage((ImTextureID)(intptr_t)st.overlay_tex, cv.to_screen(Vec2(st.overlay_lo.x, st.overlay_hi.y)),
                     cv.to_screen(Vec2(st.overlay_hi.x, st.overlay_lo.y)), ImVec2(0, st.overlay_gpu ? 1.0f : 0.0f),
                     ImVec2(1, st.overlay_gpu ? 0.0f : 1.0f));
    // Domains: triangles without anti-aliased fringes, so neighbouring triangles leave no seams.
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    for (const DomainDraw& d : st.domains) {
        if (overlay) break;
        if (d.tris.empty()) continue;
        const int nv = (int)d.outer.size(), ni = (int)d.tris.size();
        dl->PrimReserve(ni, nv);
        const ImDrawIdx base = (ImDrawIdx)dl->_VtxCurrentIdx;
        for (const Vec2& p : d.outer) dl->PrimWriteVtx(cv.to_screen(p), uv, d.colour);
        for (int i : d.tris) dl->PrimWriteIdx((ImDrawIdx)(base + i));
    }
    return overlay;
}

// Arcs: region boundaries thin, conics thick, the target's boundary white; then the vertices and
// the arcs' interior maxima.
void draw_arcs(const Stepper& st, ImDrawList* dl, const Canvas& cv, const std::vector<Candidate>& candidates) {
    std::vector<ImVec2> pts;
    for (const ArcDraw& a : st.arcs) {
        pts.clear();
        for (const Vec2& p : a.pts) pts.push_back(cv.to_screen(p));
        ImU32 col = a.kind == ArcKind::TargetBoundary ? IM_COL32(255, 255, 255, 255)
                    : a.kind == ArcKind::Conic        ? IM_COL32(15, 15, 20, 255)
                                                      : IM_COL32(45, 45, 55, 200);
        float w = a.kind == ArcKind::RegionBoundary ? 1.0f : 2.5f;
        dl->AddPolyline(pts.data(), (int)pts.size(), col, 0, w);
    }
    for (const Vec2& p : st.vertices) dl->AddCircleFilled(cv.to_screen(p), 2.2f, IM_COL32(20, 20, 25, 255), 8);
    for (const Candidate& c : candidates)
        if (c.edge >= 0) dl->AddCircle(cv.to_screen(c.p), 4.5f, IM_COL32(255, 140, 0, 255), 12, 2.0f);
}

// The seven regions of the source being inserted, outlined and named.
void draw_regions(const Stepper& st, ImDrawList* dl, const Canvas& cv) {
    const Event* reg = st.show_regions ? st.regions_event() : nullptr;
    if (!reg) return;
    for (const RegionPolygon& rp : reg->regions) {
        if (rp.polygon.size() < 2) continue;
        std::vector<ImVec2> pts;
        Vec2 mid;
        for (const Vec2& p : rp.polygon) pts.push_back(cv.to_screen(p)), mid += p;
        mid = mid / (double)rp.polygon.size();
        dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(255, 230, 60, 220), ImDrawFlags_Closed, 1.5f);
        std::string name = region_name(rp.kind);
        ImVec2 q = cv.to_screen(mid), ts2 = ImGui::CalcTextSize(name.c_str());
        dl->AddText(ImVec2(q.x - 0.5f * ts2.x, q.y - 0.5f * ts2.y), IM_COL32(255, 240, 120, 255), name.c_str());
    }
}

// The domains the current event is about (split pieces, the relabelled or the merged domain).
void outline_event_domains(const Stepper& st, ImDrawList* dl, const Canvas& cv) {
    if (!st.current || !st.snapshot()) return;
    const Event& e = *st.current;
    std::vector<int> ids = e.kind == EventKind::DomainSplit ? e.faces : std::vector<int>{};
    if (e.kind == EventKind::DomainCreated || e.kind == EventKind::DomainMerged) ids.push_back(e.face);
    std::vector<ImVec2> pts;
    for (const DomainDraw& d : st.domains)
        if (std::find(ids.begin(), ids.end(), d.face) != ids.end()) {
            pts.clear();
            for (const Vec2& p : d.outer) pts.push_back(cv.to_screen(p));
            dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(0, 230, 255, 255), ImDrawFlags_Closed, 3.0f);
        }
}

// The maximum so far (a red target mark), and a note when there is no mesh or an insertion is
// under way.
void draw_maximum_and_notes(const Stepper& st, const DomainMesh* mesh, ImDrawList* dl, const Canvas& cv) {
    if (std::isfinite(st.max_sq()) && mesh) {
        ImVec2 q = cv.to_screen(st.max_2d());
        dl->AddCircleFilled(q, 8, IM_COL32(230, 30, 40, 255), 20);
        dl->AddCircle(q, 8, IM_COL32(255, 255, 255, 255), 20, 2.0f);
        dl->AddLine(ImVec2(q.x - 12, q.y), ImVec2(q.x + 12, q.y), IM_COL32(255, 255, 255, 255), 1.5f);
        dl->AddLine(ImVec2(q.x, q.y - 12), ImVec2(q.x, q.y + 12), IM_COL32(255, 255, 255, 255), 1.5f);
    }
    const ImVec2 c0 = cv.c0;
    if (!mesh) {  // say what the target is and how it is measured instead
        char note[400] = "degenerate target: no domain mesh";
        if (const auto d = degenerate_target(st.solver->frame())) {
            if (d->kind == std::string("point"))
                std::snprintf(note, sizeof note, "degenerate target: its three corners coincide (a point). No domain "
                              "mesh: its distance is the point's, exactly.");
            else if (d->kind == std::string("segment"))
                std::snprintf(note, sizeof note, "degenerate target: a segment %.6g long (zero area). No domain mesh: "
                              "its maximum is taken on the segment, exactly.", d->longest_edge);
            else
                std::snprintf(note, sizeof note, "sliver target: its height, %.3g, is below 1e-7 of its longest edge, "
                              "%.6g. No domain mesh: it is handled as its three edges, whose maximum is exact; the true "
                              "maximum lies at most the height above it (the certified interval allows for it).",
                              d->height, d->longest_edge);
        }
        dl->AddText(nullptr, 0, ImVec2(c0.x + em(), c0.y + em()), IM_COL32(220, 220, 220, 255), note, nullptr,
                    cv.size.x - 2 * em());   // wrapped to the canvas
    }
    if (mesh && st.inserting() >= 0) {
        char note[160];
        std::snprintf(note, sizeof note, "inside insertion %d (T %d): domains it has not reached keep their labels",
                      st.insertions(), st.inserting());
        dl->AddText(nullptr, 0, ImVec2(c0.x + 0.5f * em(), c0.y + 0.4f * em()), IM_COL32(0, 230, 255, 255), note, nullptr,
                    cv.size.x - em());   // wrapped to the canvas
    }
}

// Hover: an arc within 5 px first (its equation and interior maxima), else the domain under the
// mouse (its label, d^2 and area).
void hover_tooltip(Stepper& st, const DomainMesh& mesh, const Canvas& cv, const std::vector<Candidate>& candidates) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    int best = -1;
    float bd = 5.0f;
    for (const ArcDraw& a : st.arcs)
        for (size_t i = 0; i + 1 < a.pts.size(); ++i) {
            ImVec2 p = cv.to_screen(a.pts[i]), q = cv.to_screen(a.pts[i + 1]);
            float dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
            float t = l2 > 0 ? std::clamp(((m.x - p.x) * dx + (m.y - p.y) * dy) / l2, 0.0f, 1.0f) : 0.0f;
            float ex = p.x + t * dx - m.x, ey = p.y + t * dy - m.y, dd = std::sqrt(ex * ex + ey * ey);
            if (dd < bd) bd = dd, best = a.edge;
        }
    st.hover_arc = best;
    if (best >= 0) {
        const auto& E = mesh.edges()[best];
        ImGui::BeginTooltip();
        ImGui::Text("arc %d: %s, %s", best, arc_kind_name(E.kind), conic_type_name(decompose_conic(E.equation).type));
        ImGui::Text("%s = 0", E.equation.to_string().c_str());
        bool any = false;
        for (const Candidate& c : candidates)
            if (c.edge == best) {
                ImGui::Text("interior maximum d^2 %.6g at %s", c.value, vec_text(c.p).c_str());
                any = true;
            }
        if (!any) ImGui::TextDisabled("no interior maximum");
        ImGui::EndTooltip();
        return;
    }
    const int f = mesh.face_at(cv.to_frame(m));
    st.hover_face = f;
    if (f >= 0) {
        const auto& F = mesh.faces()[f];
        ImGui::BeginTooltip();
        ImGui::Text("domain %d: %s", f, label_text(F.label, F.infinite).c_str());
        if (!F.infinite) ImGui::Text("d^2 = %s", F.poly.to_string().c_str());
        ImGui::Text("area %.6g (frame units)", mesh.face_area(f));
        ImGui::EndTooltip();
    }
}

// The legend right of the canvas: the overlay's checkbox and verdict, then every label once,
// with its colour.
void legend(Stepper& st, const DomainMesh* mesh, float height) {
    ImGui::BeginChild("legend", ImVec2(0, height), false);
    ImGui::Checkbox("overlay", &st.show_overlay);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("colour T' by the nearest source feature, computed directly from the sources\n"
                          "(CPU, %d px), and compare with the domain mesh's labels", 256);
    if (st.show_overlay && st.overlay_revision == st.revision && mesh) {
        if (st.overlay_disagree == 0)
            ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "overlay agrees");
        else
            ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "overlay disagrees at %ld samples: core bug?", st.overlay_disagree);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%ld samples compared (%ld agree by a tie: another feature with the same\n"
                              "quadratic is nearest, e.g. coplanar sources or a shared edge),\n%ld within 2 px of a change not compared",
                              st.overlay_samples, st.overlay_ties, st.overlay_ignored);
        if (st.overlay_ties > 0)  // shown as ties, not as disagreements (on a line of its own: the legend is narrow)
            ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "%.0f%% ties", 100.0 * st.overlay_ties / std::max(1L, st.overlay_samples));
    }
    ImGui::TextDisabled("%d domains", st.live_domains);
    std::map<std::pair<int, int>, std::pair<ImU32, int>> labels;
    for (const DomainDraw& d : st.domains) {
        auto& e = labels[{d.infinite ? -1 : d.label.source, d.infinite ? 0 : (int)d.label.region}];
        e.first = d.colour;
        ++e.second;
    }
    for (const auto& [key, val] : labels) {
        ImVec2 p = ImGui::GetCursorScreenPos();
        const float sz = ImGui::GetTextLineHeight();
        ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + sz, p.y + sz), val.first);
        ImGui::Dummy(ImVec2(sz, sz));
        ImGui::SameLine();
        DomainLabel l;
        l.source = key.first;
        l.region = (Region)key.second;
        if (val.second > 1)
            ImGui::Text("%s  (x%d)", label_text(l, key.first < 0).c_str(), val.second);
        else
            ImGui::TextUnformatted(label_text(l, key.first < 0).c_str());
    }
    ImGui::EndChild();
}

}  // namespace

void draw_domain_view(AppState& s) {
    Stepper& st = s.stepper;
    if (!st.open || !st.active()) return;
    if (!begin_tile("Domain view", s.tiles.domain, st.open, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) return;
    s.tiles.domain_w = ImGui::GetWindowSize().x;   // the user may drag the right edge
    const TargetSolver& ts = *st.solver;
    const DomainMesh* mesh = st.mesh();   // as it was at the current step
    const TargetFrame& fr = ts.frame();
    // Arc maxima belong to a finished insertion (inside one, the solver's are of the previous mesh).
    static const std::vector<Candidate> kNone;
    const std::vector<Candidate>& candidates = st.snapshot() ? kNone : ts.candidates();

    // The canvas: an invisible button left of the legend, taking the mouse.
    const float legend_w = 10 * em();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 c0 = ImGui::GetCursorScreenPos();
    ImVec2 csize(std::max(4 * em(), avail.x - legend_w - 0.5f * em()), std::max(4 * em(), avail.y));
    ImGui::InvisibleButton("canvas", csize, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    st.view_rect[0] = c0.x, st.view_rect[1] = c0.y, st.view_rect[2] = csize.x, st.view_rect[3] = csize.y;
    const Canvas cv(st, fr, c0, csize);
    pan_and_zoom(st, cv, hovered, active);
    for (int k = 0; k < 3; ++k) {
        const ImVec2 q = cv.to_screen(fr.corners[k]);
        st.corner_screen[k][0] = q.x, st.corner_screen[k][1] = q.y;
    }
    st.hover_arc = st.hover_face = -1;

    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(cv.c0, cv.c1, true);
    dl->AddRectFilled(cv.c0, cv.c1, IM_COL32(24, 25, 30, 255));
    const bool overlay = draw_fills(st, dl, cv);
    // The tolerance: the part above T shaded, the curve d = T.
    draw_tolerance_in_domain_view(s, dl, cv.c0, cv.c1, [&](Vec2 p) { return cv.to_screen(p); }, !overlay);
    draw_arcs(st, dl, cv, candidates);
    draw_regions(st, dl, cv);
    outline_event_domains(st, dl, cv);
    draw_maximum_and_notes(st, mesh, dl, cv);
    dl->PopClipRect();

    if (hovered && mesh && (!s.headless || s.scripted_input) && !ImGui::IsMouseDragging(ImGuiMouseButton_Right))
        hover_tooltip(st, *mesh, cv, candidates);
    ImGui::SameLine();
    legend(st, mesh, csize.y);
    ImGui::End();
}

}  // namespace hlens::gui
