#include "view3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <imgui.h>

#include "colormap.h"
#include "gl.h"
#include "panels.h"
#include "ui.h"

namespace hlens::gui {

namespace {

bool project(const glm::mat4& mvp, const ViewRect& v, const glm::vec3& p, ImVec2& out) {
    glm::vec4 c = mvp * glm::vec4(p, 1.0f);
    if (c.w <= 1e-7f) return false;
    out = ImVec2(v.x + (0.5f + 0.5f * c.x / c.w) * v.w, v.y + (0.5f - 0.5f * c.y / c.w) * v.h);
    return true;
}

// The centroid of the selected target of the current direction and its reach (the largest
// distance from the centroid to a point of T', world units); false without a selected target.
bool selected_target_ball(const AppState& s, Vec3& centroid, double& reach) {
    const int d = s.direction;
    const long t = s.selected[d];
    if (!s.scene || t < 0 || (size_t)t >= s.scene->mesh[d].num_triangles()) return false;
    const auto c = s.scene->mesh[d].corners((size_t)t);
    centroid = (c[0] + c[1] + c[2]) / 3.0;
    reach = 0;
    for (const Vec3& p : c) reach = std::max(reach, norm(p - centroid));
    return true;
}

// The selected target: outline, and where its maximum is (once traced).
void draw_target(ImDrawList* dl, const AppState& s, const Scene& scene, const glm::mat4& mvp, float r) {
    const ViewRect& v = s.view;
    const int d = s.direction;
    const long t = s.selected[d];
    if (t < 0 || (size_t)t >= s.scene->mesh[d].num_triangles()) return;
    auto c = s.scene->mesh[d].corners((size_t)t);
    ImVec2 q[3];
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok = ok && project(mvp, v, scene.local(c[i]), q[i]);
    if (ok) dl->AddPolyline(q, 3, IM_COL32(255, 255, 255, 255), ImDrawFlags_Closed, 2.0f);
    ImVec2 m;
    if (s.trace[d] && s.trace[d]->target == (uint32_t)t && s.trace[d]->error.empty() &&
        project(mvp, v, scene.local(s.trace[d]->max_point), m)) {
        dl->AddLine(ImVec2(m.x - r, m.y - r), ImVec2(m.x + r, m.y + r), IM_COL32(255, 255, 255, 255), 2);
        dl->AddLine(ImVec2(m.x - r, m.y + r), ImVec2(m.x + r, m.y - r), IM_COL32(255, 255, 255, 255), 2);
    }
}

// The stepped target's sources inserted so far, over the other mesh (the latest brighter).
void draw_inserted_sources(ImDrawList* dl, const AppState& s, const Scene& scene, const glm::mat4& mvp) {
    const Stepper& st = s.stepper;
    const std::vector<uint32_t> ins = st.inserted_sources();
    const TriangleMesh& other = s.scene->mesh[1 - s.direction];
    for (size_t i = 0; i < ins.size(); ++i) {
        if (ins[i] >= other.num_triangles()) continue;
        auto c = other.corners(ins[i]);
        ImVec2 q[3];
        bool ok = true;
        for (int k = 0; k < 3; ++k) ok = ok && project(mvp, s.view, scene.local(c[k]), q[k]);
        if (!ok) continue;
        const bool last = i + 1 == ins.size();
        dl->AddTriangleFilled(q[0], q[1], q[2], last ? IM_COL32(255, 200, 40, 150) : IM_COL32(40, 220, 255, 90));
        dl->AddPolyline(q, 3, last ? IM_COL32(255, 220, 80, 255) : IM_COL32(60, 230, 255, 220), ImDrawFlags_Closed, 1.5f);
    }
}

// Voxels seen so far at the current step, as wireframe boxes coloured by state.
void draw_voxels(ImDrawList* dl, const AppState& s, const Scene& scene, const glm::mat4& mvp) {
    static const int kEdge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    const MeshGrid& sources = s.scene->grid->of(1 - s.direction);  // the grid the target searches
    for (const auto& [vox, state] : s.stepper.voxels) {
        if (vox >= sources.num_voxels()) continue;
        const Box3 b = sources.voxel_box(vox);
        ImVec2 q[8];
        bool ok = true;
        for (int k = 0; k < 8 && ok; ++k)
            ok = project(mvp, s.view, scene.local(Vec3{k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z}), q[k]);
        if (!ok) continue;
        const ImU32 col = state == 2 ? IM_COL32(70, 230, 90, 200) : state == 1 ? IM_COL32(240, 220, 60, 200)
                                                                            : IM_COL32(140, 140, 140, 150);
        for (const auto& e : kEdge) dl->AddLine(q[e[0]], q[e[1]], col, 1.0f);
    }
}

// The search radius envelope: the sphere around the centroid of T' of radius r + (farthest corner
// from the centroid). It encloses every point within r of T' (a bounding sphere of that set, not
// the set itself). Drawn as the projected outline of the sphere (the farthest projection of
// points sampled on it).
void draw_search_radius(ImDrawList* dl, const AppState& s, const Scene& scene, const glm::mat4& mvp) {
    const ViewRect& v = s.view;
    const double r = s.stepper.search_radius();
    Vec3 g;
    double reach = 0;
    if (!std::isfinite(r) || !selected_target_ball(s, g, reach)) return;
    const double R = r + reach;
    ImVec2 cg;
    if (!project(mvp, v, scene.local(g), cg)) return;
    float rad = 0;
    bool ok = true;
    for (int i = 0; i <= 12 && ok; ++i)
        for (int j = 0; j < 24 && ok; ++j) {
            const double th = M_PI * i / 12, ph = 2 * M_PI * j / 24;
            const Vec3 p{g.x + R * std::sin(th) * std::cos(ph), g.y + R * std::sin(th) * std::sin(ph), g.z + R * std::cos(th)};
            ImVec2 q;
            ok = project(mvp, v, scene.local(p), q);
            if (ok) rad = std::max(rad, std::hypot(q.x - cg.x, q.y - cg.y));
        }
    if (ok && rad > 0) {
        dl->AddCircleFilled(cg, rad, IM_COL32(120, 170, 255, 40), 64);
        dl->AddCircle(cg, rad, IM_COL32(140, 190, 255, 200), 64, 1.5f);
        dl->AddText(ImVec2(cg.x + 0.72f * rad, cg.y - 0.72f * rad), IM_COL32(170, 205, 255, 255), "search radius");
    }
}

// Witnesses: from_point (filled) on the measured mesh, to_point (ring) on the other, labelled.
void draw_witnesses(ImDrawList* dl, const AppState& s, const Scene& scene, const glm::mat4& mvp, float r) {
    for (int dd = 0; dd < 2; ++dd) {
        if (!s.show_witness[dd]) continue;
        const OneSidedResult& w = dd == 0 ? s.result.a_to_b : s.result.b_to_a;
        ImVec2 a, b;
        if (!project(mvp, s.view, scene.local(w.from_point), a) || !project(mvp, s.view, scene.local(w.to_point), b))
            continue;
        dl->AddLine(a, b, IM_COL32(0, 0, 0, 200), 4.0f);
        dl->AddLine(a, b, kWitnessColor[dd], 2.0f);
        dl->AddCircleFilled(a, r, kWitnessColor[dd]);
        dl->AddCircle(a, r, IM_COL32(0, 0, 0, 255), 0, 1.5f);
        dl->AddCircle(b, r, kWitnessColor[dd], 0, 2.0f);
        char label[32];
        std::snprintf(label, sizeof label, "h(%s,%s)", kSide[dd], kSide[1 - dd]);
        ImVec2 lp(a.x + 1.6f * r, a.y - 2.6f * r), ls = ImGui::CalcTextSize(label);
        dl->AddRectFilled(ImVec2(lp.x - 3, lp.y - 1), ImVec2(lp.x + ls.x + 3, lp.y + ls.y + 1),
                          IM_COL32(20, 20, 24, 210), 3.0f);
        dl->AddText(lp, kWitnessColor[dd], label);
    }
}

}  // namespace

bool init_view3d(View3D& v) {
    v.scene = std::make_unique<Scene>();
    v.picker = std::make_unique<Picker>();
    std::string gl_error;
    if (!v.scene->init(gl_error) || !v.picker->init(gl_error)) {
        std::fprintf(stderr, "hlens: %s\n", gl_error.c_str());
        return false;
    }
    return true;
}

void release_view3d(View3D& v) {
    v.picker.reset();
    v.scene.reset();
}

void begin_view3d(View3D& v, const AppState& s, int fb_w, int fb_h) {
    const ImGuiIO& io = ImGui::GetIO();
    v.fb_w = fb_w, v.fb_h = fb_h;
    v.fbs_x = io.DisplayFramebufferScale.x, v.fbs_y = io.DisplayFramebufferScale.y;
    v.vx = (int)std::lround(s.view.x * v.fbs_x), v.vw = std::max(1, (int)std::lround(s.view.w * v.fbs_x));
    v.vh = std::max(1, (int)std::lround(s.view.h * v.fbs_y));
    v.vy = std::max(0, fb_h - (int)std::lround((s.view.y + s.view.h) * v.fbs_y));
    v.aspect = float(v.vw) / float(v.vh);
    v.camera.up_axis = s.up_axis;
    if (v.need_home && v.scene->loaded()) {
        v.camera.frame(v.scene->box_lo(), v.scene->box_hi(), v.aspect);
        v.need_home = false;
    }
}

ViewParams view_params(const View3D& v, const AppState& s) {
    ViewParams p;
    p.mvp = v.camera.projection(v.aspect) * v.camera.view();
    p.eye = v.camera.eye();
    p.viewport[0] = v.vx;
    p.viewport[1] = v.vy;
    p.viewport[2] = v.vw;
    p.viewport[3] = v.vh;
    p.style[0] = s.style[0];
    p.style[1] = s.style[1];
    p.measured = s.direction;
    p.use_map = s.show_colormap && s.range[s.direction].valid;
    p.lo = s.range[s.direction].lo;
    p.hi = s.range[s.direction].hi;
    p.selected = (int)s.selected[s.direction];
    p.hatch = std::round(hatch_period(ImGui::GetFontSize()) * v.fbs_x);
    p.tolerance = s.computed ? (float)s.tolerance : -1.0f;
    p.outline = std::max(1.5f, 0.12f * ImGui::GetFontSize() * v.fbs_x);
    return p;
}

void view3d_input(View3D& v, AppState& s) {
    const ImGuiIO& io = ImGui::GetIO();
    Camera& camera = v.camera;
    const ImVec2 m = io.MousePos;
    const bool over_view = !io.WantCaptureMouse && s.view.contains(m.x, m.y) && v.scene->loaded();
    for (int b = 0; b < 3; ++b)
        if (ImGui::IsMouseClicked(b)) v.press_in_view[b] = over_view;
    if (ImGui::IsMouseClicked(0)) v.press_was_double = ImGui::IsMouseDoubleClicked(0);
    // (no mouse: ImGui's position is -FLT_MAX, which does not convert to int)
    const bool mouse_ok = ImGui::IsMousePosValid(&m);
    const int px = mouse_ok ? (int)(m.x * v.fbs_x) : -1, py = mouse_ok ? v.fb_h - 1 - (int)(m.y * v.fbs_y) : -1;
    if (v.press_in_view[0] && ImGui::IsMouseDown(0)) {
        if (io.KeyShift)
            camera.pan(io.MouseDelta.x * v.fbs_x, io.MouseDelta.y * v.fbs_y, (float)v.vh);
        else
            camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
    }
    if ((v.press_in_view[1] && ImGui::IsMouseDown(1)) || (v.press_in_view[2] && ImGui::IsMouseDown(2)))
        camera.pan(io.MouseDelta.x * v.fbs_x, io.MouseDelta.y * v.fbs_y, (float)v.vh);
    if (over_view && io.MouseWheel != 0) camera.zoom(io.MouseWheel);
    if (over_view && ImGui::IsMouseDoubleClicked(0)) {   // recentre on the surface point there
        PickHit hit = v.picker->pick(*v.scene, view_params(v, s), 3u, v.fb_w, v.fb_h, px, py);
        if (hit.mesh >= 0) camera.pivot = hit.point;
    }
    // A click picks when it ends, and only if the mouse did not travel (not the end of a drag).
    const float thr = io.MouseDragThreshold;
    if (ImGui::IsMouseReleased(0) && v.press_in_view[0] && !v.press_was_double &&
        io.MouseDragMaxDistanceSqr[0] < thr * thr && s.view.contains(m.x, m.y)) {
        PickHit hit = v.picker->pick(*v.scene, view_params(v, s), 1u << s.direction, v.fb_w, v.fb_h, px, py);
        s.req.select = hit.mesh == s.direction ? hit.triangle : -1;
    }
    for (int b = 0; b < 3; ++b)
        if (ImGui::IsMouseReleased(b)) v.press_in_view[b] = false;
    if (!io.WantCaptureKeyboard && !io.WantTextInput) {   // never while typing in a text field
        if (ImGui::IsKeyPressed(GLFW_KEY_F1, false)) s.help_open = !s.help_open;
        if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) s.req.home = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) s.req.focus = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) s.req.screenshot = true;
    }
}

