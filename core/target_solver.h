// One target triangle T' of A against the mesh B: Straub 2007 §3 for a single T'.
//
// Relevant source triangles come from the voxel grid (§3.2): voxels are visited outward from the
// target's own voxels, nearest first; each source triangle found is inserted into the domain mesh
// (§3.1); after every insertion d_max = max d^2 over T' is taken, and voxels farther than the
// search radius sqrt(d_max) from the target's voxels are never visited.
//
// Use it whole (`run()`), one insertion at a time (`step()`), or one event at a time
// (`step_event()`), reading the state in between. Observers see every event as it happens; with
// none attached, no event is even built. `run()` with no observer visits the same sources in
// another order: each source found waits until no unvisited voxel can hold a nearer one, and the
// nearest goes in first (the same d^2 in the end, with fewer cuts to undo).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <string>
#include <vector>

#include "domain_mesh.h"
#include "regions.h"
#include "voxel_grid.h"

namespace hlens {

enum class EventKind : uint8_t {
    TargetBegun,         // the target's frame is set up
    VoxelVisited,        // a voxel within the search radius is visited (voxel, distance)
    VoxelCulled,         // a voxel is left out: it lies beyond the search radius (voxel, distance)
    SourceChosen,        // a source triangle will be inserted (source, voxel, distance)
    SourceCulled,        // a source triangle of a visited voxel is farther than the search radius
    RegionsProjected,    // the seven regions of the source, clipped to T' (regions)
    DomainSplit,         // a domain was cut by a region boundary or a conic (face, faces, curve)
    DomainCreated,       // a piece of a domain now belongs to the source (face, label, old_label)
    DomainMerged,        // two neighbouring domains with equal polynomials became one (face, other)
    ArcMaximum,          // a local maximum of d^2 in the interior of a conic arc (edge, point, value)
    MaximumRaised,       // the running maximum of d^2 over T' was raised by a candidate (point, value)
    SearchRadiusShrunk,  // sqrt(d_max) went down (radius, value)
    TargetFinished,      // no voxel within the search radius is left (point, value)
};
const char* event_name(EventKind k);

struct RegionPolygon { Region kind; std::vector<Vec2> polygon; };

struct Event {
    EventKind kind;
    long step = 0;            // position in the target's event stream, from 0
    int insertion = 0;        // number of sources inserted when it happened
    long long voxel = -1;
    double distance = 0;      // voxel or source distance to the target (world units)
    int32_t source = -1;
    int face = -1, other = -1;
    std::vector<int> faces;
    DomainLabel label, old_label;
    Quadratic2 curve;
    std::vector<RegionPolygon> regions;
    Vec2 point;               // in the target's frame
    Vec3 world;               // the same point in world coordinates
    double value = 0;         // d^2 (world units squared)
    double radius = 0;        // search radius (world units)
};

// A solver borrows scratch memory (visited-voxel and -source marks) of the thread that constructs
// it: step it on that thread, or at least never after that thread has ended.
class TargetSolver {
public:
    // Target `target` of mesh `side` of the grid against the other mesh.
    TargetSolver(const VoxelGrid& grid, int side, uint32_t target);
    // Only the part `piece` of the target (a triangle inside it, e.g. a sub-triangle the fast
    // mode's culling left): the maximum over the target is the maximum over its pieces.
    TargetSolver(const VoxelGrid& grid, int side, uint32_t target, const std::array<Vec3, 3>& piece);
    ~TargetSolver();
    TargetSolver(const TargetSolver&) = delete;
    TargetSolver& operator=(const TargetSolver&) = delete;

    // Observers (chainable). `record_events` keeps the whole stream for step_event() and tracing.
    TargetSolver& on_event(std::function<void(const Event&)> cb);
    TargetSolver& record_events(bool on = true);
    // Stop early once d_max drops below `bound_sq` (the target cannot reach it): fast mode.
    TargetSolver& stop_below(double bound_sq);
    // Check the domain mesh's invariants after every insertion (slow; for tests).
    // `thorough`: validate() as below; otherwise only the invariants and one point per domain (the
    // check of earlier versions, cheaper).
    TargetSolver& validate_each_insertion(bool on = true, bool thorough = true);
    // Step in run()'s unwatched order (nearest source first) instead of the paper's: for checking
    // that order insertion by insertion. Before the first step.
    TargetSolver& nearest_first(bool on = true);

