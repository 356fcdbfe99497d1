// Straub 2007 §3.1-3.2 for one target triangle: relevant triangles by a nearest-first voxel
// search bounded by the shrinking search radius, each inserted into the domain mesh.
#include "target_solver.h"

#include "label_check.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "copies.h"
#include "point_triangle.h"

namespace hlens {

const char* event_name(EventKind k) {
    static const char* names[] = {"target_begun",   "voxel_visited",  "voxel_culled",  "source_chosen", "source_culled",
                                  "regions_projected", "domain_split", "domain_created", "domain_merged", "arc_maximum",
                                  "maximum_raised", "search_radius_shrunk", "target_finished"};
    return names[(int)k];
}

namespace {
Event make_event(EventKind k) {
    Event e;
    e.kind = k;
    return e;
}
}  // namespace

// Which voxels and sources a target has seen: stamp arrays (one entry per voxel and per source,
// reused across targets by bumping the stamp) instead of hash sets. Each thread keeps one pair for
// the solver it is running; a second solver alive on the same thread (the debugger keeps several)
// gets a pair of its own.
struct TargetSolver::Seen {
    struct Stamps {
        std::vector<uint32_t> mark;
        uint32_t now = 0;
        bool in_use = false;
        void start(size_t n) {
            if (mark.size() != n) { mark.assign(n, 0); now = 0; }
            if (++now == 0) { std::fill(mark.begin(), mark.end(), 0); now = 1; }
        }
        bool insert(size_t i) {  // true if i was not seen yet
            if (mark[i] == now) return false;
            mark[i] = now;
            return true;
        }
    };
    struct Pair { Stamps voxels, sources; };
    static Pair& shared() { static thread_local Pair p; return p; }
    Pair own;
    Pair* use;
    Seen(size_t nv, size_t ns) {
        Pair& s = shared();
        use = s.voxels.in_use ? &own : &s;
        use->voxels.in_use = true;
        use->voxels.start(nv);
        use->sources.start(ns);
    }
    ~Seen() { use->voxels.in_use = false; }
    Stamps& voxels() { return use->voxels; }
    Stamps& sources() { return use->sources; }
};

TargetSolver::TargetSolver(const VoxelGrid& grid, int side, uint32_t target)
    : TargetSolver(grid, side, target, grid.mesh(side).corners(target)) {}

TargetSolver::TargetSolver(const VoxelGrid& grid, int side, uint32_t target, const std::array<Vec3, 3>& piece)
    : grid_(grid), side_(side), target_(target) {
    corners_ = piece;
    for (const Vec3& c : corners_) box_.add(c);
    frame_ = TargetFrame::make(corners_);
    centroid_ = (corners_[0] + corners_[1] + corners_[2]) / 3.0;
    for (const Vec3& c : corners_) reach_ = std::max(reach_, norm(c - centroid_));
    reach_ = reach_ * (1 + 1e-12) + 1e-300;
    if (!frame_.degenerate) {
        mesh_ = std::make_unique<DomainMesh>(frame_.ccw_corners());
    }
}

TargetSolver::~TargetSolver() = default;

TargetSolver& TargetSolver::on_event(std::function<void(const Event&)> cb) { callbacks_.push_back(std::move(cb)); return *this; }
TargetSolver& TargetSolver::record_events(bool on) { recording_ = on; return *this; }
TargetSolver& TargetSolver::stop_below(double b) { stop_below_ = b; return *this; }
TargetSolver& TargetSolver::nearest_first(bool on) {
    if (phase_ == Phase::Begin) nearest_first_ = on;
    return *this;
}
TargetSolver& TargetSolver::validate_each_insertion(bool on, bool thorough) {
    validate_each_ = on;
    validate_thorough_ = thorough;
    return *this;
}

std::array<Vec3, 3> TargetSolver::source_corners(uint32_t s) const { return grid_.mesh(1 - side_).corners(s); }

double TargetSolver::search_radius() const { return std::sqrt(max_sq_); }

void TargetSolver::emit(Event e) {
    e.step = next_step_++;
    e.insertion = (int)inserted_.size();
    e.radius = search_radius();
    for (auto& cb : callbacks_) cb(e);
    if (recording_) log_.push_back(std::move(e));
}

// A lower bound of the distance from T' to the sources listed in voxel v: the gap between the
// target's box and the voxel's, less the margins; inside the grid also the gap to the nearest of
// the target's own voxels (tighter for a large target among small voxels; the box's for a small
// one in a large voxel, whose 26 neighbours it keeps from being visited). Both shrink along a
// path from v towards a voxel of the target, so the nearest-first search still reaches every
// voxel within the search radius.
double TargetSolver::voxel_distance2(size_t v) const {
    const MeshGrid& g = grid_.of(1 - side_);
    double box_gap = 0;
    const Box3 b = g.voxel_box(v);
    for (int i = 0; i < 3; ++i) {
        const double gap = std::max({0.0, b.lo[i] - box_.hi[i], box_.lo[i] - b.hi[i]}) - 2 * g.margin();
        if (gap > 0) box_gap += gap * gap;
    }
    if (outside_grid_) return box_gap;
    double best = HUGE_VAL;
    auto c = g.coords(v);
    for (const auto& t : target_voxels_) {
        double d2 = 0;
        for (int i = 0; i < 3; ++i) {
            // Triangles are listed in voxels enlarged by margin(): the gap shrinks by two of them.
            double gap = std::max(0.0, std::max(0, std::abs(c[i] - t[i]) - 1) * g.voxel_size - 2 * g.margin());
            d2 += gap * gap;
        }
        best = std::min(best, d2);
    }
    return std::max(best, box_gap);
}

void TargetSolver::begin() {
    // Started here, not in the constructor: several solvers may live on one thread (the debugger
    // keeps one per target), but only the one being run uses the stamps at a time.
    const MeshGrid& g = grid_.of(1 - side_);
    seen_ = std::make_unique<Seen>(g.num_voxels(), g.mesh().num_triangles());
    outside_grid_ = !g.box().contains(box_);
    if (!outside_grid_)
        for (size_t v : g.voxels_of_triangle(corners_)) {
            target_voxels_.push_back(g.coords(v));
            seen_->voxels().insert(v);
            queue_.push({0.0, v});
        }
    if (target_voxels_.empty()) {
        // The target is (partly) outside the sources' grid: start from the voxels its box clamps to.
        // Each other voxel has a path to them along which the box gap never grows, so the search
        // still visits voxels in increasing order of distance.
        outside_grid_ = true;
        const auto lo = g.locate(box_.lo), hi = g.locate(box_.hi);
        for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int i = lo[0]; i <= hi[0]; ++i) {
                    const size_t v = g.index(i, j, k);
                    seen_->voxels().insert(v);
                    queue_.push({voxel_distance2(v), v});
                }
    }
    if (watching()) {
        Event e = make_event(EventKind::TargetBegun);
        e.world = corners_[0];
        emit(e);
    }
    phase_ = Phase::NextSource;
}

