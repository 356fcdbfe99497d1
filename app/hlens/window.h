// The window: GLFW with an OpenGL 3.3 core context, and Dear ImGui on it (style, fonts scaled to
// the screen's content scale, the GLFW and OpenGL3 backends). Interactive runs keep the floating
// windows' layout in ~/.config/hlens/imgui.ini; headless runs (--screenshot) have vsync off, a
// fixed window size and no imgui.ini unless --layout-file is given.
#pragma once
#include "app_state.h"
#include "args.h"
#include "gl.h"

namespace hlens::gui {

struct Window {
    GLFWwindow* handle = nullptr;
    bool headless = false;
    float dpi = 1.0f;             // the content scale the fonts and sizes are built for
    float forced_dpi = 0;         // --dpi-scale: taken as the new content scale at frame 3
    long frame = 0;
    int redraw = 3;               // frames still to draw before waiting for events
    int fb_w = 0, fb_h = 0;       // the framebuffer's size this frame (pixels)
};

// Creates the window and the context and sets up Dear ImGui; Ctrl-C and SIGTERM then end the
// loop as closing the window does. False (with a message on stderr) when it cannot.
bool open_window(Window& w, const Options& opt, bool headless);
// Neither closed nor interrupted.
bool window_open(const Window& w);
// Events: interactive and idle (nothing `busy`, no redraw pending), sleeps until something
// happens, 10 frames a second while only the exact colour map or the statistics are `filling`
// (their progress shows; input still wakes the loop at once). Rebuilds fonts and sizes on a new
// content scale. Files dropped on the window go to s.dropped.
void poll_events(Window& w, AppState& s, bool busy, bool filling);
// The backends' new frame; headless, ImGui's clock advances a fixed 1/60 s per frame, so what
// depends on it (the double-click interval, fades, playing) does not depend on this machine.
void begin_frame(Window& w);
// ImGui's new frame (after any scripted input), the framebuffer's size, and whether to keep
// drawing (input this frame, or the timeline playing).
void new_frame(Window& w, const AppState& s);
// Renders ImGui's draw data (over the 3D view).
void render_imgui();
// Swaps the buffers.
void present(Window& w);
// Shuts down Dear ImGui, the window and GLFW (the GL objects must be gone already).
void close_window(Window& w);

}  // namespace hlens::gui
