#include "graph.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include "app_state.h"
#include "colormap.h"
#include "layout.h"
#include "gl.h"
#include "shader.h"

namespace hlens::gui {

namespace {

constexpr int kSubdivisions = 64;   // per edge of T'

struct Vertex {
    float p[3];
    float c[3];
};

// GL resources of the graph view (one view, one GL context).
struct GraphGl {
    bool tried = false;
    std::string error;
    GLuint program = 0;
    GLuint fbo = 0, colour = 0, depth = 0;
    int w = 0, h = 0;
    GLuint vao[2] = {0, 0}, vbo[2] = {0, 0};   // 0: surface triangles, 1: lines
    GLsizei count[2] = {0, 0};
};
GraphGl g;

void colour_of(unsigned c, float out[3]) {
    out[0] = ((c >> IM_COL32_R_SHIFT) & 0xFF) / 255.0f;
    out[1] = ((c >> IM_COL32_G_SHIFT) & 0xFF) / 255.0f;
    out[2] = ((c >> IM_COL32_B_SHIFT) & 0xFF) / 255.0f;
}

bool init_gl() {
    if (g.tried) return g.program != 0;
    g.tried = true;
    g.program = load_program("graph.vert.glsl", "graph.frag.glsl", g.error);
    if (!g.program) return false;
    glGenVertexArrays(2, g.vao);
    glGenBuffers(2, g.vbo);
    for (int i = 0; i < 2; ++i) {
        glBindVertexArray(g.vao[i]);
        glBindBuffer(GL_ARRAY_BUFFER, g.vbo[i]);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)0);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), (void*)(3 * sizeof(float)));
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void ensure_target(int w, int h) {
    if (g.fbo && g.w == w && g.h == h) return;
    if (!g.fbo) {
        glGenFramebuffers(1, &g.fbo);
        glGenTextures(1, &g.colour);
        glGenRenderbuffers(1, &g.depth);
    }
    g.w = w, g.h = h;
    glBindTexture(GL_TEXTURE_2D, g.colour);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, g.depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g.colour, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.depth);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The surface and the lines of the current state, normalised: (x, y) centred on T' and divided by