// Radius test with a relative margin: rounding must never cull a voxel or source that could matter;
// nor may the domain mesh's resolution. Where the meshes nearly coincide, a sliver 5e-8 of T' wide
// along an edge kept the source face's plane distance, 1.6e-9, beside the edge's 4.5e-9: the
// radius shrank to the former, the source holding the nearest edge was culled, and the target's
// maximum came out 4.9e-9 at that corner (generate_pairs.py "nearcoinc_far" 20391).
bool TargetSolver::beyond(double d2) const {
    const double r = resolved_radius();
    return d2 > r * r * (1 + 1e-9) + 1e-300;
}

double TargetSolver::upper_sq() const {
    const double r = resolved_radius();
    return r * r + rounding_sq();
}

// A lower bound of d^2 from T' to source s, tighter than the boxes': every point of T' is within
// `reach` of its centroid, so the source is at least |centroid - source| - reach away from all of
// T'. That difference (negative for a source near the centroid) goes to `dc`.
double TargetSolver::centroid_bound2(uint32_t s, double* dc) const {
    const auto sc = source_corners(s);
    const double d = std::sqrt(closest_point_on_triangle(centroid_, sc[0], sc[1], sc[2]).dist2) - reach_;
    if (dc) *dc = d;
    return d > 0 ? d * d : 0.0;
}

// The 26 neighbours of a visited voxel not seen yet join the queue by their distance.
void TargetSolver::queue_neighbours(size_t voxel) {
    const MeshGrid& g = grid_.of(1 - side_);
    const auto c = g.coords(voxel);
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int i = c[0] + dx, j = c[1] + dy, k = c[2] + dz;
                if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz) continue;
                size_t v = g.index(i, j, k);
                if (!seen_->voxels().insert(v)) continue;
                queue_.push({voxel_distance2(v), v});
                if (watching()) voxel_log_.push_back({v, 1});
            }
}

bool TargetSolver::next_source(uint32_t& s, double& dist, size_t& voxel) {
    if (nearest_first_) return next_nearest_source(s, dist, voxel);
    const Box3& tbox = box_;
    for (;;) {
        while (!pending_sources_.empty()) {
            s = pending_sources_.back();
            double d2 = pending_dist_.back();
            pending_sources_.pop_back();
            pending_dist_.pop_back();
            if (!beyond(d2) && max_sq_ < HUGE_VAL) d2 = std::max(d2, centroid_bound2(s));
            if (beyond(d2)) {
                if (watching()) {
                    Event e = make_event(EventKind::SourceCulled);
                    e.source = (int32_t)s; e.voxel = (long long)pending_voxel_; e.distance = std::sqrt(d2);
                    emit(e);
                }
                continue;
            }
            dist = std::sqrt(d2);
            voxel = pending_voxel_;
            return true;
        }
        if (queue_.empty()) return false;
        QueueItem top = queue_.top();
        if (beyond(top.d2)) return false;
        queue_.pop();
        if (watching()) {
            Event e = make_event(EventKind::VoxelVisited);
            e.voxel = (long long)top.voxel; e.distance = std::sqrt(top.d2);
            emit(e);
            voxel_log_.push_back({top.voxel, 2});
        }
        const MeshGrid& g = grid_.of(1 - side_);
        queue_neighbours(top.voxel);
        // Sources of this voxel, nearest (by bounding boxes) last so pop_back takes it first.
        std::vector<std::pair<double, uint32_t>>& found = found_;
        found.clear();
        for (const uint32_t* it = g.begin(top.voxel); it != g.end(top.voxel); ++it)
            if (seen_->sources().insert(*it)) found.push_back({box_distance2(tbox, g.mesh().triangle_bounds(*it)), *it});
        std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.first > b.first || (a.first == b.first && a.second > b.second); });
        for (auto& f : found) { pending_sources_.push_back(f.second); pending_dist_.push_back(f.first); }
        pending_voxel_ = top.voxel;
        pending_voxel_dist_ = std::sqrt(top.d2);
    }
}

