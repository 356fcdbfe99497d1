#include "args.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>

#include "gl.h"

namespace hlens::gui {

const char* usage_text() {
    return "usage: hlens [A B] [--target I] [--direction ab|ba] [--size WxH] [--screenshot PATH]\n"
           "             [--step N|end] [--event-log] [--graph] [--overlay] [--case NAME [--epsilon E]] [--export-case DIR]\n"
           "             [--exact-colormap on|off|wait] [--units NAME] [--stats]\n"
           "             [--color-by max|mean|rms] [--tolerance T]\n"
           "             [--export-errors PATH.ply]\n"
           "\n"
           "The interactive debugger of Hausdorff Lens. With no meshes it opens the built-in demo pair\n"
           "(assets/demo_a.obj, assets/demo_b.obj).\n"
           "\n"
           "  --target I          select triangle I of the measured mesh as the target T'\n"
           "  --direction ab|ba   measure A against B (targets in A, default) or B against A\n"
           "  --step N|end        open the timeline and the domain view of the target (needs --target)\n"
           "                      after event N of its construction (end: finished)\n"
           "  --event-log         with --step: also open the event log (every event, filterable)\n"
           "  --graph             with --step: also open the graph of d^2 over the target\n"
           "  --overlay           with --step: colour the domain view by the nearest source feature\n"
           "  --case NAME         load a built-in degenerate case instead of files (parallel,\n"
           "                      coplanar_overlap, shared_edge, shared_vertex, perpendicular, sliver,\n"
           "                      duplicated, target_in_source_plane); --epsilon E: near-degenerate\n"
           "  --export-case DIR   with --screenshot and --target: write the target and its relevant\n"
           "                      sources to DIR/hlens-case-<target>-target.obj and -sources.obj\n"
           "  --size WxH          window size in pixels (default 1280x800)\n"
           "  --screenshot PATH   headless: wait for the computation, render, write a PNG, print the\n"
           "                      state as one JSON line on stdout and exit (0; 2 on bad input)\n"
           "  --exact-colormap on|off|wait\n"
           "                      after the distances, the exact maximum of every triangle the fast\n"
           "                      computation skipped is filled into the colour map in the background\n"
           "                      (on, the default); until then a triangle is grey and hatched, \"not\n"
           "                      yet exact\". off: never fill in; wait: with --screenshot, the picture\n"
           "                      waits until every triangle is exact (the default of --screenshot;\n"
           "                      with on it is taken as soon as the distances are known)\n"
           "  --exact-map-pace MS the fill-in waits MS milliseconds after each triangle (for tests:\n"
           "                      its Cancel, whatever the speed of the machine)\n"
           "  --stats             compute the exact surface statistics of both directions at start-up\n"
           "                      (as the sidebar's \"Compute statistics\"; --screenshot waits for them)\n"
           "  --color-by max|mean|rms\n"
           "                      the colour map's value per triangle: the exact maximum (default), or\n"
           "                      the exact mean or RMS distance over it (these compute the statistics)\n"
           "  --tolerance T       the tolerance field: triangles whose maximum exceeds T outlined red, the\n"
           "                      area above T for the mesh (with the statistics) and the target; in the\n"
           "                      domain view the curve d = T and the part above it shaded\n"
           "  --export-errors PATH.ply\n"
           "                      once the statistics are known, write the error maps as hlens-cli\n"
           "                      --export-errors does: PATH-ab.ply (A) and PATH-ba.ply (B)\n"
           "\n"
           "  --click X,Y, --double-click X,Y, --drag X0,Y0,X1,Y1, --right-drag X0,Y0,X1,Y1,\n"
           "  --wheel X,Y,STEPS, --hover X,Y, --wait FRAMES, --key home|f1|f12|left|right|space\n"
           "                      with --screenshot: input played in order once the computation\n"
           "                      is done (window pixels from the top-left; a frame is 1/60 s)\n"
           "  --layout-file PATH  keep the window layout in PATH (interactive runs use\n"
           "                      ~/.config/hlens/imgui.ini; headless runs none unless given)\n"
           "  --units NAME        the unit of the meshes' coordinates, shown with the colour bar's values\n"
           "  --dpi-scale S       act as if the window moved to a screen of content scale S\n"
           "                      (fonts and sizes follow, as when it really happens)\n"
           "\n"
           "Mouse: left-drag orbits, right- or shift+left-drag pans, the wheel zooms, a click picks a\n"
           "target, a double-click recentres. Keys: Home resets the camera, F frames the target, F12 saves\n"
           "a PNG, F1 shows every mouse action and shortcut (keys are ignored while typing in a text\n"
           "field).\n";
}

namespace {
long parse_long(const std::string& s, const std::string& what) {
    if (s.empty() || s.size() > 12) throw UsageError(what + " expects a non-negative integer, got '" + s + "'");
    for (char c : s)
        if (c < '0' || c > '9') throw UsageError(what + " expects a non-negative integer, got '" + s + "'");
    return std::strtol(s.c_str(), nullptr, 10);
}
std::vector<float> parse_floats(const std::string& s, size_t n, const std::string& what) {
    std::vector<float> v;
    size_t i = 0;
    while (i <= s.size() && v.size() < n + 1) {
        size_t j = s.find(',', i);
        if (j == std::string::npos) j = s.size();
        std::string part = s.substr(i, j - i);
        char* end = nullptr;
        float f = std::strtof(part.c_str(), &end);
        if (part.empty() || !end || *end != 0) throw UsageError(what + ": expected numbers separated by commas, got '" + s + "'");
        v.push_back(f);
        i = j + 1;
    }
    if (v.size() != n) throw UsageError(what + ": expected " + std::to_string(n) + " numbers, got '" + s + "'");
    return v;
}

// The index of v among `choices`; else a UsageError "<what>, got 'v'".
int parse_choice(const std::string& v, std::initializer_list<const char*> choices, const std::string& what) {
    int i = 0;
    for (const char* c : choices) {
        if (v == c) return i;
        ++i;
    }
    throw UsageError(what + ", got '" + v + "'");
}

}  // namespace

// Long: one branch per option, then the checks across options. A flat list reads like the usage;
// split, each piece would hold a handful of unrelated options.
Options parse_args(const std::vector<std::string>& args) {
    Options o;
    std::vector<std::string> positional;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--target") {
            o.target = parse_long(value(), "--target");
        } else if (a == "--step") {
            const std::string& v = value();
            o.step = v == "end" ? LONG_MAX : parse_long(v, "--step");
        } else if (a == "--case") {
            o.case_name = value();
        } else if (a == "--epsilon") {
            const std::string& v = value();
            char* end = nullptr;
            o.epsilon = std::strtod(v.c_str(), &end);
            if (v.empty() || !end || *end || !(o.epsilon >= 0) || o.epsilon > 1)
                throw UsageError("--epsilon expects a number in [0, 1], got '" + v + "'");
            o.epsilon_given = true;
        } else if (a == "--export-case") {
            o.export_dir = value();
        } else if (a == "--event-log") {
            o.event_log = true;
        } else if (a == "--graph") {
            o.graph = true;
        } else if (a == "--overlay") {
            o.overlay = true;
        } else if (a == "--direction") {
            const std::string& v = value();
            if (v == "ab") o.direction = 0;
            else if (v == "ba") o.direction = 1;
            else throw UsageError("--direction expects ab or ba, got '" + v + "'");
        } else if (a == "--size") {
            const std::string& v = value();
            size_t x = v.find_first_of("xX");
            if (x == std::string::npos) throw UsageError("--size expects WxH, got '" + v + "'");
            long w = parse_long(v.substr(0, x), "--size"), h = parse_long(v.substr(x + 1), "--size");
            if (w < 64 || h < 64 || w > 8192 || h > 8192) throw UsageError("--size: width and height must be in 64..8192");
            o.width = (int)w;
            o.height = (int)h;
            o.size_given = true;
        } else if (a == "--screenshot") {
            o.screenshot = value();
            if (o.screenshot.empty()) throw UsageError("--screenshot needs a path");
        } else if (a == "--click" || a == "--double-click") {
            auto v = parse_floats(value(), 2, a);
            o.input.push_back({a == "--click" ? InputAction::Click : InputAction::DoubleClick, v[0], v[1], v[0], v[1]});
        } else if (a == "--key") {
            const std::string& v = value();
            InputAction k;
            k.kind = InputAction::Key;
            if (v == "home") k.key = GLFW_KEY_HOME;
            else if (v == "f12") k.key = GLFW_KEY_F12;
            else if (v == "f1") k.key = GLFW_KEY_F1;
            else if (v == "left") k.key = GLFW_KEY_LEFT;
            else if (v == "right") k.key = GLFW_KEY_RIGHT;
            else if (v == "space") k.key = GLFW_KEY_SPACE;
            else throw UsageError("--key expects home, f1, f12, left, right or space, got '" + v + "'");
            o.input.push_back(k);
        } else if (a == "--drag" || a == "--right-drag") {
            auto v = parse_floats(value(), 4, a);
            o.input.push_back({a == "--drag" ? InputAction::Drag : InputAction::RightDrag, v[0], v[1], v[2], v[3]});
        } else if (a == "--wheel") {
            auto v = parse_floats(value(), 3, a);
            o.input.push_back({InputAction::Wheel, v[0], v[1], v[2], 0});
        } else if (a == "--hover") {
            auto v = parse_floats(value(), 2, a);
            o.input.push_back({InputAction::Hover, v[0], v[1], 40, 0});
        } else if (a == "--wait") {
            o.input.push_back({InputAction::Wait, 0, 0, (float)parse_long(value(), a), 0});
        } else if (a == "--exact-colormap") {
            o.exact_colormap = parse_choice(value(), {"off", "on", "wait"}, "--exact-colormap expects on, off or wait");
        } else if (a == "--exact-map-pace") {
            o.exact_pace_ms = (int)parse_long(value(), a);
        } else if (a == "--color-by") {
            o.color_by = parse_choice(value(), {"max", "mean", "rms"}, "--color-by expects max, mean or rms");
        } else if (a == "--tolerance") {
            const std::string& v = value();
            char* end = nullptr;
            o.tolerance = std::strtod(v.c_str(), &end);
            if (v.empty() || !end || *end || !(o.tolerance >= 0) || !std::isfinite(o.tolerance))
                throw UsageError("--tolerance expects a distance >= 0, got '" + v + "'");
        } else if (a == "--export-errors") {
            o.export_errors = value();
            const std::string& e = o.export_errors;
            if (e.size() < 5 || e.compare(e.size() - 4, 4, ".ply") != 0)
                throw UsageError("--export-errors needs a path ending in .ply, got '" + e + "'");
        } else if (a == "--stats") {
            o.stats = true;
        } else if (a == "--units") {
            o.units = value();
        } else if (a == "--layout-file") {
            o.layout_file = value();
        } else if (a == "--dpi-scale") {
            auto v = parse_floats(value(), 1, a);
            if (!(v[0] >= 0.5f && v[0] <= 4)) throw UsageError("--dpi-scale expects a number in 0.5..4");
            o.dpi_scale = v[0];
        } else if (a.size() > 1 && a[0] == '-') {
            throw UsageError("unknown option " + a);
        } else {
            positional.push_back(a);
        }
    }
    if (!o.input.empty() && o.screenshot.empty())
        throw UsageError("--click, --double-click, --drag, --right-drag, --wheel, --hover, --wait and --key need --screenshot");
    if (o.step >= 0 && o.target < 0) throw UsageError("--step needs --target");
    if (o.epsilon_given && o.case_name.empty()) throw UsageError("--epsilon needs --case");
    if (!o.export_dir.empty() && (o.screenshot.empty() || o.target < 0)) throw UsageError("--export-case needs --screenshot and --target");
    if (!o.case_name.empty() && !positional.empty()) throw UsageError("--case replaces the meshes A B");
    if (positional.empty()) {
        o.demo = true;
    } else if (positional.size() == 2) {
        o.path[0] = positional[0];
        o.path[1] = positional[1];
    } else {
        throw UsageError("expected two meshes A B (or none for the demo), got " + std::to_string(positional.size()));
    }
    return o;
}

int read_command_line(int argc, char** argv, Options& opt) {
    try {
        opt = parse_args(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "hlens: %s\n%s", e.what(), usage_text());
        return 2;
    }
    if (opt.help) {
        std::fputs(usage_text(), stdout);
        return 0;
    }
    return -1;
}

}  // namespace hlens::gui
