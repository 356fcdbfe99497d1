#include "script_input.h"

#include <cfloat>

#include <imgui.h>

namespace hlens::gui {

Script make_script(const std::vector<InputAction>& actions) {
    Script script;
    std::vector<MouseFrame>& f = script.frames;
    for (const InputAction& a : actions) {
        if (a.kind == InputAction::Key) {
            MouseFrame k = f.empty() ? MouseFrame{-1, -1, false} : f.back();
            k.down = false;
            k.key = a.key;
            f.push_back(k);
            k.key = -1;
            f.push_back(k);
        } else if (a.kind == InputAction::Drag || a.kind == InputAction::RightDrag) {
            const bool left = a.kind == InputAction::Drag;
            auto at = [&](float x, float y, bool down) {
                MouseFrame m{x, y, left && down};
                m.right = !left && down;
                return m;
            };
            f.push_back(at(a.x0, a.y0, false));
            f.push_back(at(a.x0, a.y0, true));
            for (int i = 1; i <= 8; ++i) f.push_back(at(a.x0 + (a.x1 - a.x0) * i / 8, a.y0 + (a.y1 - a.y0) * i / 8, true));
            f.push_back(at(a.x1, a.y1, false));
        } else if (a.kind == InputAction::Wheel) {
            f.push_back({a.x0, a.y0, false});
            MouseFrame w{a.x0, a.y0, false};
            w.wheel = a.x1;
            f.push_back(w);
        } else if (a.kind == InputAction::Hover || a.kind == InputAction::Wait) {
            MouseFrame m = a.kind == InputAction::Hover ? MouseFrame{a.x0, a.y0, false}
                                                        : (f.empty() ? MouseFrame{-1, -1, false} : f.back());
            m.down = m.right = false;
            m.key = -1;
            m.wheel = 0;
            for (int i = 0; i < (int)a.x1; ++i) f.push_back(m);
            continue;
        } else {
            f.push_back({a.x0, a.y0, false});
            for (int k = 0; k < (a.kind == InputAction::DoubleClick ? 2 : 1); ++k) {
                f.push_back({a.x0, a.y0, true});
                f.push_back({a.x0, a.y0, false});
            }
        }
        MouseFrame rest = f.back();
        rest.wheel = 0;
        f.push_back(rest);
    }
    return script;
}

void feed_script(Script& script, bool headless, bool results_in, bool trace_running) {
    const std::vector<MouseFrame>& f = script.frames;
    const bool running = !script.done() && results_in && (script.pos > 0 || !trace_running);
    const bool over = headless && !f.empty() && script.done();
    if (!running && !over) return;
    const MouseFrame m = running ? f[script.pos++] : MouseFrame{f.back().x, f.back().y, false};
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = m.x < 0 ? ImVec2(-FLT_MAX, -FLT_MAX) : ImVec2(m.x, m.y);
    for (bool& b : io.MouseDown) b = false;
    io.MouseDown[0] = m.down;
    io.MouseDown[1] = m.right;
    io.MouseWheel = m.wheel;
    for (bool& k : io.KeysDown) k = false;
    if (m.key >= 0) io.KeysDown[m.key] = true;
}

}  // namespace hlens::gui