// Run unwatched, the sources go in nearest first by their lower bound of distance to T' (ties, the
// sources touching T', by distance to its centroid), not in voxel order: the same sources within
// the search radius, but the domains of the nearest form first, and fewer insertions cut what a
// later one would cut again. A found source waits in a heap until no voxel still to visit can hold
// a nearer one. Stepped or watched, the paper's order (voxel by voxel) stays.
bool TargetSolver::next_nearest_source(uint32_t& s, double& dist, size_t& voxel) {
    const MeshGrid& g = grid_.of(1 - side_);
    for (;;) {
        if (!near_.empty() && (queue_.empty() || near_.front().lb < queue_.top().d2)) {
            std::pop_heap(near_.begin(), near_.end());
            const Near n = near_.back();
            near_.pop_back();
            if (beyond(n.lb)) return false;  // the rest, and every voxel left, lie farther still
            s = n.source;
            dist = std::sqrt(n.lb);
            voxel = n.voxel;
            return true;
        }
        if (queue_.empty()) return false;
        const QueueItem top = queue_.top();
        if (beyond(top.d2)) return false;
        queue_.pop();
        queue_neighbours(top.voxel);
        for (const uint32_t* it = g.begin(top.voxel); it != g.end(top.voxel); ++it) {
            if (!seen_->sources().insert(*it)) continue;
            double lb = box_distance2(box_, g.mesh().triangle_bounds(*it));
            if (beyond(lb)) continue;  // the radius only shrinks: beyond for good
            double dc;
            lb = std::max(lb, centroid_bound2(*it, &dc));
            near_.push_back({lb, dc, *it, top.voxel});
            std::push_heap(near_.begin(), near_.end());
        }
    }
}

void TargetSolver::insert(uint32_t s, double dist, size_t voxel) {
    if (watching()) {
        Event e = make_event(EventKind::SourceChosen);
        e.source = (int32_t)s; e.voxel = (long long)voxel; e.distance = dist;
        emit(e);
    }
    std::array<Vec3, 3> sc = source_corners(s);
    SourceProjection& proj = projection_;
    project_source(frame_, sc, s, proj);
    inserted_.push_back(s);
    for (const Vec3& c : sc) source_extent_ = std::max(source_extent_, norm(c - frame_.origin));
    if (!mesh_) {
        degenerate_projections_.push_back(proj);
        // Each evaluation looks at every piece along the edges and every crossing of two: after
        // every insertion that is cubic in the sources (a segment target 9 from a strip of 2,500
        // slivers, every one within the radius, took minutes). Run in one go, it is evaluated as the
        // sources double, and at the end: in between the maximum is an earlier, higher one, so
        // the search only culls less (at most twice the sources it needs) and stops no earlier.
        if (unwatched_run_ && inserted_.size() < degenerate_due_) {
            degenerate_stale_ = true;
            return;
        }
        degenerate_maximum();
        degenerate_due_ = 2 * inserted_.size();
        return;
    }
    if (watching()) {
        Event e = make_event(EventKind::RegionsProjected);
        e.source = (int32_t)s;
        const auto c = frame_.ccw_corners();
        std::vector<Vec2> tri(c.begin(), c.end());
        for (const SourceRegion& r : proj.regions) e.regions.push_back({r.kind, clip_convex(tri, r.planes)});
        emit(e);
    }
    DomainMesh::Listener L;
    if (watching()) {
        L.on_split = [&](int parent, const std::vector<int>& kids, const Quadratic2& curve) {
            Event e = make_event(EventKind::DomainSplit);
            e.source = (int32_t)s; e.face = parent; e.faces = kids; e.curve = curve;
            emit(e);
        };
        L.on_relabel = [&](int face, DomainLabel old, DomainLabel now) {
            Event e = make_event(EventKind::DomainCreated);
            e.source = (int32_t)s; e.face = face; e.label = now; e.old_label = old;
            emit(e);
        };
        L.on_merge = [&](int kept, int removed) {
            Event e = make_event(EventKind::DomainMerged);
            e.source = (int32_t)s; e.face = kept; e.other = removed;
            emit(e);
        };
    }
    // A face whose largest value is below the source's smallest possible value over the face is
    // out of its reach: d_T >= |c - T| - r on the disc (c, r) holding the face.
    // Most faces are culled, and most of those already by a lower bound of d from the source's
    // bounding ball (centre sb, radius rb): the computed d is at least |c - sb| - rb less the
    // rounding of the point-triangle distance (well below `slack`), so where the bound culls, d
    // culls too, and only the other faces need the exact distance.
    const Vec3 sb = (sc[0] + sc[1] + sc[2]) / 3.0;
    const double rb = std::max({norm(sc[0] - sb), norm(sc[1] - sb), norm(sc[2] - sb)}) * (1 + 1e-12);
    double mag = rb + 4 * frame_.scale;
    for (const Vec3& p : {sc[0], frame_.origin})
        mag += std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const double slack = 1e-11 * mag;
    auto cull = [&](int f) {
        const DomainMesh::Face& F = mesh_->faces()[f];
        if (F.infinite || !(F.max_value < HUGE_VAL)) return false;
        Box2 b = mesh_->cached_face_box(f);
        Vec2 c = 0.5 * (b.lo + b.hi);
        double r = 0.5 * norm(b.hi - b.lo) * (1 + 1e-9) + 1e-12;
        const double dl = (norm(frame_.to_world(c) - sb) * (1 - 1e-14) - rb - slack) / frame_.scale * (1 - 1e-14);
        if (dl > r && (dl - r) * (dl - r) > F.max_value * (1 + 1e-9)) return true;
        double d = std::sqrt(source_distance2(frame_, sc, c));
        return d > r && (d - r) * (d - r) > F.max_value * (1 + 1e-9);
    };
    const bool changed = mesh_->insert(proj, cull, watching() ? &L : nullptr);
    for (int k = 0; k < 3; ++k)
        corner_d2_[k] = std::min(corner_d2_[k], source_distance2(frame_, sc, mesh_->vertices()[k].p));
    if (validate_each_) {
        std::string msg = validate(validate_thorough_);
        if (!msg.empty()) throw std::logic_error("target " + std::to_string(target_) + ", after source " + std::to_string(s) + ": " + msg);
    }
    if (changed) update_maximum();  // an unchanged mesh has the same maxima (with a listener, always changed)
}

