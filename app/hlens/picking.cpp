#include "picking.h"

#include <glm/gtc/type_ptr.hpp>

#include "shader.h"

namespace hlens::gui {

Picker::~Picker() {
    if (program_) glDeleteProgram(program_);
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (color_) glDeleteRenderbuffers(1, &color_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
}

bool Picker::init(std::string& error) {
    program_ = load_program("mesh.vert.glsl", "pick.frag.glsl", error);
    return program_ != 0;
}

void Picker::resize(int w, int h) {
    if (w == w_ && h == h_ && fbo_) return;
    if (!fbo_) {
        glGenFramebuffers(1, &fbo_);
        glGenRenderbuffers(1, &color_);
        glGenRenderbuffers(1, &depth_);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32UI, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    w_ = w;
    h_ = h;
}

// Draws the meshes of `mask` into the ID framebuffer, which is left bound; filled, or `as_drawn`
// (a wireframe mesh as its lines).
void Picker::render_ids(const Scene& scene, const ViewParams& p, unsigned mask, int fb_width, int fb_height, bool as_drawn) {
    resize(fb_width, fb_height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(p.viewport[0], p.viewport[1], p.viewport[2], p.viewport[3]);
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, zero);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUseProgram(program_);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_mvp"), 1, GL_FALSE, glm::value_ptr(p.mvp));
    for (int side = 0; side < 2; ++side) {
        if (!(mask & (1u << side)) || !p.style[side].visible) continue;
        glUniform1ui(glGetUniformLocation(program_, "u_mesh"), (GLuint)side);
        glPolygonMode(GL_FRONT_AND_BACK, as_drawn && p.style[side].mode == DrawMode::Wireframe ? GL_LINE : GL_FILL);
        scene.mesh(side).draw();
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUseProgram(0);
}

std::vector<int> Picker::triangle_ids(const Scene& scene, const ViewParams& p, int side, int fb_width, int fb_height) {
    const int w = p.viewport[2], h = p.viewport[3];
    std::vector<int> ids((size_t)w * h, -1);
    if (!program_ || !scene.loaded() || w <= 0 || h <= 0) return ids;
    GLint prev_fbo = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prev_fbo);
    render_ids(scene, p, 3u, fb_width, fb_height, true);   // both: the other one may be in front
    std::vector<GLuint> px((size_t)w * h * 4, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(p.viewport[0], p.viewport[1], w, h, GL_RGBA_INTEGER, GL_UNSIGNED_INT, px.data());
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)prev_fbo);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    for (size_t i = 0; i < ids.size(); ++i)
        if (px[4 * i] == GLuint(side + 1) && px[4 * i + 1] > 0) ids[i] = int(px[4 * i + 1]) - 1;
    return ids;
}

PickHit Picker::pick(const Scene& scene, const ViewParams& p, unsigned mask, int fb_width, int fb_height, int x, int y) {
    PickHit hit;
    if (!program_ || !scene.loaded() || x < 0 || y < 0 || x >= fb_width || y >= fb_height) return hit;
    GLint prev_fbo = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prev_fbo);
    render_ids(scene, p, mask, fb_width, fb_height, false);
    GLuint id[4] = {0, 0, 0, 0};
    float depth = 1;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(x, y, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, id);
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)prev_fbo);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    if (id[0] == 0 || id[1] == 0) return hit;
    hit.mesh = int(id[0]) - 1;
    hit.triangle = int(id[1]) - 1;
    // Unproject the pixel centre at its depth.
    glm::vec4 ndc(2.0f * (x + 0.5f - p.viewport[0]) / p.viewport[2] - 1.0f,
                  2.0f * (y + 0.5f - p.viewport[1]) / p.viewport[3] - 1.0f, 2.0f * depth - 1.0f, 1.0f);
    glm::vec4 w = glm::inverse(p.mvp) * ndc;
    if (w.w != 0) hit.point = glm::vec3(w) / w.w;
    return hit;
}

}  // namespace hlens::gui
