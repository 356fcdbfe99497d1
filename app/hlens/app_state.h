// What the panels show and edit: the application state, in one place. The main loop owns one
// AppState; panels read it and set `Requests` for the loop to act on (requests.h: start/cancel
// jobs, reset the camera, save a PNG), so panels need no access to OpenGL or to the job threads.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "compute.h"
#include "scene.h"
#include "stepper.h"
#include "tolerance_cut.h"

namespace hlens::gui {

struct AppError {
    std::string title;    // e.g. "Cannot load mesh B"
    std::string file;     // the file named by the error ("" if none)
    std::string reason;
};

// The colour map's range: the exact values known so far (never a bound). It follows them as the
// fill-in brings more, until the user moves it ("Reset" makes it follow again).
struct ColourRange {
    float lo = 0, hi = 1;         // current range of the colour map
    float data_lo = 0, data_hi = 1;
    bool valid = false;
};

// The exact colour map of one direction: the exact maximum distance over each triangle of the
// measured mesh, known at once where fast mode solved the triangle, then filled in by the
// background job (ExactMapJob); a triangle not yet known is drawn "not yet exact" (grey, hatched).
struct ExactMap {
    std::vector<double> value;    // per triangle: the exact maximum distance, -1 while not yet exact
    size_t exact = 0;             // how many values are known
    bool stopped = false;         // the user cancelled its fill-in: not restarted until asked
    std::string failed;           // the fill-in failed (why); not restarted
    double complete_at = -1;      // when every value was known (seconds, as AppState::distances_at)
    bool complete() const { return exact == value.size(); }   // (also for a mesh without triangles)
    bool known(long t) const { return t >= 0 && (size_t)t < value.size() && value[t] >= 0; }
};

enum class ExactMode { Off, On, Wait };   // --exact-colormap off|on|wait

// The exact surface statistics of both directions (issue 9): computed only when asked for
// ("Compute statistics", --stats, colouring by mean or RMS, exporting the error map), in the
// background (StatsJob: every target's full construction), with progress and Cancel.
struct StatsView {
    bool wanted = false;          // asked for: computed once the distances are known
    std::array<std::shared_ptr<const SurfaceStats>, 2> dir;   // null until computed
    double tolerance = -1;        // the tolerance they were computed with (< 0: none)
    bool running = false, cancelled = false;
    double progress = -1, elapsed = 0;
    std::string phase, failed;
    bool ready() const { return dir[0] && dir[1]; }
};

// What the colour map shows per triangle of the measured mesh (--color-by).
enum class ColourBy { Max = 0, Mean = 1, Rms = 2 };
const char* colour_by_name(ColourBy c);   // "max", "mean", "rms"

struct Requests {
    bool cancel = false, recompute = false, home = false, screenshot = false, clear_errors = false;
    bool exact_cancel = false, exact_resume = false;   // stop / continue the exact colour map's fill-in
    bool stats_start = false, stats_cancel = false;   // compute (again, at the current tolerance) / stop the statistics
    bool colours = false;         // the colour map's quantity changed: upload and re-range it
    bool export_errors = false;   // write the error map (PLY) of both directions
    bool focus = false;           // frame the selected target and the sphere of its largest distance
    int set_direction = -1;
    long select = -2;             // -2: nothing; -1: clear the selection; >= 0: select that target
    bool load = false;            // open load_path[0], load_path[1] as A and B
    std::string load_case;        // non-empty: load that built-in case (with case_eps)
    double case_eps = 0;
    bool export_case = false;     // export the selected target into export_dir
    std::string load_path[2];
};

// The view rectangle (the part of the window right of the sidebar), in window coordinates.
struct ViewRect {
    float x = 0, y = 0, w = 1, h = 1;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
    bool operator==(const ViewRect& o) const { return x == o.x && y == o.y && w == o.w && h == o.h; }
};

struct AppState {
    std::string path[2];
    std::string name[2] = {"A", "B"};   // file names for the UI
    bool demo = false;
    bool headless = false;
    bool scripted_input = false;  // headless with --click/--drag/...: hover tooltips are wanted

    std::shared_ptr<const LoadedScene> scene;   // set as soon as the meshes are loaded
    bool computed = false, cancelled = false;
    HausdorffResult result;