void draw_view_overlay(const AppState& s, const Scene& scene, const glm::mat4& mvp) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ViewRect& v = s.view;
    dl->PushClipRect(ImVec2(v.x, v.y), ImVec2(v.x + v.w, v.y + v.h), false);
    const float r = 0.38f * em();
    if (scene.loaded() && s.scene) {
        draw_target(dl, s, scene, mvp, r);
        const Stepper& st = s.stepper;
        const int d = s.direction;
        if (st.open && st.active() && st.scene == s.scene && st.side == d && st.target == s.selected[d]) {
            draw_inserted_sources(dl, s, scene, mvp);
            if (st.show_voxels && s.scene->grid) {
                draw_voxels(dl, s, scene, mvp);
                draw_search_radius(dl, s, scene, mvp);
            }
        }
        if (s.computed) draw_witnesses(dl, s, scene, mvp, r);
    }
    const char* hint = "drag: orbit  right-drag: pan  wheel: zoom  click: pick";
    ImVec2 ts = ImGui::CalcTextSize(hint);
    if (scene.loaded() && ts.x + em() < v.w)
        dl->AddText(ImVec2(v.x + 0.5f * em(), v.y + v.h - ts.y - 0.4f * em()), IM_COL32(170, 170, 180, 255), hint);
    dl->PopClipRect();
}

