#include "window.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <string>
#include <thread>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "settings.h"

namespace hlens::gui {

namespace {

// Files dropped on the window (GLFW calls this from glfwPollEvents, on the main thread).
std::vector<std::string> g_dropped;
void on_drop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

// The window moved to a screen with another content scale (GLFW calls this from glfwPollEvents).
float g_content_scale = 0;   // 0: no change pending
void on_content_scale(GLFWwindow*, float sx, float) { g_content_scale = std::max(1.0f, sx); }

// Ctrl-C or a polite kill ends the loop as closing the window does (the layout is saved).
volatile std::sig_atomic_t g_quit = 0;
void on_signal(int) { g_quit = 1; }

void glfw_error(int code, const char* what) { std::fprintf(stderr, "hlens: GLFW error %d: %s\n", code, what); }

// Fonts and sizes for a content scale: everything else is sized in multiples of the font size.
// Called before the first frame and between frames when the scale changes (rebuilding the font
// atlas and its texture, and the style from scratch so sizes are not scaled twice).
void apply_dpi_scale(float scale, bool rebuild_texture) {
    ImGuiIO& io = ImGui::GetIO();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 0;
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    io.Fonts->Clear();
    ImFontConfig font;
    font.SizePixels = std::round(13.0f * scale);
    io.Fonts->AddFontDefault(&font);
    if (rebuild_texture) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
}

}  // namespace

bool open_window(Window& w, const Options& opt, bool headless) {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    w.headless = headless;
    w.forced_dpi = opt.dpi_scale;

    // Window and OpenGL 3.3 core context
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        std::fprintf(stderr, "hlens: cannot initialise GLFW (no display? try: xvfb-run -a -s \"-screen 0 1600x1000x24\" hlens ...)\n");
        return false;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, headless ? GLFW_FALSE : GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, headless ? GLFW_FALSE : GLFW_TRUE);
    w.handle = glfwCreateWindow(opt.width, opt.height, "Hausdorff Lens", nullptr, nullptr);
    if (!w.handle) {
        std::fprintf(stderr, "hlens: cannot create an OpenGL 3.3 core window\n");
        glfwTerminate();
        return false;
    }
    glfwMakeContextCurrent(w.handle);
    if (!headless) glfwSetDropCallback(w.handle, on_drop);
    glfwSwapInterval(headless ? 0 : 1);

    // Dear ImGui: style, DPI scaling, backends
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    static std::string ini;   // must outlive the context
    ini = !opt.layout_file.empty() ? opt.layout_file : headless ? "" : config_file("imgui.ini");
    io.IniFilename = ini.empty() ? nullptr : ini.c_str();
    w.dpi = 1.0f;
    if (!headless) {
        float sx = 1, sy = 1;
        glfwGetWindowContentScale(w.handle, &sx, &sy);
        w.dpi = std::max(1.0f, sx);
    }
    apply_dpi_scale(w.dpi, false);
    ImGui_ImplGlfw_InitForOpenGL(w.handle, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    glfwSetWindowContentScaleCallback(w.handle, on_content_scale);
    return true;
}

bool window_open(const Window& w) { return !glfwWindowShouldClose(w.handle) && !g_quit; }

void poll_events(Window& w, AppState& s, bool busy, bool filling) {
    if (w.headless || busy || w.redraw > 0)
        glfwPollEvents();
    else
        glfwWaitEventsTimeout(filling ? 0.1 : 0.25);
    if (w.headless && (busy || filling)) std::this_thread::sleep_for(std::chrono::milliseconds(10));   // leave the cores to the jobs
    // A new content scale (the window moved to another screen; --dpi-scale from frame 3 on).
    if (w.forced_dpi > 0 && w.frame == 3) g_content_scale = w.forced_dpi;
    if (g_content_scale > 0 && g_content_scale != w.dpi) {
        w.dpi = g_content_scale;
        apply_dpi_scale(w.dpi, true);
        w.redraw = 3;
    }
    g_content_scale = 0;
    ++w.frame;
    if (!g_dropped.empty()) {
        s.dropped = std::move(g_dropped);
        g_dropped.clear();
    }
}

void begin_frame(Window& w) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (w.headless) ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
}

void new_frame(Window& w, const AppState& s) {
    ImGui::NewFrame();
    glfwGetFramebufferSize(w.handle, &w.fb_w, &w.fb_h);
    const ImGuiIO& io = ImGui::GetIO();
    bool input = io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 || ImGui::IsAnyMouseDown() ||
                 io.InputQueueCharacters.Size > 0;
    for (bool k : io.KeysDown) input = input || k;
    w.redraw = input || s.stepper.playing ? 3 : std::max(0, w.redraw - 1);
}

void render_imgui() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void present(Window& w) { glfwSwapBuffers(w.handle); }

void close_window(Window& w) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(w.handle);
    glfwTerminate();
}

}  // namespace hlens::gui