    int direction = 0;            // 0: A to B (colour map and targets on A), 1: B to A (on B)
    long selected[2] = {-1, -1};  // selected target per direction (-1: none)
    std::optional<TraceSummary> trace[2];   // trace of the selected target per direction
    bool trace_running = false;

    MeshStyle style[2];
    ColourRange range[2];
    ExactMap exact[2];            // per direction, like range
    ExactMode exact_mode = ExactMode::On;
    int exact_pace_ms = 0;        // --exact-map-pace
    // The fill-in job, filled by the loop each frame (its progress is exact[exact_side].exact).
    bool exact_running = false;
    int exact_side = 0;
    double distances_at = -1;     // seconds from start-up (or Recompute) until the distances showed
    // Where the colour bar was drawn (window coordinates: x, y, w, h), for the headless state.
    float colour_bar_rect[4] = {0, 0, 0, 0};
    std::string units;                  // --units: appended to the colour bar's top value
    std::string colour_bar_hi_label;    // that label as drawn, for the headless state
    ViewRect target_window;       // the target panel over the 3D view (window coordinates)
    bool show_witness[2] = {true, true};
    bool show_colormap = true;
    ColourBy colour_by = ColourBy::Max;
    double tolerance = -1;        // the tolerance T (world units; < 0: none)
    double tolerance_input = 0;   // the tolerance field (applied while its checkbox is on)
    // The selected target cut at T (its finished domain mesh, from its trace) and the domain
    // view's mesh at the current step cut at T, each with what it was computed for.
    ToleranceCut target_cut, view_cut;
    const void* target_cut_of = nullptr;
    unsigned long view_cut_revision = 0;
    StatsView stats;
    std::string errors_path = "hlens-errors.ply";   // "Export error map": PATH-ab.ply, PATH-ba.ply
    std::string errors_status;    // the paths written, or the error
    bool errors_ok = false;
    bool errors_pending = false;  // export once the statistics are known (--export-errors)
    std::vector<std::string> errors_written;
    int up_axis = 2;

    std::string demo_path[2];     // the built-in demo pair
    std::string edit_path[2];     // the file panel's text fields
    std::vector<std::string> recent;    // recently opened files, newest first (not kept in headless runs)
    std::string recent_file;            // where `recent` is kept ("" in headless runs; settings.h)
    std::vector<std::string> dropped;   // files dropped on the window, waiting for "which side?"

    // Built-in cases (cases.h) and "Export case".
    bool case_loaded = false;     // A and B are case_mesh, not files
    std::string case_name;
    double case_eps = 0;
    TriangleMesh case_mesh[2];
    int case_choice = 0;
    bool case_near = false;
    float case_log_eps = -6;      // log10 of epsilon for the menu's slider
    std::string export_dir = ".";
    std::string export_status;    // the paths written, or the error
    bool export_ok = false;

    std::vector<AppError> errors;
    std::string status;           // last status message (e.g. "saved hlens-....png")

    // Progress of the compute job, filled by the loop each frame.
    bool computing = false;
    double progress = -1;
    std::string phase;
    double elapsed = 0;

    bool help_open = false;       // the Help window (F1)
    Stepper stepper;              // the timeline and the domain view of the selected target

    ViewRect view;                // the 3D view
    float sidebar_width = 0;
    // Tiled layout (layout()): with a target's timeline open, the area right of the sidebar is
    // split into the domain view (left), the 3D view (right, above a strip holding the graph and
    // the event log when they are open) and the timeline (bottom). The user drags the free edge of
    // each tile; the chosen sizes live here and, through the windows' sizes, in imgui.ini.
    struct Tile {
        ViewRect r;
        float lo_w = 0, hi_w = 0, lo_h = 0, hi_h = 0;   // the sizes the user may drag it to
    };
    struct Tiles {
        bool on = false;
        Tile domain, timeline, graph, log;
        bool graph_on = false, log_on = false;
        float domain_w = 0, strip_h = 0, graph_w = 0;   // chosen sizes (0: the default)
        float timeline_need = 0;                        // the height the timeline's contents took
    } tiles;
    Requests req;
};

// The state at start-up from the command line (a built-in case loaded, --direction, --stats, the
// views --step opens, ...). False: an unknown --case (reported on stderr).
struct Options;   // args.h
bool init_state(AppState& s, const Options& opt);

}  // namespace hlens::gui