    // Stepping back: a fresh solver for the same target, advanced to just after event `step`
    // (the construction is deterministic, so replaying from the start gives the same state).
    static std::unique_ptr<TargetSolver> replay_to(const VoxelGrid& grid, int side, uint32_t target, long step);

    bool step();                     // insert the next source; false once finished
    const Event* step_event();       // advance to the next event (nullptr once finished)
    void run();                      // to the end; unwatched, nearest source first
    bool finished() const { return phase_ == Phase::Done; }

    // State, readable between steps.
    const TargetFrame& frame() const { return frame_; }
    const DomainMesh* domain_mesh() const { return mesh_.get(); }   // null for a degenerate target
    double max_sq() const { return max_sq_; }         // current max of d^2 over T' (world units)
    // Once finished: the domain mesh's own maximum, by its domains' polynomials (world units).
    // max_sq() is d^2 evaluated directly at the best candidates, so where a domain too thin to cut
    // stayed with a neighbour whose polynomial lies above d^2 there, the neighbour's candidates
    // come out lower than their polynomial says, and the thin domain's own maximum is nobody's
    // candidate: then this, not max_sq(), bounds d^2 over T' (see kResolution).
    double claimed_sq() const { return claimed_sq_; }
    Vec3 max_point() const { return max_world_; }
    Vec2 max_point_2d() const { return max_2d_; }
    double search_radius() const;                     // sqrt(max_sq), +inf before the first source
    int insertions() const { return (int)inserted_.size(); }
    const std::vector<uint32_t>& inserted_sources() const { return inserted_; }
    const std::vector<Event>& events() const { return log_; }
    const std::vector<Candidate>& candidates() const { return candidates_; }
    bool stopped_early() const { return stopped_early_; }
    // How far the true maximum distance may lie above max_sq()'s root: for a sliver target
    // (handled as its three edges) its height; once finished, at least claimed_sq()'s root less
    // max_sq()'s. Zero for every other target.
    double slack() const;
    // The same for a target with frame `frame`, without solving it.
    static double sliver_slack(const TargetFrame& frame);
    // How far max_sq() may be off by the rounding of the domains' quadratics (world units squared):
    // tiny against max_sq() unless the meshes (nearly) coincide, where d^2 is a small difference of
    // large terms.
    double rounding_sq() const;
    // The domain mesh resolves d^2 to within kResolution of T''s size (frame units): a sliver
    // narrower than kVertexTolerance along a boundary stays with its neighbour, and a vertex may
    // sit up to 1e-6 off its curves (DomainMesh::kOffCurve). As d is 1-Lipschitz, d over T' is at
    // most sqrt(max_sq()) + kResolution * scale: the search radius culls with that, and
    // upper_sq() bounds the true maximum by it (rounding included). Once finished, the bound is
    // taken from the larger of max_sq() and claimed_sq(): the Lipschitz step starts from the
    // domains' polynomials, which the directly evaluated candidates may undercut.
    static constexpr double kResolution = 1e-6;
    double upper_sq() const;
    // Voxel states for display: 0 unseen, 1 pending, 2 visited, 3 culled.
    const std::vector<std::pair<size_t, uint8_t>>& voxel_states() const { return voxel_log_; }
    // The domain mesh's invariants, then per domain (issue 8): its label names a feature of an
    // inserted source whose quadratic is the domain's polynomial (up to the tie rule); at several
    // interior points the polynomial equals d^2 computed directly (to 1e-7 relative), and the point
    // lies in the label's region or in that of a feature tied with it (up to twice
    // DomainMesh::kVertexTolerance). A point within twice that of the domain's boundary, below the
    // domain mesh's resolution, is held to the gradients times that distance, and to four times
    // it for the region; a domain thinner than DomainMesh::kTinyChord as a whole, only to its
    // polynomial. Empty if all hold, else the first failure.
    std::string validate(bool thorough = true) const;

    // The exact squared distance from a point of T' (frame coordinates) to the inserted sources.
    // With `floor`: the first source's d^2 found no higher than it, if any (the least is not needed).
    double direct_d2(Vec2 p, double floor = -HUGE_VAL) const;
    // Point-to-source distances evaluated so far (direct_d2's and the degenerate maximum's): a
    // counter of the work, for tests and profiling.
    size_t distance_evaluations() const { return distance_evaluations_; }
    Vec2 onto_target(Vec2 p) const;  // the point of T' nearest p
    uint32_t target() const { return target_; }
    std::array<Vec3, 3> source_corners(uint32_t s) const;

private:
    enum class Phase { Begin, NextSource, Done };
    struct QueueItem { double d2; size_t voxel; bool operator<(const QueueItem& o) const { return d2 > o.d2; } };