void TargetSolver::update_maximum() {
    const double sc2 = frame_.scale * frame_.scale;
    mesh_->update_maxima(candidates_);  // reuses the vector's storage
    double best = -HUGE_VAL;
    Vec2 where;
    for (const Candidate& cand : candidates_) {
        // At a corner of T' the value is held to d^2 there, evaluated directly: a corner of a thin
        // T' (a sliver target, or a piece of one, in fast mode) may lie in the tip of a domain whose
        // region line crossed T' where it was thinner than a chord the splits insert (kTinyChord),
        // and keeps that domain's polynomial beyond its region, below d^2. Generate_pairs3.py "sliver"
        // 14674: a piece 1.8e-7 tall whose tip 4.3e-5 long kept an edge's polynomial, 8.6e-11 where
        // d^2 is 1.9e-9; the piece stopped below L and fast mode left its target, which held
        // paper mode's witness, to the confirmation (a witness an ulp away, 1.9e-17 apart).
        Candidate c = cand;
        if (c.vertex >= 0 && c.vertex < 3) c.value = std::max(c.value, corner_d2_[c.vertex]);
        if (watching() && c.edge >= 0) {
            Event e = make_event(EventKind::ArcMaximum);
            e.face = -1; e.other = c.edge; e.point = c.p; e.world = frame_.to_world(c.p); e.value = c.value * sc2;
            emit(e);
        }
        if (c.value > best) {
            best = c.value;
            where = c.p;
            if (watching()) {
                Event e = make_event(EventKind::MaximumRaised);
                e.point = c.p; e.world = frame_.to_world(c.p); e.value = c.value * sc2;
                emit(e);
            }
        }
    }
    double old = max_sq_;
    max_sq_ = std::max(0.0, best) * sc2;
    max_2d_ = where;
    max_world_ = frame_.to_world(where);
    if (max_sq_ < old && watching()) {
        Event e = make_event(EventKind::SearchRadiusShrunk);
        e.value = max_sq_; e.point = where; e.world = max_world_;
        emit(e);
    }
}

namespace {

// A source's region along the segment A + t D, t in [0, 1]: its interval, the source's d^2 there
// as a polynomial in t, that polynomial's rounding on [0, 1] (slop, generously) and an upper bound
// of it over the interval (top: the chord's larger end, plus how far a concave part rises above it;
// d^2 along a line is convex but for rounding).
struct SegmentPiece { double lo, hi; Poly q; uint32_t s; double slop, top; };

void pieces_along(Vec2 A, Vec2 D, const std::vector<uint32_t>& sources, const std::vector<SourceProjection>& projections,
                  std::vector<SegmentPiece>& out) {
    RationalCurve line;
    line.n0 = A; line.n1 = D;
    out.clear();
    for (size_t i = 0; i < sources.size(); ++i)
        for (const SourceRegion& r : projections[i].regions) {
            double lo = 0, hi = 1;
            bool empty = false;
            for (const HalfPlane& h : r.planes) {
                if (h.kind == HalfPlane::All) continue;
                if (h.kind == HalfPlane::None) { empty = true; break; }
                double a = dot(h.n, D), b = h.offset - dot(h.n, A);  // inside: t a >= b
                if (a > 0) lo = std::max(lo, b / a);
                else if (a < 0) hi = std::min(hi, b / a);
                else if (b > 0) empty = true;
            }
            if (empty || lo > hi) continue;
            SegmentPiece pc{lo, hi, line.compose(r.poly), sources[i], 0, HUGE_VAL};
            for (int d = 0; d <= pc.q.deg; ++d) pc.slop += 1e-12 * std::fabs(pc.q.c[d]);
            if (pc.q.deg <= 2)
                pc.top = std::max(pc.q(lo), pc.q(hi)) + std::max(0.0, -pc.q.c[2]) * (hi - lo) * (hi - lo) / 4 + pc.slop;
            out.push_back(pc);
        }
}

// Bins along the segment A + t D, t in [0, 1]. Over bin b, [b / K, (b + 1) / K]: `top`, an upper
// bound of the lower envelope of d^2, the least over sources of the larger of d^2 at the bin's ends
// (d^2 to one triangle is convex along a line), with 1e-12 of it and `noise` (rounding_sq() in
// frame units: the evaluation's absolute rounding, for near-coincident meshes), evaluated directly
// as the candidates are; and the pieces that may be the envelope somewhere in it (their least
// value there not above `top`). A bin is live while its top is above the best value found.
struct EnvelopeBins {
    std::vector<double> top;
    std::vector<int> first, pieces;  // bin b's pieces: pieces[first[b] .. first[b + 1]), ascending
    int bin(double t) const { return std::min((int)top.size() - 1, std::max(0, (int)std::floor(t * top.size()))); }
    // The piece of bin(t) lowest at t (-1 if none holds t): its source is most likely the nearest.
    int lowest_at(double t, const std::vector<SegmentPiece>& all) const {
        const int b = bin(t);
        int best = -1;
        double v = HUGE_VAL;
        for (int i = first[b]; i < first[b + 1]; ++i) {
            const SegmentPiece& pc = all[pieces[i]];
            if (pc.lo <= t && t <= pc.hi && pc.q(t) < v) v = pc.q(t), best = pieces[i];
        }
        return best;
    }
};

double least_on(const Poly& q, double lo, double hi) {
    double m = std::min(q(lo), q(hi));
    if (q.deg == 2 && q.c[2] > 0) {
        const double x = -q.c[1] / (2 * q.c[2]);
        if (lo < x && x < hi) m = std::min(m, q(x));
    }
    return m;
}

template <class Dist2>
void envelope_bins(Vec2 A, Vec2 D, const std::vector<uint32_t>& sources, const std::vector<SegmentPiece>& pieces, int K,
                   double noise, Dist2 dist2, EnvelopeBins& out) {
    out.top.assign(K, HUGE_VAL);  // one bin: no bound, every piece
    if (K > 1) {
        std::vector<double> e(K + 1);
        for (uint32_t s : sources) {
            for (int b = 0; b <= K; ++b) e[b] = dist2(s, A + (double(b) / K) * D);
            for (int b = 0; b < K; ++b) out.top[b] = std::min(out.top[b], std::max(e[b], e[b + 1]));
        }
        for (double& t : out.top) t = t * (1 + 1e-12) + noise;
    }
    std::vector<std::pair<int, int>> in;  // (bin, piece)
    for (size_t i = 0; i < pieces.size(); ++i) {
        const SegmentPiece& pc = pieces[i];
        for (int b = out.bin(pc.lo); b <= out.bin(pc.hi); ++b) {
            const double lo = std::max(pc.lo, double(b) / K), hi = std::min(pc.hi, double(b + 1) / K);
            if (K == 1 || least_on(pc.q, lo, hi) - pc.slop <= out.top[b]) in.push_back({b, (int)i});
        }
    }
    out.first.assign(K + 1, 0);
    for (const auto& x : in) ++out.first[x.first + 1];
    for (int b = 0; b < K; ++b) out.first[b + 1] += out.first[b];
    out.pieces.resize(in.size());
    std::vector<int> fill(out.first.begin(), out.first.end() - 1);
    for (const auto& x : in) out.pieces[fill[x.first]++] = x.second;
}

}  // namespace

