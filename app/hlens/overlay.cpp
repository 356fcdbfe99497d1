#include "overlay.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <imgui.h>

#include "colormap.h"
#include "gl.h"
#include <hlens/label_check.h>
#include "shader.h"
#include "stepper.h"

namespace hlens::gui {

namespace {

constexpr int kResolution = 256;   // pixels along the longer side of T''s bounding box
constexpr int kBorder = 2;         // samples this close (in overlay pixels) to a change are not compared

GLuint g_tex = 0;

constexpr int kGpuResolution = 1024;   // pixels along the longer side of the GPU overlay

// The GPU path: overlay.frag.glsl renders the nearest feature per fragment into g_gpu.tex.
struct GpuOverlay {
    bool tried = false;
    std::string error;
    GLuint program = 0, vao = 0, vbo = 0, fbo = 0, tex = 0, sources = 0;
    int w = 0, h = 0;
} g_gpu;

// Renders the overlay on the GPU; false (and the CPU picture is used) when the shader is missing.
bool render_gpu(const std::vector<std::array<Vec3, 3>>& src, const std::vector<uint32_t>& ids, const TargetFrame& fr,
                Vec2 lo, Vec2 hi, int W, int H) {
    if (!g_gpu.tried) {
        g_gpu.tried = true;
        g_gpu.program = load_program("overlay.vert.glsl", "overlay.frag.glsl", g_gpu.error);
        if (g_gpu.program) {
            glGenVertexArrays(1, &g_gpu.vao);
            glGenBuffers(1, &g_gpu.vbo);
            glGenFramebuffers(1, &g_gpu.fbo);
            glGenTextures(1, &g_gpu.tex);
            glGenTextures(1, &g_gpu.sources);
        }
    }
    if (!g_gpu.program) return false;
    if (g_gpu.w != W || g_gpu.h != H) {
        g_gpu.w = W, g_gpu.h = H;
        glBindTexture(GL_TEXTURE_2D, g_gpu.tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindFramebuffer(GL_FRAMEBUFFER, g_gpu.fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g_gpu.tex, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    // One row per source: three corners, then the seven region colours.
    const int n = std::max<int>(1, (int)src.size());
    std::vector<float> data((size_t)n * 10 * 4, 0.0f);
    for (size_t s = 0; s < src.size(); ++s) {
        float* row = &data[s * 40];
        for (int k = 0; k < 3; ++k) row[4 * k] = (float)src[s][k].x, row[4 * k + 1] = (float)src[s][k].y, row[4 * k + 2] = (float)src[s][k].z;
        for (int r = 0; r < 7; ++r) {
            DomainLabel l;
            l.source = (int32_t)ids[s], l.region = (Region)r;
            const unsigned c = domain_label_colour(l, false);
            float* t = row + 4 * (3 + r);
            t[0] = ((c >> IM_COL32_R_SHIFT) & 0xFF) / 255.0f, t[1] = ((c >> IM_COL32_G_SHIFT) & 0xFF) / 255.0f;
            t[2] = ((c >> IM_COL32_B_SHIFT) & 0xFF) / 255.0f, t[3] = 1.0f;
        }
    }
    glBindTexture(GL_TEXTURE_2D, g_gpu.sources);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 10, n, 0, GL_RGBA, GL_FLOAT, data.data());
    const float quad[12] = {(float)lo.x, (float)lo.y, (float)hi.x, (float)lo.y, (float)hi.x, (float)hi.y,
                            (float)lo.x, (float)lo.y, (float)hi.x, (float)hi.y, (float)lo.x, (float)hi.y};
    GlStateGuard saved;
    glBindVertexArray(g_gpu.vao);
    glBindBuffer(GL_ARRAY_BUFFER, g_gpu.vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), (void*)0);
    glBindFramebuffer(GL_FRAMEBUFFER, g_gpu.fbo);
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST), glDisable(GL_BLEND), glDisable(GL_CULL_FACE), glDisable(GL_SCISSOR_TEST);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(g_gpu.program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, g_gpu.sources);
    const GLuint P = g_gpu.program;
    glUniform1i(glGetUniformLocation(P, "u_sources"), 0);
    glUniform1i(glGetUniformLocation(P, "u_count"), (GLint)src.size());
    glUniform2f(glGetUniformLocation(P, "u_lo"), (float)lo.x, (float)lo.y);
    glUniform2f(glGetUniformLocation(P, "u_hi"), (float)hi.x, (float)hi.y);
    glUniform2f(glGetUniformLocation(P, "u_t0"), (float)fr.corners[0].x, (float)fr.corners[0].y);
    glUniform2f(glGetUniformLocation(P, "u_t1"), (float)fr.corners[1].x, (float)fr.corners[1].y);
    glUniform2f(glGetUniformLocation(P, "u_t2"), (float)fr.corners[2].x, (float)fr.corners[2].y);
    glUniform4f(glGetUniformLocation(P, "u_none"), 70 / 255.0f, 72 / 255.0f, 80 / 255.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

}  // namespace

void update_overlay(Stepper& st) {
    if (!st.solver || st.overlay_revision == st.revision) return;
    st.overlay_revision = st.revision;
    const TargetSolver& ts = *st.solver;
    const TargetFrame& fr = ts.frame();
    const DomainMesh* mesh = st.mesh();   // the state at the current step
    st.overlay_samples = st.overlay_disagree = st.overlay_ignored = st.overlay_ties = 0;
    st.overlay_w = st.overlay_h = 0;
    if (!mesh) return;

    // The sources in the target's frame (frame units, z along the target's normal).
    std::vector<std::array<Vec3, 3>> src;
    const std::vector<uint32_t> ids = st.inserted_sources();
    // Inside an insertion the domains the source has not reached yet still hold the previous
    // state, those it took hold the new one: a sample labelled by the source being inserted is
    // compared with the nearest feature over all sources, any other with the nearest feature
    // over the sources before it (where the previous state is still right).
    const int cur = st.inserting() >= 0 && !ids.empty() ? (int)ids.size() - 1 : -1;
    // The comparison itself is the core's (label_check.h: the tie rule of the domain mesh).
    std::vector<std::array<Vec3, 3>> world;
    for (uint32_t s : ids) {
        world.push_back(ts.source_corners(s));
        src.push_back(source_in_frame(fr, world.back()));  // for the GPU picture
    }
    LabelCheckOptions opt;
    opt.resolution = kResolution;
    opt.border = kBorder;
    opt.current = cur;
    const LabelCheck L = check_labels(*mesh, fr, world, ids, opt);
    st.overlay_samples = L.samples, st.overlay_disagree = L.disagree, st.overlay_ignored = L.ignored, st.overlay_ties = L.ties;
    const int W = L.width, H = L.height, n = W * H;
    st.overlay_w = W, st.overlay_h = H;
    st.overlay_lo = L.lo;
    st.overlay_hi = L.hi;
    const std::vector<int>&feat = L.nearest, &dom = L.domain;
    Box2 box;
    for (const Vec2& c : fr.corners) box.add(c);
    const double bw = std::max(1e-300, box.hi.x - box.lo.x), bh = std::max(1e-300, box.hi.y - box.lo.y);

    // The picture: the nearest feature's label in the domain view's colours (so where the two
    // agree, the overlay looks like the domain fills), transparent outside T'.
    std::vector<unsigned> rgba(n, 0);
    for (int i = 0; i < n; ++i) {
        if (dom[i] == -1) continue;   // outside T' (the domain mesh covers exactly T')
        DomainLabel l;
        if (feat[i] >= 0) l.source = (int32_t)ids[feat[i] / 8], l.region = (Region)(feat[i] % 8);
        rgba[i] = domain_label_colour(l, feat[i] < 0);
    }
    if (!g_tex) glGenTextures(1, &g_tex);
    glBindTexture(GL_TEXTURE_2D, g_tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    st.overlay_tex = g_tex;
    st.overlay_gpu = false;
    if (st.overlay_use_gpu && cur < 0) {   // (the shader knows one set of sources: not inside an insertion)
        // The same box at a finer resolution (the texture's row 0 is the bottom: drawn flipped).
        const double gp = std::max(bw, bh) / kGpuResolution;
        const int GW = std::max(1, (int)std::ceil(bw / gp)), GH = std::max(1, (int)std::ceil(bh / gp));
        const Vec2 ghi(box.lo.x + GW * gp, box.lo.y + GH * gp);
        if (render_gpu(src, ids, fr, box.lo, ghi, GW, GH)) {
            st.overlay_tex = g_gpu.tex;
            st.overlay_gpu = true;
            st.overlay_hi = ghi;
        }
    }
}

}  // namespace hlens::gui