// its extent, z = d^2 / (max d^2) * 0.6. Long: the surface and its lines share the lattice, its
// heights and the normalisation (`vert`); apart, they would pass all of these around.
void build(Stepper& st) {
    const TargetSolver& ts = *st.solver;
    const TargetFrame& fr = ts.frame();
    const DomainMesh* mesh = st.mesh();   // the state at the current step
    const bool any = st.insertions() > 0;
    const double s2 = fr.scale * fr.scale;
    const Vec2 c0 = fr.corners[0], c1 = fr.corners[1], c2 = fr.corners[2];
    Box2 box;
    for (const Vec2& c : fr.corners) box.add(c);
    const Vec2 mid(0.5 * (box.lo.x + box.hi.x), 0.5 * (box.lo.y + box.hi.y));
    const double ext = std::max({1e-300, box.hi.x - box.lo.x, box.hi.y - box.lo.y});

    // Heights at the lattice points of T' (exact, frame units).
    const int N = kSubdivisions;
    auto index = [N](int i, int j) { return i * (N + 1) - i * (i - 1) / 2 + j; };   // i + j <= N
    std::vector<Vec2> pt;
    std::vector<double> z;
    double zmax = 0, zmin = HUGE_VAL;
    for (int i = 0; i <= N; ++i)
        for (int j = 0; i + j <= N; ++j) {
            Vec2 p = c0 + (c1 - c0) * (double(i) / N) + (c2 - c0) * (double(j) / N);
            double d = any ? st.d2_at(p) : 0.0;
            pt.push_back(p);
            z.push_back(d);
            if (std::isfinite(d)) zmax = std::max(zmax, d), zmin = std::min(zmin, d);
        }
    st.graph_samples = (long)pt.size();
    st.graph_grid_max = any ? zmax * s2 : NAN;
    double zmark = NAN;
    // (inside an insertion the running maximum belongs to the previous state: not marked)
    if (any && std::isfinite(st.max_sq()) && st.inserting() < 0) zmark = st.d2_at(st.max_2d());
    st.graph_z_min = any && std::isfinite(zmin) ? zmin * s2 : NAN;
    st.graph_z_max = any ? std::max(zmax, std::isfinite(zmark) ? zmark : 0.0) * s2 : NAN;
    const double ztop = std::max({zmax, std::isfinite(zmark) ? zmark : 0.0});
    // Relief: z from the smallest to the largest sample (the base plane is then min d^2), else
    // from 0 (the base plane is d^2 = 0).
    const double zlo = st.graph_relief && std::isfinite(zmin) && zmin < ztop ? zmin : 0.0;
    const double zspan = std::max(1e-300, ztop - zlo);
    auto vert = [&](Vec2 p, double d, const float col[3]) {
        Vertex v;
        v.p[0] = (float)((p.x - mid.x) / ext);
        v.p[1] = (float)((p.y - mid.y) / ext);
        v.p[2] = (float)(std::isfinite(d) ? 0.6 * (d - zlo) / zspan : 0.0);
        v.c[0] = col[0], v.c[1] = col[1], v.c[2] = col[2];
        return v;
    };

    // Surface: two triangles per lattice cell, each coloured by the domain at its centroid.
    std::vector<Vertex> tri;
    auto add_tri = [&](int a, int b, int c) {
        Vec2 m = (pt[a] + pt[b] + pt[c]) / 3.0;
        float col[3] = {0.45f, 0.45f, 0.5f};
        if (mesh) {
            int f = mesh->face_at(m);
            if (f >= 0) colour_of(domain_label_colour(mesh->faces()[f].label, mesh->faces()[f].infinite), col);
        }
        tri.push_back(vert(pt[a], z[a], col));
        tri.push_back(vert(pt[b], z[b], col));
        tri.push_back(vert(pt[c], z[c], col));
    };
    for (int i = 0; i < N; ++i)
        for (int j = 0; i + j < N; ++j) {
            add_tri(index(i, j), index(i + 1, j), index(i, j + 1));
            if (i + j + 1 < N) add_tri(index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
        }

    // Lines: every arc of the domain mesh lifted by d^2 (straight arcs resampled, d^2 is not linear
    // along them), slightly raised so the surface does not hide them; the maximum as a vertical
    // red line from the base to the lifted point plus a cross there; T' outlined at z = 0.
    std::vector<Vertex> lines;
    const float dark[3] = {0.06f, 0.06f, 0.08f}, white[3] = {1, 1, 1}, red[3] = {0.95f, 0.1f, 0.12f};
    const float lift = 0.004f;
    auto line = [&](Vertex a, Vertex b) { lines.push_back(a), lines.push_back(b); };
    if (any)
        for (const ArcDraw& a : st.arcs) {
            const float* col = a.kind == ArcKind::TargetBoundary ? white : dark;
            for (size_t k = 0; k + 1 < a.pts.size(); ++k) {
                const int n = a.pts.size() == 2 ? 32 : 2;
                for (int q = 0; q < n; ++q) {
                    Vec2 p = a.pts[k] + (a.pts[k + 1] - a.pts[k]) * (double(q) / n);
                    Vec2 r = a.pts[k] + (a.pts[k + 1] - a.pts[k]) * (double(q + 1) / n);
                    Vertex va = vert(p, st.d2_at(p), col), vb = vert(r, st.d2_at(r), col);
                    va.p[2] += lift, vb.p[2] += lift;
                    line(va, vb);
                }
            }
        }
    for (int k = 0; k < 3; ++k) line(vert(fr.corners[k], zlo, white), vert(fr.corners[(k + 1) % 3], zlo, white));
    if (std::isfinite(zmark)) {
        Vec2 m = st.max_2d();
        Vertex top = vert(m, zmark, red), base = vert(m, zlo, red);
        line(base, top);
        const float r = 0.03f;
        for (int ax = 0; ax < 3; ++ax) {
            Vertex a = top, b = top;
            a.p[ax] -= r, b.p[ax] += r;
            line(a, b);
        }
    }
    for (int i = 0; i < 2; ++i) {
        const std::vector<Vertex>& v = i == 0 ? tri : lines;
        glBindBuffer(GL_ARRAY_BUFFER, g.vbo[i]);
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(v.size() * sizeof(Vertex)), v.data(), GL_STATIC_DRAW);
        g.count[i] = (GLsizei)v.size();
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void render(const Stepper& st, int w, int h) {
    ensure_target(w, h);
    GlStateGuard saved;

    glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
    glViewport(0, 0, w, h);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glClearColor(0.094f, 0.098f, 0.118f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    const float dist = 1.6f / st.graph_zoom;
    const float cp = std::cos(st.graph_pitch), sp = std::sin(st.graph_pitch);
    const glm::vec3 pivot(0, 0, 0.25f);
    const glm::vec3 eye = pivot + dist * glm::vec3(cp * std::cos(st.graph_yaw), cp * std::sin(st.graph_yaw), sp);
    const glm::mat4 mvp = glm::perspective(0.7f, float(w) / float(std::max(h, 1)), 0.01f * dist, dist + 5.0f) *
                          glm::lookAt(eye, pivot, glm::vec3(0, 0, 1));
    glUseProgram(g.program);
    glUniformMatrix4fv(glGetUniformLocation(g.program, "u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
    glUniform3f(glGetUniformLocation(g.program, "u_light"), 0.3f, 0.4f, 1.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glUniform1i(glGetUniformLocation(g.program, "u_lit"), 1);
    glBindVertexArray(g.vao[0]);
    glDrawArrays(GL_TRIANGLES, 0, g.count[0]);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glUniform1i(glGetUniformLocation(g.program, "u_lit"), 0);
    glBindVertexArray(g.vao[1]);
    glDrawArrays(GL_LINES, 0, g.count[1]);

}

}  // namespace

void draw_graph_view(AppState& s) {
    Stepper& st = s.stepper;
    if (!st.open || !st.graph_open || !st.active()) return;
    const float em = ImGui::GetFontSize();
    if (!begin_tile("Graph of d^2", s.tiles.graph, st.graph_open, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) return;
    s.tiles.strip_h = ImGui::GetWindowSize().y;                          // the strip's top edge
    if (s.tiles.log_on) s.tiles.graph_w = ImGui::GetWindowSize().x;      // and the edge it shares with the log
    if (!init_gl()) {
        ImGui::TextWrapped("graph view unavailable: %s", g.error.c_str());
        ImGui::End();
        return;
    }
    if (st.graph_revision != st.revision) {
        build(st);
        st.graph_revision = st.revision;
    }
    if (std::isfinite(st.graph_z_max)) {
        ImGui::Text("%ld samples  d^2 %.6g .. %.6g", st.graph_samples, st.graph_z_min, st.graph_z_max);
        ImGui::SameLine();
        if (ImGui::Checkbox("relief", &st.graph_relief)) st.graph_revision = 0;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("height from min d^2 to max d^2 (off: from 0)");
    } else
        ImGui::TextDisabled("no source inserted yet: d^2 = inf");
    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 size(std::max(4 * em, avail.x), std::max(4 * em, avail.y));
    ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("graph_canvas", size, ImGuiButtonFlags_MouseButtonLeft);
    st.graph_rect[0] = p0.x, st.graph_rect[1] = p0.y, st.graph_rect[2] = size.x, st.graph_rect[3] = size.y;
    ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        st.graph_yaw -= io.MouseDelta.x * 0.01f;
        st.graph_pitch = std::clamp(st.graph_pitch + io.MouseDelta.y * 0.01f, -1.55f, 1.55f);
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0)
        st.graph_zoom = std::clamp(st.graph_zoom * std::pow(1.15f, io.MouseWheel), 0.2f, 50.0f);
    const int w = std::max(1, (int)(size.x * io.DisplayFramebufferScale.x)),
              h = std::max(1, (int)(size.y * io.DisplayFramebufferScale.y));
    render(st, w, h);
    ImGui::GetWindowDrawList()->AddImage((ImTextureID)(intptr_t)g.colour, p0, ImVec2(p0.x + size.x, p0.y + size.y),
                                         ImVec2(0, 1), ImVec2(1, 0));
    ImGui::End();
}

}  // namespace hlens::gui