// A target with (nearly) no area is handled as its three edges: along a segment d^2 is the lower
// envelope of convex pieces, whose maximum lies at a piece end or where two pieces cross. Such
// points are evaluated directly, highest bound first: d^2 at a point of piece p is at most p's
// quadratic there (its source's d^2), so once no bound is above the best value found, no other
// point can beat it; two pieces cross above it only if both rise above it on their overlap, and
// only in a bin whose bound of the envelope is above it (EnvelopeBins; with many pieces); and a
// point's distances stop as soon as one is no higher than the best. (Every point against every
// source after every insertion, each source projected again each time, a target 9 away from 94
// slivers took 1.4 s, and fast mode solved three such targets in 2,052 pieces: generate_pairs11.py
// "slivers_strip" 1023, 122 s. A segment under a strip of 2,500 slivers on a circle, its maximum
// flat, crossed thousands of pieces whose tops rose above the best and evaluated each crossing
// against every source: minutes.) The interior of a sliver is within its height of an edge, so
// the result is short of the true maximum by at most that height (reported as slack()).
void TargetSolver::degenerate_maximum() {
    assert(degenerate_projections_.size() == inserted_.size());
    degenerate_stale_ = false;
    double best = -HUGE_VAL;
    struct Candidate { double bound, t; };
    std::vector<Candidate> cands;
    std::vector<SegmentPiece> pieces;
    EnvelopeBins bins;
    for (int k = 0; k < 3; ++k) {
        const Vec2 A = frame_.corners[k], D = frame_.corners[(k + 1) % 3] - A;
        pieces_along(A, D, inserted_, degenerate_projections_, pieces);
        const int K = (int)std::clamp<size_t>(pieces.size() / 16, 1, 256);  // few pieces: one bin, no bound
        const double noise = rounding_sq() / (frame_.scale * frame_.scale);
        auto dist2 = [&](uint32_t s, Vec2 p) { return ++distance_evaluations_, source_distance2(frame_, source_corners(s), p); };
        envelope_bins(A, D, inserted_, pieces, K, noise, dist2, bins);
        auto evaluate = [&] {  // highest bound first, until no bound is above the best value found
            std::sort(cands.begin(), cands.end(), [](const Candidate& x, const Candidate& y) { return x.bound > y.bound; });
            for (const Candidate& c : cands) {
                if (!(c.bound > best)) break;
                const double t = std::min(1.0, std::max(0.0, c.t));
                if (!(bins.top[bins.bin(t)] > best)) continue;
                const Vec2 p = A + t * D;
                // The source lowest there first: where it is no higher than the best, so is d^2.
                const int low = bins.lowest_at(t, pieces);
                if (low >= 0 && !(dist2(pieces[low].s, p) > best)) continue;
                const double v = direct_d2(p, best);
                if (v > best) { best = v; max_2d_ = p; }
            }
            cands.clear();
        };
        cands.assign({{HUGE_VAL, 0.0}, {HUGE_VAL, 1.0}});
        for (const SegmentPiece& pc : pieces) {
            cands.push_back({pc.q(pc.lo) + pc.slop, pc.lo});
            cands.push_back({pc.q(pc.hi) + pc.slop, pc.hi});
        }
        evaluate();
        // Two pieces cross on the envelope in a live bin only where both may be the envelope there
        // (a bin's pieces): each crossing is taken in the bin it falls in.
        for (int b = 0; b < K; ++b) {
            if (!(bins.top[b] > best)) continue;
            for (int x = bins.first[b]; x < bins.first[b + 1]; ++x)
                for (int y = x + 1; y < bins.first[b + 1]; ++y) {
                    const SegmentPiece &p = pieces[bins.pieces[x]], &q = pieces[bins.pieces[y]];
                    if (p.s == q.s || !(std::min(p.top, q.top) > best)) continue;
                    const double lo = std::max(p.lo, q.lo), hi = std::min(p.hi, q.hi);
                    if (lo > hi) continue;
                    for (double r : sign_change_roots(p.q + (-1.0) * q.q, lo, hi))
                        if (const double v = std::min(p.q(r) + p.slop, q.q(r) + q.slop); v > best && bins.bin(r) == b)
                            cands.push_back({v, r});
                }
        }
        evaluate();
    }
    double old = max_sq_;
    max_sq_ = best * frame_.scale * frame_.scale;
    max_world_ = frame_.to_world(max_2d_);
    if (max_sq_ < old && watching()) {
        Event e = make_event(EventKind::SearchRadiusShrunk);
        e.value = max_sq_; e.point = max_2d_; e.world = max_world_;
        emit(e);
    }
}