    void emit(Event e);
    bool watching() const { return !callbacks_.empty() || recording_; }
    void begin();
    bool next_source(uint32_t& s, double& dist, size_t& voxel);
    bool next_nearest_source(uint32_t& s, double& dist, size_t& voxel);
    void queue_neighbours(size_t voxel);
    bool beyond(double d2) const;                          // farther than the search radius
    // sqrt(max_sq_) widened by the domain mesh's resolution (kResolution): beyond(), upper_sq().
    double resolved_radius() const { return std::sqrt(std::max(max_sq_, claimed_sq_)) + kResolution * frame_.scale; }
    double centroid_bound2(uint32_t s, double* dc = nullptr) const;
    void insert(uint32_t s, double dist, size_t voxel);
    void update_maximum();
    void finish();
    double voxel_distance2(size_t v) const;
    void degenerate_maximum();

    const VoxelGrid& grid_;
    int side_;
    uint32_t target_;
    std::array<Vec3, 3> corners_;     // the target's corners, or the piece's
    Box3 box_;                        // their bounding box
    Vec3 centroid_;
    double reach_ = 0;                // largest distance from the centroid to a point of T'
    double source_extent_ = 0;        // largest distance from the frame's origin to an inserted source's corner
    TargetFrame frame_;
    std::unique_ptr<DomainMesh> mesh_;
    Phase phase_ = Phase::Begin;

    std::vector<std::function<void(const Event&)>> callbacks_;
    bool recording_ = false, validate_each_ = false, validate_thorough_ = true;
    std::vector<Event> log_;
    size_t cursor_ = 0;
    long next_step_ = 0;

    std::vector<std::array<int, 3>> target_voxels_;
    bool outside_grid_ = false;        // the target is not inside the sources' grid: box gaps
    std::priority_queue<QueueItem> queue_;
    std::vector<size_t> seen_voxels_;   // sorted insertion not needed: small; use a hash set below
    std::vector<uint32_t> pending_sources_;
    std::vector<double> pending_dist_;
    size_t pending_voxel_ = 0;
    double pending_voxel_dist_ = 0;
    std::vector<uint32_t> inserted_;
    std::vector<std::pair<size_t, uint8_t>> voxel_log_;
    struct Seen;
    std::unique_ptr<Seen> seen_;

    double max_sq_ = HUGE_VAL;        // world units
    double claimed_sq_ = 0;           // world units; set by finish() (claimed_sq())
    // d^2 at T''s corners (the domain mesh's vertices 0-2), exact over the inserted sources (frame
    // units): update_maximum holds a corner's candidate to it (see there).
    double corner_d2_[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    Vec2 max_2d_;
    Vec3 max_world_;
    double stop_below_ = -1;
    bool stopped_early_ = false;
    std::vector<Candidate> candidates_;
    SourceProjection projection_;     // the source being inserted (its storage reused)
    std::vector<SourceProjection> degenerate_projections_;  // a target with no domain mesh: each inserted source's
    // run() unwatched: found sources by (lower bound of d^2, centroid distance less reach), a min-heap.
    struct Near {
        double lb, key;
        uint32_t source;
        size_t voxel;
        bool operator<(const Near& o) const { return lb > o.lb || (lb == o.lb && (key > o.key || (key == o.key && source > o.source))); }
    };
    std::vector<Near> near_;
    bool nearest_first_ = false;
    mutable size_t distance_evaluations_ = 0;
    // run() unwatched: a target with no domain mesh has degenerate_maximum() due when the inserted
    // sources reach this many (they double between), and at the end if any came in since; and a
    // target with the corners of an inserted source ends there (covered_).
    bool unwatched_run_ = false, degenerate_stale_ = false;
    size_t degenerate_due_ = 1;
    std::vector<std::pair<double, uint32_t>> found_;  // a visited voxel's new sources (storage reused)
    // The target (or piece) has the three corners of an inserted source, so it lies in that source
    // and d = 0 on all of it, exactly: max_sq() is 0 at a corner and no other source is needed.
    bool covered_ = false;
};

}  // namespace hlens
