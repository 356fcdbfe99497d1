// Stepping through one target's construction (the stepping model, no drawing): a TargetSolver
// recording its events, driven from the timeline panel, and the drawing data of its domain mesh
// for the 2D domain view.
//
// The solver runs on the UI thread: one event (or one insertion) per request is cheap, and
// stepping back replays from the start (the construction is deterministic). After every change
// rebuild() turns the domain mesh into polygons in the target's frame; the domain view only
// transforms and draws them.
//
// The solver produces the events of a whole insertion at once (its state is then the state after
// that insertion), so an observer keeps a snapshot of the state at each event of the insertion in
// progress: the views show the domain mesh as it was at the current event, half-cut domains
// included. mesh(), max_sq(), insertions() ... give that state.
#pragma once
#include <climits>
#include <map>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compute.h"
#include <hlens/target_solver.h>

namespace hlens::gui {

struct DomainDraw {
    int face = -1;
    DomainLabel label;
    bool infinite = false;
    unsigned colour = 0;              // ImU32
    double area = 0;
    std::vector<Vec2> outer;          // the outer loop, sampled (frame coordinates)
    std::vector<int> tris;            // triangles of `outer` (indices, three per triangle)
};

struct ArcDraw {
    int edge = -1;
    ArcKind kind = ArcKind::Conic;
    std::vector<Vec2> pts;            // the arc sampled between z0 and z1
};

// The state at one event inside an insertion.
struct StepSnapshot {
    std::shared_ptr<const DomainMesh> mesh;   // null for a degenerate target
    double max_sq = HUGE_VAL;                 // world units
    Vec2 max_2d;
    int insertions = 0;                       // sources inserted (the one being inserted included)
    int32_t inserting = -1;                   // the source being inserted, once its regions are projected
};

// A target without a domain mesh (TargetFrame::degenerate), for the domain view's note and the
// state JSON: "point" (its corners coincide), "segment" (collinear corners) or "sliver" (a height
// below 1e-7 of its longest edge: handled as its three edges, the true maximum at most `height`
// above theirs). World units; nullopt for a target with a domain mesh.
struct DegenerateTarget { const char* kind; double height, longest_edge; };
std::optional<DegenerateTarget> degenerate_target(const TargetFrame& fr);

struct Stepper {
    // What is being stepped.
    std::shared_ptr<const LoadedScene> scene;
    int side = -1;
    long target = -1;
    std::unique_ptr<TargetSolver> solver;
    long step = -1;                   // the current event (-1: before the first)
    bool at_end = false;              // no event is left
    std::optional<Event> current;

    // Requests and UI state.
    bool open = false;                // timeline and domain view shown
    long pending = -2;                // a jump asked for before the solver existed (LONG_MAX: the end)
    bool playing = false;
    float speed = 10;                 // events per second while playing
    double play_accum = 0;
    int jump_input = 0;
    bool show_regions = true;
    bool fit = true;                  // reset pan and zoom on the next frame
    float zoom = 1;
    float pan_x = 0, pan_y = 0;       // frame units

    // Drawing data of the current state.
    std::vector<DomainDraw> domains;  // in order of decreasing area
    std::vector<ArcDraw> arcs;
    std::vector<Vec2> vertices;
    int live_domains = 0, live_arcs = 0, live_vertices = 0;

    // Event log panel (with the timeline): every recorded event of the target, filtered by kind.
    bool event_log = false;
    bool kind_shown[16] = {true, true, true, true, true, true, true, true, true, true, true, true, true, true, true, true};
    std::vector<long> log_rows;       // indices into the full event stream that pass the filter
    const void* log_source = nullptr; // the stream log_rows was built from
    size_t log_source_size = 0;
    bool log_dirty = true;
    long log_scrolled_step = -2;      // the step last scrolled into view
    long log_shown = 0, log_total = 0;   // for the headless JSON line
    float log_current_y = -1, log_row_x = 0, log_row_h = 0;   // the current step's line on screen (-1: not shown)

    // Voxels seen so far at the current step, and the search radius envelope, in the 3D view.
    // voxel_states() is not tied to steps (the solver may run ahead of the current event), so
    // rebuild() replays it only as far as the VoxelVisited/VoxelCulled events up to `step`.
    bool show_voxels = true;
    std::vector<std::pair<size_t, uint8_t>> voxels;   // (voxel, 1 pending / 2 visited / 3 culled), latest state
    long vox_visited = 0, vox_pending = 0, vox_culled = 0;