// A finished target's domain mesh may claim more than its candidates' direct values (claimed_sq()):
// the truth lies between, so the excess counts as slack too. Generate_pairs.py "sliver" 65010: a
// needle target 1.9e-5 long and 2.9e-5 of that wide, whose corner touches the end of a source
// running on from it. That source is nearest in a domain 2.9e-5 long and at most 8.5e-10 wide
// (below kVertexTolerance), left to the neighbour's edge quadratic; the candidates came out
// 4.4e-14 (at the corner, directly), the truth is 5.66e-10 and the neighbour's polynomial said
// 5.66e-10. The confirmation (confirm_top.cpp) looks at targets whose value plus slack can
// reach the result: it left this one out, and the certified upper end was 1.6e-14 short.
double TargetSolver::slack() const {
    if (covered_) return 0;
    const double excess = claimed_sq_ > max_sq_ ? std::sqrt(claimed_sq_) - std::sqrt(max_sq_) : 0.0;
    return std::max(sliver_slack(frame_), excess);
}

double TargetSolver::sliver_slack(const TargetFrame& frame) {
    if (!frame.degenerate) return 0;
    double h = 0;  // the height of the sliver over its longest edge (world units)
    for (const Vec2& c : frame.corners) h = std::max(h, std::fabs(c.y));
    return h * frame.scale;
}

double TargetSolver::rounding_sq() const {
    if (covered_) return 0;
    // A source's quadratic in the frame has coefficients of the size of |w0|^2, w0 running from
    // the frame's origin to the source's corners (T' itself has unit size): one evaluation is off
    // by a few ulps of that, whatever the (small) value.
    const double w = 1 + source_extent_ / frame_.scale;
    return 64 * 0x1p-52 * frame_.scale * frame_.scale * w * w;
}

double TargetSolver::direct_d2(Vec2 p, double floor) const {
    double best = HUGE_VAL;
    for (uint32_t s : inserted_) {
        ++distance_evaluations_;
        if (!((best = std::min(best, source_distance2(frame_, source_corners(s), p))) > floor)) break;
    }
    return best;
}

// The point of T' (frame) nearest p: a candidate may stand up to the domain mesh's resolution
// beyond T''s edges (a chord's end), and its value there is no distance of the surface.
// (Generate_pairs.py "perp" 65235, A to B: the maximum taken 1.4e-10 outside the middle of an
// edge was 1.2e-10 above the truth, and the certified interval missed it.)
Vec2 TargetSolver::onto_target(Vec2 p) const {
    const std::array<Vec2, 3> c = frame_.ccw_corners();
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && cross(c[(k + 1) % 3] - c[k], p - c[k]) >= 0;
    if (inside) return p;
    Vec2 best = c[0];
    double best_d = HUGE_VAL;
    for (int k = 0; k < 3; ++k) {
        const Vec2 q = segment_closest(p, c[k], c[(k + 1) % 3]);
        if (norm(p - q) < best_d) best_d = norm(p - q), best = q;
    }
    return best;
}

void TargetSolver::finish() {
    const double sc2 = frame_.scale * frame_.scale;
    if (covered_) {  // d = 0 exactly; the frame's origin is a corner (no rounding in the witness)
        max_sq_ = claimed_sq_ = 0;
        max_2d_ = Vec2{0, 0};
        max_world_ = frame_.origin;
    } else if (!mesh_ && degenerate_stale_) {
        degenerate_maximum();
    }
    if (mesh_ && !inserted_.empty() && !stopped_early_ && !covered_) {
        // The number comes from direct evaluation of the best candidates (design notes: extra
        // candidates never hurt, and a face with a wrong polynomial cannot inflate the result).
        claimed_sq_ = max_sq_;  // the running maximum: the candidates by their polynomials
        std::vector<const Candidate*> order;
        for (const Candidate& c : candidates_) order.push_back(&c);
        std::sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->value > b->value; });
        double top = order.empty() ? 0 : order[0]->value, best = -HUGE_VAL;
        Vec2 where = max_2d_;
        for (size_t i = 0; i < order.size(); ++i) {
            if (i >= 8 && order[i]->value < top - 1e-6 * std::max(top, 1e-300)) break;
            const Vec2 q = onto_target(order[i]->p);
            double v = direct_d2(q);
            if (v > best) { best = v; where = q; }
        }
        max_sq_ = std::max(0.0, best) * sc2;
        max_2d_ = where;
        max_world_ = frame_.to_world(where);
    }
    if (inserted_.empty()) max_sq_ = HUGE_VAL;  // B is empty: nothing is near
    if (watching()) {
        while (!queue_.empty()) {
            QueueItem q = queue_.top();
            queue_.pop();
            Event e = make_event(EventKind::VoxelCulled);
            e.voxel = (long long)q.voxel; e.distance = std::sqrt(q.d2);
            emit(e);
            voxel_log_.push_back({q.voxel, 3});
        }
        Event e = make_event(EventKind::TargetFinished);
        e.point = max_2d_; e.world = max_world_; e.value = max_sq_;
        emit(e);
    }
    phase_ = Phase::Done;
}

