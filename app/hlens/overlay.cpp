#include "overlay.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <imgui.h>

#include "gl.h"
#include "shader.h"
#include "stepper.h"

namespace hlens::gui {

namespace {

constexpr int kResolution = 256;   // pixels along the longer side of T''s bounding box
constexpr int kBorder = 2;         // samples this close (in overlay pixels) to a change are not compared

struct Feature {
    double d2 = HUGE_VAL;
    Region region = Region::abc;
};

// Squared distance from p to triangle abc and which of its seven regions p's closest point is in
// (Ericson, Real-Time Collision Detection 5.1.5, with the edge regions named ab, bc, ca).
Feature closest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    auto d2 = [&](const Vec3& q) { return norm2(p - q); };
    const double d1 = dot(ab, ap), d2_ = dot(ac, ap);
    if (d1 <= 0 && d2_ <= 0) return {d2(a), Region::a};
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {d2(b), Region::b};
    const double vc = d1 * d4 - d3 * d2_;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return {d2(a + ab * (d1 / (d1 - d3))), Region::ab};
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {d2(c), Region::c};
    const double vb = d5 * d2_ - d1 * d6;
    if (vb <= 0 && d2_ >= 0 && d6 <= 0) return {d2(a + ac * (d2_ / (d2_ - d6))), Region::ca};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return {d2(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))), Region::bc};
    const double den = 1.0 / (va + vb + vc);
    return {d2(a + ab * (vb * den) + ac * (vc * den)), Region::abc};
}

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
    for (uint32_t s : ids) {
        std::array<Vec3, 3> c = ts.source_corners(s), f;
        for (int k = 0; k < 3; ++k) {
            Vec3 w = (c[k] - fr.origin) / fr.scale;
            f[k] = Vec3(dot(w, fr.e1), dot(w, fr.e2), dot(w, fr.normal));
        }
        src.push_back(f);
    }

    Box2 box;
    for (const Vec2& c : fr.corners) box.add(c);
    const double bw = std::max(1e-300, box.hi.x - box.lo.x), bh = std::max(1e-300, box.hi.y - box.lo.y);
    const double px = std::max(bw, bh) / kResolution;
    const int W = std::max(1, (int)std::ceil(bw / px)), H = std::max(1, (int)std::ceil(bh / px));
    st.overlay_w = W, st.overlay_h = H;
    st.overlay_lo = box.lo;
    st.overlay_hi = Vec2(box.lo.x + W * px, box.lo.y + H * px);

    // Per pixel (row 0 at the top): the nearest feature (first minimum over the sources, as a
    // label) and the domain mesh's label there; -1 outside T' or without a domain.
    const int n = W * H;
    std::vector<int> feat(n, -1), dom(n, -1);
    std::vector<Vec2> where(n);
    std::vector<double> best_d2(n, HUGE_VAL);
    auto code = [](int source_slot, Region r) { return source_slot * 8 + (int)r; };
    auto slot = [&](int source) {
        for (size_t i = 0; i < ids.size(); ++i)
            if ((int)ids[i] == source) return (int)i;
        return -1;
    };
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int i = y * W + x;
            const Vec2 p(box.lo.x + (x + 0.5) * px, box.lo.y + (H - y - 0.5) * px);
            where[i] = p;
            const int f = mesh->face_at(p);
            if (f < 0) continue;
            const auto& F = mesh->faces()[f];
            dom[i] = F.infinite || F.label.source < 0 ? -2 : code(slot(F.label.source), F.label.region);
            if (src.empty()) continue;
            const Vec3 q(p.x, p.y, 0);
            Feature best;
            int bs = -1;
            for (size_t s = 0; s < src.size(); ++s) {
                if ((int)s == cur) continue;
                Feature ft = closest_feature(q, src[s][0], src[s][1], src[s][2]);
                if (ft.d2 < best.d2) best = ft, bs = (int)s;
            }
            if (cur >= 0 && dom[i] >= 0 && dom[i] / 8 == cur) {
                Feature ft = closest_feature(q, src[cur][0], src[cur][1], src[cur][2]);
                if (ft.d2 < best.d2) best = ft, bs = cur;
            }
            if (bs < 0) continue;
            feat[i] = code(bs, best.region);
            best_d2[i] = best.d2;
        }

    // Compare away from changes: the domain's label must name a feature that is nearest at the
    // sample, i.e. the labelled source's region test gives the labelled region and that source's
    // distance equals the minimum (to 1e-9 relative: shared edges and corners of neighbouring
    // sources are ties, and either source is a correct label there).
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int i = y * W + x;
            if (dom[i] < 0 || feat[i] < 0) continue;
            bool near_change = false;
            for (int dy = -kBorder; dy <= kBorder && !near_change; ++dy)
                for (int dx = -kBorder; dx <= kBorder && !near_change; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= W || yy >= H) { near_change = true; break; }
                    const int j = yy * W + xx;
                    near_change = dom[j] != dom[i] || feat[j] != feat[i];
                }
            if (near_change) {
                ++st.overlay_ignored;
                continue;
            }
            ++st.overlay_samples;
            if (dom[i] == feat[i]) continue;
            const int s = dom[i] / 8;
            bool ok = false;
            if (s >= 0 && s < (int)src.size()) {
                Feature ft = closest_feature(Vec3(where[i].x, where[i].y, 0), src[s][0], src[s][1], src[s][2]);
                ok = (int)ft.region == dom[i] % 8 && ft.d2 <= best_d2[i] * (1 + 1e-9) + 1e-300;
            }
            if (!ok) ++st.overlay_disagree;
            else ++st.overlay_ties;
        }

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