void frame_camera(View3D& v, const AppState& s, bool home, bool focus) {
    const Scene& scene = *v.scene;
    if (home && scene.loaded()) v.camera.frame(scene.box_lo(), scene.box_hi(), v.aspect);
    // Opening the timeline of a target (or stepping another one) frames it, with room for the
    // sphere of its largest distance, so the voxels and the search radius are visible.
    const long key = s.stepper.open && s.stepper.active() ? s.stepper.side * (1L << 40) + s.stepper.target : -1;
    if (key != v.focused_key && key >= 0) focus = true;
    v.focused_key = key;
    const Camera& c = v.camera;
    const bool untouched = c.pivot == v.focused.pivot && c.distance == v.focused.distance && c.yaw == v.focused.yaw && c.pitch == v.focused.pitch;
    if (key >= 0 && v.focus_aspect > 0 && untouched && (v.aspect != v.focus_aspect || s.computed != v.focus_computed)) focus = true;
    Vec3 centroid;
    double reach = 0;
    if (focus && scene.loaded() && selected_target_ball(s, centroid, reach)) {
        // The room is the target's bound from the distance run (at least its maximum), not the
        // exact value, which the background map may or may not have found yet: the framing must
        // not depend on that timing.
        const OneSidedResult& r = s.direction == 0 ? s.result.a_to_b : s.result.b_to_a;
        const long t = s.selected[s.direction];
        const double tmax = s.computed && t >= 0 && (size_t)t < r.target_max.size() ? r.target_max[t] : 0;
        const float half = (float)(1.15 * (reach + (std::isfinite(tmax) ? tmax : 0.0))) + 1e-6f;
        const glm::vec3 g = scene.local(centroid);
        v.camera.focus(g - glm::vec3(half), g + glm::vec3(half), v.aspect);
        v.focus_aspect = v.aspect;
        v.focus_computed = s.computed;
        v.focused = v.camera;
    }
}

void draw_view3d(const View3D& v, const ViewParams& p) {
    glViewport(0, 0, v.fb_w, v.fb_h);
    glClearColor(kClearColor[0], kClearColor[1], kClearColor[2], kClearColor[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    v.scene->draw(p);
}

}  // namespace hlens::gui
