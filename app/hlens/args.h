// Command line of hlens:  hlens [A B] [--target I] [--direction ab|ba] [--size WxH] [--screenshot PATH]
//                         [--step N|end] [--event-log] [--case NAME [--epsilon E]] [--export-case DIR]
//                         [--click X,Y] [--double-click X,Y] [--drag X0,Y0,X1,Y1] [--right-drag X0,Y0,X1,Y1]
//                         [--wheel X,Y,STEPS] [--hover X,Y] [--wait FRAMES] [--key home|f12|left|right|space]
//                         [--layout-file PATH] [--dpi-scale S] [--exact-colormap on|off|wait] [--exact-map-pace MS]
//                         [--units NAME]
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace hlens::gui {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Scripted mouse input for headless runs, in window coordinates (the screenshot's pixels at 1x):
// played frame by frame through Dear ImGui's input state, as real mouse events would be.
struct InputAction {
    enum Kind { Click, DoubleClick, Drag, RightDrag, Key, Wheel, Hover, Wait } kind = Click;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;   // Wheel: x1 = steps (up > 0); Hover, Wait: x1 = frames
    int key = 0;   // Key: a GLFW key code
};

struct Options {
    std::string path[2];         // mesh A, mesh B (the built-in demo pair when none are given)
    bool demo = false;           // no meshes given: the demo pair
    long target = -1;            // --target I: select triangle I of the measured mesh (-1: none)
    int direction = 0;           // 0: A to B (targets in A), 1: B to A (targets in B)
    int width = 1280, height = 800;
    bool size_given = false;
    std::string screenshot;      // --screenshot PATH: headless run, write a PNG and exit
    std::vector<InputAction> input;   // --click, --double-click, --drag, --key (in the given order)
    long step = -1;              // --step N|end: open the timeline at event N (LONG_MAX: end; -1: not given)
    bool event_log = false;      // --event-log: open the event log with the timeline
    std::string case_name;       // --case NAME: a built-in case instead of files
    double epsilon = 0;          // --epsilon E: its near-degeneracy
    bool epsilon_given = false;
    std::string export_dir;      // --export-case DIR: headless, export the selected target there
    bool overlay = false;        // --overlay: with --step, the nearest-feature overlay in the domain view
    bool graph = false;          // --graph: with --step, open the graph of d^2
    std::string layout_file;     // --layout-file PATH: keep the window layout there (also headless)
    float dpi_scale = 0;         // --dpi-scale S: act as if the window's content scale became S
    std::string units;           // --units NAME: the distances' unit, shown on the colour bar
    // --exact-colormap: 1 on (fill in the exact maxima in the background), 0 off (never: skipped
    // triangles stay "not yet exact"), 2 wait (on; --screenshot waits until it is complete).
    // -1: not given (on; wait with --screenshot).
    int exact_colormap = -1;
    int exact_pace_ms = 0;       // --exact-map-pace MS: the fill-in waits MS per triangle (tests of Cancel)
    int color_by = 0;            // --color-by max|mean|rms: 0, 1, 2 (mean and RMS imply --stats)
    double tolerance = -1;       // --tolerance T: the tolerance field, set and on (< 0: not given)
    std::string export_errors;   // --export-errors PATH.ply: write the error maps (with --screenshot)
    bool stats = false;          // --stats: compute the exact surface statistics at start-up
    bool help = false;
};

// Throws UsageError with a one-line message.
Options parse_args(const std::vector<std::string>& args);
const char* usage_text();
// main()'s command line into `opt`: -1 to go on, else the exit code (0 after --help, which prints
// the usage; 2 after a usage error, printed with the usage on stderr).
int read_command_line(int argc, char** argv, Options& opt);

}  // namespace hlens::gui
