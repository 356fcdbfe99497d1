// Picking: the meshes are drawn into an offscreen framebuffer that stores, per pixel, the mesh and
// triangle index (RGBA32UI) and the depth; one pixel is read back under the mouse. Drawn on demand
// (when a click or double-click ends), never every frame.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl.h"
#include "scene.h"

namespace hlens::gui {

struct PickHit {
    int mesh = -1;       // 0: A, 1: B, -1: background
    int triangle = -1;
    glm::vec3 point{0.0f};   // scene-local position of the pixel's surface point
};

class Picker {
public:
    ~Picker();
    bool init(std::string& error);
    // mask bit i: mesh i takes part. x, y: framebuffer pixel, GL convention (origin bottom-left).
    PickHit pick(const Scene& scene, const ViewParams& p, unsigned mask, int fb_width, int fb_height, int x, int y);
    // The triangle of mesh `side` drawn at every pixel of the view (p.viewport), -1 where there is
    // none or the other mesh is drawn in front (as it is drawn: a wireframe as lines): row 0 is the
    // view's bottom row. For the headless state.
    std::vector<int> triangle_ids(const Scene& scene, const ViewParams& p, int side, int fb_width, int fb_height);

private:
    void resize(int w, int h);
    void render_ids(const Scene& scene, const ViewParams& p, unsigned mask, int fb_width, int fb_height, bool as_drawn);
    GLuint program_ = 0, fbo_ = 0, color_ = 0, depth_ = 0;
    int w_ = 0, h_ = 0;
};

}  // namespace hlens::gui