    std::vector<float> radius_plot;   // search radius after insertion 1, 2, ... up to the current step

    // The graph of d^2 over T' (graph.cpp): rebuilt when `revision` changes (every rebuild()).
    unsigned long revision = 0;
    bool graph_open = false;
    unsigned long graph_revision = 0;   // the revision the graph was built for (0: never)
    long graph_samples = 0;
    double graph_z_max = NAN;           // max of d^2 over the samples and the marked maximum (world units)
    double graph_grid_max = NAN;        // max over the grid samples alone (world units)
    double graph_z_min = NAN;           // min over the grid samples (world units)
    bool graph_relief = true;           // heights from min to max d^2 (else from 0)
    float graph_yaw = -1.35f, graph_pitch = 0.6f, graph_zoom = 1.0f;
    float graph_rect[4] = {0, 0, 0, 0}; // the graph's canvas on screen (window coordinates)

    // The independent nearest-feature overlay of the domain view (overlay.cpp).
    bool show_overlay = false;
    unsigned long overlay_revision = 0;
    long overlay_samples = 0, overlay_disagree = 0, overlay_ignored = 0;
    long overlay_ties = 0;              // compared samples whose label differs from the first nearest feature by a tie
    int overlay_w = 0, overlay_h = 0;
    Vec2 overlay_lo, overlay_hi;        // the texture's extent in the target's frame
    unsigned overlay_tex = 0;           // GL texture name
    bool overlay_use_gpu = true;        // draw the overlay with overlay.frag.glsl (the comparison stays on the CPU)
    bool overlay_gpu = false;           // the texture shown came from the GPU (row 0 at the bottom)

    // The domain view's canvas on screen, the corners of T' there and what the mouse hovers, for
    // the headless JSON line.
    float view_rect[4] = {0, 0, 0, 0};
    float corner_screen[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    int hover_arc = -1, hover_face = -1;

    // The state at the current step: a snapshot inside an insertion, else the solver's own.
    std::map<long, StepSnapshot> snapshots;   // events of the solver's latest insertion
    std::shared_ptr<const DomainMesh> last_copy;
    bool mesh_changed = true;
    const StepSnapshot* snapshot() const;
    const DomainMesh* mesh() const;
    double max_sq() const;
    Vec2 max_2d() const;
    int insertions() const;
    std::vector<uint32_t> inserted_sources() const;   // the first insertions() of the solver's
    double search_radius() const { return std::sqrt(max_sq()); }
    int32_t inserting() const;                // the source whose insertion is under way (-1: none)
    // d^2 at p (frame units) as the current state has it: the domain's polynomial inside an
    // insertion, else the exact distance to the inserted sources.
    double d2_at(Vec2 p) const;

    void reset(std::shared_ptr<const LoadedScene> sc, int sd, long t);
    void clear();
    bool active() const { return solver != nullptr; }
    // Navigation; each rebuilds the drawing data.
    void forward();                   // one event
    void back();                      // one event (replay)
    void next_insertion();            // to the last event of the next insertion
    void to_end();
    void jump(long n);                // to just after event n (LONG_MAX: the end)
    void rebuild();
    const Event* advance();           // the solver's next event, keeping the snapshots
    void new_solver();                // a fresh solver for the target, observed
    void rebuild_voxels();            // `voxels` and the counts at the current step
    // The last RegionsProjected event at or before the current step, if any.
    const Event* regions_event() const;
};

// The outer loop of face f sampled (frame coordinates, straight runs merged) and triangulated
// (index triples into `outer`), as the domain view fills it.
void face_polygon(const DomainMesh& m, int f, std::vector<Vec2>& outer, std::vector<int>& tris);


// Keeps the stepper on the selected target of the current direction (reset when it changes).
struct AppState;
void sync_stepper(AppState& s);

// Its views: the timeline (timeline.h), the domain view (domain_view.h), the graph of d^2
// (graph.h), the event log (event_log.h); its events as text: event_text.h.

}  // namespace hlens::gui
