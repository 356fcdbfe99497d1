// The 3D view: both meshes with the colour map (scene.h) through a turntable camera (camera.h),
// its mouse and keyboard, picking (picking.h), and what is drawn over it with ImGui: the witness
// points and segments, the selected target and its maximum, and for the stepped target the
// sources inserted so far, the voxels seen and the search radius.
#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "app_state.h"
#include "camera.h"
#include "picking.h"
#include "scene.h"

namespace hlens::gui {

struct View3D {
    // (unique_ptr: both hold GL objects, released before the context is destroyed)
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Picker> picker;
    Camera camera;
    bool need_home = false;       // new meshes: frame them once they are on the GPU
    // This frame: the framebuffer, its scale over window coordinates, the view's rectangle in
    // framebuffer pixels (GL counts rows from the bottom) and its aspect ratio.
    int fb_w = 0, fb_h = 0;
    float fbs_x = 1, fbs_y = 1;
    int vx = 0, vy = 0, vw = 1, vh = 1;
    float aspect = 1;
    // Mouse: which button's press began over the view; the press of a double-click (its release
    // does not pick); the stepped target the camera was last framed on.
    bool press_in_view[3] = {false, false, false};
    bool press_was_double = false;
    long focused_key = -1;
    // What that framing used (the tile's aspect, whether the distances were in) and the camera it
    // gave: while the camera is untouched, a change of either (the timeline's tiles settle a
    // frame after it opens; the distances may come before or after) frames the target again, so
    // the view does not depend on the frame it first happened at.
    float focus_aspect = 0;
    bool focus_computed = false;
    Camera focused;
};

// The renderer and picking (needs the GL context). False with a message on stderr.
bool init_view3d(View3D& v);
// The GL objects, before the context goes.
void release_view3d(View3D& v);
// After the layout (s.view): this frame's viewport, the camera's up axis, new meshes framed.
void begin_view3d(View3D& v, const AppState& s, int fb_w, int fb_h);
// Everything the scene's drawing (and picking) needs this frame.
ViewParams view_params(const View3D& v, const AppState& s);
// Mouse and keyboard for the 3D view, only when ImGui does not want them: orbit, pan, zoom,
// recentre (double-click), pick (a click, not a drag: s.req.select), Home, F, F1, F12.
void view3d_input(View3D& v, AppState& s);
// Drawn into the 3D view with ImGui's background draw list; `mvp` maps scene-local coordinates.
void draw_view_overlay(const AppState& s, const Scene& scene, const glm::mat4& mvp);
// "Reset view" (home) and framing the selected target with the sphere of its largest distance
// (focus; also when a target's timeline opens or another target is stepped).
void frame_camera(View3D& v, const AppState& s, bool home, bool focus);
// Clears the window and draws the meshes (ImGui is rendered on top afterwards).
void draw_view3d(const View3D& v, const ViewParams& p);

}  // namespace hlens::gui