bool TargetSolver::step() {
    if (phase_ == Phase::Done) return false;
    if (phase_ == Phase::Begin) begin();
    uint32_t s;
    double dist;
    size_t voxel;
    // Stop only when the running maximum is below the bound by more than its rounding and resolution.
    if (stop_below_ >= 0 && upper_sq() < stop_below_) { stopped_early_ = true; finish(); return false; }
    if (!next_source(s, dist, voxel)) { finish(); return false; }
    insert(s, dist, voxel);
    // A copy of the target among the sources (a mesh against itself, an unchanged part of a
    // re-export or a local edit): nothing is nearer than 0. Every neighbour touching the target
    // lies within the search radius and was inserted, to tie at best (camelhead against itself:
    // 80 us a target, 1.9 s, where CGAL's bounds took 0.02 s). Stepping shows the paper's search.
    if (unwatched_run_ && same_corners(corners_, source_corners(s))) {
        covered_ = true;
        finish();
        return false;
    }
    return true;
}

const Event* TargetSolver::step_event() {
    recording_ = true;
    while (cursor_ >= log_.size()) {
        if (phase_ == Phase::Done) return nullptr;
        step();
    }
    return &log_[cursor_++];
}

std::unique_ptr<TargetSolver> TargetSolver::replay_to(const VoxelGrid& grid, int side, uint32_t target, long step) {
    auto ts = std::make_unique<TargetSolver>(grid, side, target);
    while (const Event* e = ts->step_event())
        if (e->step >= step) break;
    return ts;
}

void TargetSolver::run() {
    // Run in one go with no one watching: the sources nearest first (next_nearest_source). Step by
    // step, or watched, the paper's order.
    if (phase_ == Phase::Begin && !watching()) nearest_first_ = unwatched_run_ = true;
    while (step()) {}
}

// Points of face f to check it at: some interior point and the points of a 6 x 6 grid over its
// box that fall inside it, away from its boundary (where a label may rightly be either side's).
static std::vector<Vec2> probe_points(const DomainMesh& m, int f) {
    std::vector<Vec2> out;
    Vec2 p;
    if (m.interior_point(f, p)) out.push_back(p);
    const Box2 b = m.face_box(f);
    const double size = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) {
            const Vec2 q{b.lo.x + (i + 0.5) / 6 * (b.hi.x - b.lo.x), b.lo.y + (j + 0.5) / 6 * (b.hi.y - b.lo.y)};
            if (m.point_in_face(f, q) && !m.near_boundary(f, q, 1e-3 * size)) out.push_back(q);
        }
    return out;
}

