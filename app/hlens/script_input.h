// Scripted input of headless runs (--click, --drag, --key, ...; args.h InputAction): one mouse and
// keyboard state per frame, fed to Dear ImGui in place of the backend's, as real events would be.
#pragma once
#include <cstddef>
#include <vector>

#include "args.h"

namespace hlens::gui {

struct MouseFrame {
    float x, y;
    bool down;
    int key = -1;        // a GLFW key held down during this frame
    bool right = false;  // the right button is down
    float wheel = 0;     // wheel steps this frame
};

struct Script {
    std::vector<MouseFrame> frames;
    size_t pos = 0;               // the next frame to play
    bool done() const { return pos >= frames.size(); }
};

Script make_script(const std::vector<InputAction>& actions);

// Between the backends' new frame and ImGui::NewFrame. The script starts once `results_in` (the
// distances, --target applied, and the 3D tile where it was the frame before: main.cpp) and no
// trace is running, then plays one frame per frame (a
// click's trace must not delay the next input); afterwards the mouse stays where it ended,
// buttons up (a hover lasts until the picture). Does nothing in interactive runs.
void feed_script(Script& script, bool headless, bool results_in, bool trace_running);

}  // namespace hlens::gui
