// hlens: the interactive debugger of Hausdorff Lens (GLFW + Dear ImGui + OpenGL 3.3 core).
//
// One straight main loop, as in Dear ImGui's examples/example_glfw_opengl3/main.cpp. Loading and
// computing run on background threads (jobs.h); the loop only polls them. The views read and edit
// one AppState (app_state.h) and ask for what needs the jobs, the GPU or the camera through its
// requests, which the loop acts on after drawing them (requests.h).
//
// Headless (--screenshot PATH): vsync off, no imgui.ini; the loop waits for the computation (and
// the trace of --target, and the exact colour map's fill-in unless --exact-colormap on|off), plays
// the scripted input, lets ImGui settle for a few frames, reads the back buffer into a PNG before
// swapping, prints the state as one JSON line on stdout and exits (0, or 2 on bad input).
#include <chrono>
#include <cstdio>

#include <imgui.h>

#include "app_state.h"
#include "args.h"
#include "capture.h"
#include "jobs.h"
#include "layout.h"
#include "panels.h"
#include "requests.h"
#include "script_input.h"
#include "view3d.h"
#include "window.h"

using namespace hlens::gui;

int main(int argc, char** argv) {
    const auto program_start = std::chrono::steady_clock::now();
    // ---- 1. Set-up: the command line and the state, the window with its GL context and Dear
    //         ImGui, the 3D view's renderer, the computation started in the background
    Options opt;
    if (const int rc = read_command_line(argc, argv, opt); rc >= 0) return rc;
    AppState s;
    if (!init_state(s, opt)) return 2;
    Window window;
    if (!open_window(window, opt, s.headless)) return 1;
    View3D view;
    if (!init_view3d(view)) return 1;
    Jobs jobs(program_start);
    jobs.start_compute(s);
    StartTarget start(opt.target, opt.step);
    Script script = make_script(opt.input);
    Headless headless;
    ViewRect last_view{0, 0, -1, -1};   // no layout yet

    while (window_open(window)) {
        // ---- 2. Poll events (interactive and idle: sleep until something happens)
        poll_events(window, s, jobs.busy(), jobs.filling());
        // ---- 3. Harvest the background jobs; --target and --step once the meshes are there
        update_jobs(s, jobs, *view.scene, view.need_home, start);
        // ---- 4. Begin the frame; headless, scripted input replaces the mouse and keys
        begin_frame(window);
        //      (it starts once the distances are in and the 3D tile kept its place for a frame)
        const bool settled = s.view == last_view;
        last_view = s.view;
        feed_script(script, s.headless, jobs.compute_done && start.target_applied && (settled || script.pos > 0), jobs.trace.running());
        new_frame(window, s);
        // ---- 5. Layout; the 3D view's mouse and keyboard, only when ImGui does not want them
        layout(s, ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
        begin_view3d(view, s, window.fb_w, window.fb_h);
        view3d_input(view, s);
        // ---- 6. The views: the panels, and the overlay of the 3D view
        const ViewParams params = view_params(view, s);
        draw_panels(s);
        draw_view_overlay(s, *view.scene, params.mvp);
        // ---- 7. Act on the views' requests
        if (!act_on_requests(s, jobs, view, opt, headless.exit_code)) break;
        // ---- 8. Render: the 3D view, then ImGui on top
        draw_view3d(view, params);
        render_imgui();
        // ---- 9. Screenshots: read the back buffer before it is swapped (headless: then exit)
        save_requested_screenshot(s, window.fb_w, window.fb_h);
        if (s.headless && picture_ready(headless, s, opt, jobs, start, script)) {
            take_picture(headless, s, opt, view, params);
            break;
        }
        // ---- 10. Present
        present(window);
    }

    // ---- 11. Clean-up: the jobs first (they may still be reading the meshes), the GL objects
    //          before the context
    jobs.cancel_all();
    release_view3d(view);
    close_window(window);
    std::fflush(stdout);
    if (s.headless && headless.exit_code < 0) {
        std::fprintf(stderr, "hlens: the window was closed before the screenshot was taken\n");
        return 1;
    }
    return s.headless ? headless.exit_code : 0;
}