std::string TargetSolver::validate(bool thorough) const {
    if (!mesh_) return "";
    std::string msg = mesh_->validate();
    if (!msg.empty()) return msg;
    std::vector<SourceProjection> proj;
    for (uint32_t s : inserted_) proj.push_back(project_source(frame_, source_corners(s), s));
    const double delta = mesh_->delta();  // the tie rule's allowance, as the mesh applied it
    const double noise = rounding_sq() / (frame_.scale * frame_.scale);  // frame units squared
    const std::vector<int> classes = thorough ? tie_classes(proj, delta) : std::vector<int>();
    const auto& F = mesh_->faces();
    // The regions of the features tied with face g's label (the same quadratic), through a chain
    // (tie_classes: merging joins neighbours link by link): the domain may extend over them. The
    // polynomial is still checked against d^2 below.
    auto tied_regions = [&](const DomainMesh::Face& g) {
        std::vector<int> seed;
        std::vector<const SourceRegion*> tied;
        for (size_t s = 0; s < proj.size(); ++s)
            for (const SourceRegion& r : proj[s].regions)
                if (same_feature_quadratic(r.poly, r.kind, g.poly, g.label.region, delta)) seed.push_back(classes[feature_index(s, r.kind)]);
        for (size_t s = 0; s < proj.size(); ++s)
            for (const SourceRegion& r : proj[s].regions)
                if (std::find(seed.begin(), seed.end(), classes[feature_index(s, r.kind)]) != seed.end()) tied.push_back(&r);
        return tied;
    };
    auto in_any = [](const std::vector<const SourceRegion*>& regions, Vec2 p, double slack) {
        for (const SourceRegion* r : regions)
            if (region_margin(*r, p, false) >= -slack) return true;
        return false;
    };
    // Whether p lies within kTinyChord of face f's boundary and `pred` holds for a neighbour face
    // there: a sliver that thin is cut by no chord (find_chords), so there either side may be right.
    auto neighbour_within_tiny_chord = [&](size_t f, Vec2 p, const auto& pred) {
        if (!mesh_->near_boundary((int)f, p, DomainMesh::kTinyChord)) return false;
        for (size_t g = 1; g < F.size(); ++g)
            if (g != f && F[g].alive && !F[g].infinite && mesh_->near_boundary((int)g, p, DomainMesh::kTinyChord) && pred(F[g]))
                return true;
        return false;
    };
    char buf[320];
    for (size_t f = 1; f < F.size(); ++f) {
        // 0. Every source's regions tile the plane: once one is inserted, no domain is uncovered.
        if (F[f].alive && F[f].infinite && !inserted_.empty())
            return std::snprintf(buf, sizeof buf, "face %zu: no source's domain after %zu insertions (area %g)", f,
                                 inserted_.size(), mesh_->face_area((int)f)), buf;
        if (!F[f].alive || F[f].infinite) continue;
        const DomainLabel L = F[f].label;
        // 1. The label names a feature of an inserted source whose quadratic is the domain's.
        const SourceProjection* own = nullptr;
        for (const SourceProjection& p : proj)
            if ((int)p.source == L.source) own = &p;
        const Quadratic2* q = own ? region_quadratic(*own, L.region) : nullptr;
        if (thorough && (!q || !same_feature_quadratic(*q, L.region, F[f].poly, L.region, delta)))
            return std::snprintf(buf, sizeof buf, "face %zu (source %d, %s): the label's quadratic is not the domain's", f,
                                 L.source, region_name(L.region)), buf;
        // Only the thorough check asks where the domain lies.
        const std::vector<const SourceRegion*> tied = thorough ? tied_regions(F[f]) : std::vector<const SourceRegion*>();
        // A face thinner than kTinyChord as a whole (its area below kTinyChord times its size) is a
        // sliver the splits left on one side (find_chords): all of it lies within kTinyChord of its
        // neighbours, wherever its label's region is, so only its polynomial is held (check 2).
        // Generate_pairs3.py "rot_tiny_far" 3051, the paper's order: a vertex region's sliver 2e-12
        // wide along T''s edge went with the edge region beside it and, once a nearer source took
        // the rest, stayed as a face 2e-12 wide whose tip lay 4.2e-7 beyond the edge's region.
        const Box2 box = mesh_->face_box((int)f);
        const bool sliver = mesh_->face_area((int)f) <= DomainMesh::kTinyChord * norm(box.hi - box.lo);
        std::vector<Vec2> probes = probe_points(*mesh_, (int)f);
        if (!thorough && probes.size() > 1) probes.resize(1);
        for (Vec2 p : probes) {
            // The domain mesh resolves d^2 to kVertexTolerance (1e-7 of T'): a boundary sits up to
            // that far from its curve, and a sliver narrower than that along a boundary, or a piece
            // that size where several boundaries cross, stays with a neighbour (domain_split.cpp,
            // boundary_hugs_chord; README "Tolerances and degenerate input"). A probe within twice
            // that of the domain's boundary is held to what that allows: the neighbour's quadratic
            // equals d^2 on the true boundary, so they differ by at most the two gradients (the
            // polynomial's, and d^2's, at most 2 d) times the distance; and it may lie that much
            // farther outside its region. Every other probe is held to 1e-7 relative, and to the
            // domain's tie slack (DomainMesh::Face::tie_slack: a tied feature may be that nearer).
            const bool rim = mesh_->near_boundary((int)f, p, 2 * DomainMesh::kVertexTolerance);
            // 2. The polynomial is d^2 there, computed directly.
            const double poly = F[f].poly(p), direct = direct_d2(p);
            auto fits = [&](const DomainMesh::Face& g, bool near_rim) {
                const double resolution =
                    near_rim ? (norm(g.poly.gradient(p)) + 2 * std::sqrt(std::max(0.0, direct))) * 2 * DomainMesh::kVertexTolerance : 0.0;
                return std::fabs(g.poly(p) - direct) <= 1e-7 * direct + 16 * noise + resolution + g.tie_slack;
            };
            // Within kTinyChord of the boundary, a neighbour's polynomial may be the right one (as
            // its label may be, check 3). Generate_pairs15.py "float32_far" 3640, nearest first: a
            // strip of an edge's domain along T''s edge ends in a sliver 8e-13 wide at T''s
            // corner; a plane inserted later is nearer over its last 4e-7 (5.5e-13 where its
            // polynomial is 2.2e-12), and the probe beside its 1e-12 arc at the corner lay there.
            if (!fits(F[f], rim) && !neighbour_within_tiny_chord(f, p, [&](const DomainMesh::Face& g) { return fits(g, true); }))
                return std::snprintf(buf, sizeof buf, "face %zu (source %d, %s): polynomial %.12g but d^2 = %.12g at (%.9g, %.9g)", f,
                                     L.source, region_name(L.region), poly, direct, p.x, p.y), buf;
            // 3. The point lies in the region of the label's feature or of one tied with it, up to
            // how far the domain's boundary may sit from the region's line (twice the vertex
            // tolerance: on a domain 1e-7 wide at a cluster of boundaries every point is that near),
            // or the region's line from where it is computed: where the sources' frame coordinates
            // round by more than that (delta, as the mesh's continuity check has it), delta
            // (generate_pairs6.py "zero_area" 7181: a target 1.6e-14 across, delta 2.8e-3, a
            // domain's tip 1.3e-6 of T' outside its region, 2e-20 in world units). By the region's
            // lines, not its bevels: two lines meeting at theta place their corner only to that
            // tolerance over theta, and a bevel measures along the wedge (generate_pairs9.py
            // "tiny_fins" 2316: a fin's face region a wedge 2.5e-7 wide, its tip where the edge
            // region's lines, 0.003 rad apart, cross 1.4e-5 further on; a point there 3.4e-8 outside
            // the face region's line was 6.9e-6 beyond its bevel, and d^2 right to 4e-9).
            const double reach = std::max(DomainMesh::kVertexTolerance, delta);
            const double slack = (rim ? 4 : 2) * reach;
            // Within kTinyChord of the boundary, a neighbour's label may be the right one: a sliver
            // that thin goes to either side, as a whole face (above) or as the end of one.
            // Generate_pairs15.py "terrain_crack" 4327: a face's end was a sliver 6e-12 wide
            // between two region lines along T''s edge, reaching a source corner where three
            // sources meet; interior_point's probe there lay 6.7e-7 beyond the label's region
            // (its corner, where an ill-conditioned region line crosses T''s edge) and 4e-10 inside
            // the neighbour's, 6e-12 away.
            if (thorough && !sliver && !in_any(tied, p, slack) &&
                !neighbour_within_tiny_chord(f, p, [&](const DomainMesh::Face& g) { return in_any(tied_regions(g), p, slack); }))
                return std::snprintf(buf, sizeof buf, "face %zu (source %d, %s): (%.9g, %.9g) lies outside the label's region", f,
                                     L.source, region_name(L.region), p.x, p.y), buf;
        }
    }
    return "";
}

}  // namespace hlens
