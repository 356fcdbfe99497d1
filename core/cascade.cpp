// Fast mode: culling by cascading bounds (design notes, "Beyond the paper: exact and fast").
//
// h(A,B)^2 = max over targets T' of max over T' of d^2, and the maximum over T' is the maximum over
// any set of pieces covering T'. So a piece may be dropped as soon as an upper bound of d^2 over it
// is below a lower bound L of the result, and only the pieces left need the exact construction.
//
//   L  starts at the farthest vertex of A and rises with every exact value and with the true
//      distance of every piece's centroid (each is the distance of a point of A to B: <= h).
//   U(S) for a piece S (a sub-triangle of T'):
//      - for ANY triangle T of B, d(., T) is convex, so max over S of d(., T) is at a corner of S:
//        U(S) = min over a few candidate triangles T (nearest to S's centroid, to its parent's
//        centroid, to T''s corners) of max over corners v of |v - T|;
//      - d(., B) is 1-Lipschitz: max over S of d <= d(c) + r, with c the centroid and r the
//        largest |c - corner|.
//   A piece with U(S) < L is dropped; a piece larger than the triangles of B near it is split in
//   four at its edge midpoints (the bounds tighten as pieces shrink); a small piece that survives
//   is solved exactly (TargetSolver on the piece, stopped as soon as its search radius is below L).
//
// The result is exact, not bounded: every point of A lies in a dropped piece (whose d^2 < L <= h^2)
// or in a solved one. Comparisons use a tie margin far above rounding (tie_threshold_sq), so a
// piece is dropped only when it is certainly below. At the end, every target that has a solved
// piece within the tie margin of the final L is solved again whole, as paper mode solves it: the
// maximum, its point and the lowest-index witness among equal values are then paper mode's, bit for
// bit, whatever order the threads ran in.
#include "cascade.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <numeric>
#include <unordered_map>

#include "confirm_top.h"
#include "copies.h"
#include "parallel.h"
#include "point_triangle.h"
#include "split_pattern.h"
#include "target_solver.h"

namespace hlens {

namespace {

constexpr double kTieMargin = 1e-9;  // relative, on distances
constexpr int kMaxDepth = 10;        // pieces of 1/1024 of the target's size at most
constexpr double kSplitRatio = 1.0;  // split while a piece is longer than this many source edges,
constexpr double kFineRatio = 0.125;  // or this many while its centroid is below L
constexpr int kCandidates = 4;       // triangles of B tried for the corner bound of a piece

using Corners = std::array<Vec3, 3>;

struct Piece {
    Corners c;
    double u = HUGE_VAL;         // upper bound of d^2 over the piece (world units)
    double centre_sq = 0;        // d^2 at its centroid, once tightened
    uint32_t target = 0;
    int depth = 0;
    bool tightened = false;      // u includes the bounds from the centroid's nearest triangle
    uint32_t corner_tri[3];      // nearest triangle of B to each corner
    uint32_t cand[kCandidates];  // candidate nearest triangles, UINT32_MAX where unused
};

double longest_edge2(const Corners& c) {
    return std::max({norm2(c[1] - c[0]), norm2(c[2] - c[1]), norm2(c[0] - c[2])});
}

// TargetSolver::sliver_slack() of target `c`, without solving it (solved whole, its slack() may be
// more: claimed_sq()): its height over its longest edge if its frame is degenerate, else 0. The
// frame is built only for nearly flat triangles (the frame's test is a height below 1e-7 of the
// longest edge; the cross product's rounding is far below the factor 10 kept here).
double sliver_slack(const Corners& c) {
    const double l2 = longest_edge2(c);
    if (norm(cross(c[1] - c[0], c[2] - c[0])) > 1e-6 * l2) return 0;
    return TargetSolver::sliver_slack(TargetFrame::make(c));
}

// max of d^2 over S when S is cut by a plane through the edge that triangles t1 and t2 of B share,
// bisecting their dihedral angle: each side is a convex polygon, bounded by its vertices against
// one of the two (convexity again). Tight where S straddles that edge and d to the two triangles is
// the distance to their planes; +inf when they share no edge.
double edge_cut_bound_sq(const Corners& S, const TriangleMesh& B, uint32_t t1, uint32_t t2) {
    const Tri &f1 = B.triangles[t1], &f2 = B.triangles[t2];
    uint32_t shared[2], o1 = UINT32_MAX, o2 = UINT32_MAX;
    int n = 0;
    for (uint32_t v : f1) {
        if (v == f2[0] || v == f2[1] || v == f2[2]) { if (n < 2) shared[n] = v; ++n; }
        else o1 = v;
    }
    if (n != 2 || o1 == UINT32_MAX) return HUGE_VAL;
    for (uint32_t v : f2)
        if (v != shared[0] && v != shared[1]) o2 = v;
    if (o2 == UINT32_MAX) return HUGE_VAL;
    const Vec3 a = B.positions[shared[0]], e = B.positions[shared[1]] - a;
    const double e2 = norm2(e);
    if (!(e2 > 0)) return HUGE_VAL;
    auto inward = [&](uint32_t o) {  // unit direction from the edge into the triangle, in its plane
        Vec3 w = B.positions[o] - a;
        w -= (dot(w, e) / e2) * e;
        double l = norm(w);
        return l > 0 ? w / l : Vec3{};
    };
    const Vec3 m = inward(o1) - inward(o2);
    if (!(norm2(m) > 0)) return HUGE_VAL;  // folded onto each other: no plane between them
    const auto c1 = B.corners(t1), c2 = B.corners(t2);
    auto d1 = [&](const Vec3& p) { return closest_point_on_triangle(p, c1[0], c1[1], c1[2]).dist2; };
    auto d2 = [&](const Vec3& p) { return closest_point_on_triangle(p, c2[0], c2[1], c2[2]).dist2; };
    double side[3], u = 0;
    for (int i = 0; i < 3; ++i) {
        side[i] = dot(S[i] - a, m);
        if (side[i] >= 0) u = std::max(u, d1(S[i]));
        if (side[i] <= 0) u = std::max(u, d2(S[i]));
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if ((side[i] > 0 && side[j] < 0) || (side[i] < 0 && side[j] > 0)) {
            const Vec3 x = S[i] + (side[i] / (side[i] - side[j])) * (S[j] - S[i]);
            u = std::max({u, d1(x), d2(x)});
        }
    }
    return u;
}

// Pieces in decreasing order of their bound, shared by the workers: whole targets from a list
// sorted once, split pieces from a heap. A worker that finds nothing waits while others may still
// push; the run ends when nothing is queued and nobody is working.
class PieceQueue {
public:
    PieceQueue(const std::vector<uint32_t>& order, const std::vector<double>& U, std::function<Piece(uint32_t)> root)
        : order_(order), U_(U), root_(std::move(root)) {}

    // A root piece is taken under the lock and built after it (on a mesh of a million targets,
    // building them under the lock kept the second thread waiting).
    bool pop(Piece& out, const std::atomic<bool>* cancel) {
        uint32_t root = UINT32_MAX;
        {
            std::unique_lock<std::mutex> lock(m_);
            for (;;) {
                if (cancel && cancel->load()) return false;
                const bool have_root = next_ < order_.size();
                if (!heap_.empty() && (!have_root || heap_.front().u >= U_[order_[next_]])) {
                    std::pop_heap(heap_.begin(), heap_.end(), lower);
                    out = heap_.back();
                    heap_.pop_back();
                } else if (have_root) {
                    root = order_[next_++];
                } else if (busy_ == 0) {
                    return false;
                } else {
                    cv_.wait(lock);
                    continue;
                }
                ++busy_;
                break;
            }
        }
        if (root != UINT32_MAX) out = root_(root);
        return true;
    }
    void push(const Piece& p) {
        std::lock_guard<std::mutex> lock(m_);
        heap_.push_back(p);
        std::push_heap(heap_.begin(), heap_.end(), lower);
        cv_.notify_one();
    }
    void done() {
        std::lock_guard<std::mutex> lock(m_);
        if (--busy_ == 0) cv_.notify_all();
    }
    size_t roots_taken() const { return next_; }

private:
    static bool lower(const Piece& a, const Piece& b) { return a.u < b.u; }
    const std::vector<uint32_t>& order_;
    const std::vector<double>& U_;
    std::function<Piece(uint32_t)> root_;
    std::mutex m_;
    std::condition_variable cv_;
    std::vector<Piece> heap_;
    size_t next_ = 0;
    int busy_ = 0;
};

// The shared state of one cascade run.
class Cascade {
public:
    Cascade(const VoxelGrid& grid, int side, const HausdorffOptions& opt, TargetTable& out)
        : grid_(grid), side_(side), A_(grid.mesh(side)), B_(grid.mesh(1 - side)), opt_(opt), out_(out),
          best_sq_(A_.num_triangles()), bound_sq_(A_.num_triangles()) {
        coord_ = coordinate_magnitude(A_, B_);
        for (auto& b : best_sq_) b = -1.0;
        for (auto& b : bound_sq_) b = 0.0;
    }

    void run() {
        const int threads = resolve_threads(opt_.threads);
        std::vector<double> vertex_d2;
        std::vector<uint32_t> near_vertex;
        out_.vertex_sq = farthest_vertex_sq(grid_, side_, threads, opt_.cancel, &near_vertex, &vertex_d2);
        L_ = out_.vertex_sq;
        out_.copy = copied_targets(grid_, side_, vertex_d2);
        const size_t n = A_.num_triangles();
        // A first bound per target from its corners (no new query), and the order in which targets
        // are taken: largest bound first, so that L rises early.
        std::vector<double> U(n);
        parallel_for(n, threads, opt_.cancel, [&](size_t t) {
            U[t] = out_.copy[t] ? 0.0 : root_piece((uint32_t)t, near_vertex, vertex_d2, HUGE_VAL).u;
        });
        std::vector<uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return U[x] > U[y]; });
        PieceQueue queue(order, U, [&](uint32_t t) { return root_piece(t, near_vertex, vertex_d2, U[t]); });
        ProgressTicker prog(opt_.progress, n);
        parallel_for((size_t)threads, threads, opt_.cancel, [&](size_t) {
            Piece p;
            while (queue.pop(p, opt_.cancel)) {
                if (p.depth == 0) prog.tick();
                process(p, queue);
                queue.done();
            }
        });
        if (opt_.cancel && opt_.cancel->load()) return;
        solve_ties(threads);
        out_.solves = solves_.load();
    }

private:
    double threshold() const { return tie_threshold_sq(L_.load(), coord_); }

    // A target as one piece, bounded by its corners' nearest triangles and, as d is 1-Lipschitz,
    // by a corner's distance plus the longest edge from it.
    // `known`: the bound when already computed.
    Piece root_piece(uint32_t t, const std::vector<uint32_t>& near_vertex, const std::vector<double>& vertex_d2,
                     double known) const {
        Piece p;
        p.c = A_.corners(t);
        p.target = t;
        for (int i = 0; i < 3; ++i) p.corner_tri[i] = near_vertex[A_.triangles[t][i]];
        set_candidates(p, UINT32_MAX);
        p.u = known;
        if (known < HUGE_VAL) return p;
        p.u = corner_bound(p);
        for (int i = 0; i < 3; ++i) {
            const double r = std::sqrt(std::max(norm2(p.c[(i + 1) % 3] - p.c[i]), norm2(p.c[(i + 2) % 3] - p.c[i])));
            const double lip = std::sqrt(vertex_d2[A_.triangles[t][i]]) + r;
            p.u = std::min(p.u, lip * lip);
        }
        return p;
    }

    // Candidates: the centroid's nearest triangle first, then the corners'.
    static void set_candidates(Piece& p, uint32_t centre_tri) {
        std::fill(p.cand, p.cand + kCandidates, UINT32_MAX);
        int k = 0;
        auto add = [&](uint32_t t) {
            if (t != UINT32_MAX && std::find(p.cand, p.cand + k, t) == p.cand + k) p.cand[k++] = t;
        };
        add(centre_tri);
        for (uint32_t t : p.corner_tri) add(t);
    }

    double corner_bound(const Piece& p) const {
        double u = HUGE_VAL;
        for (int i = 0; i < kCandidates && p.cand[i] != UINT32_MAX; ++i) {
            u = std::min(u, corner_distance_bound2(p.c, B_.corners(p.cand[i])));
            for (int j = i + 1; j < kCandidates && p.cand[j] != UINT32_MAX; ++j)
                u = std::min(u, edge_cut_bound_sq(p.c, B_, p.cand[i], p.cand[j]));
        }
        return u;
    }

    // The bounds from the centroid: its true distance raises L; its nearest triangle joins the
    // candidates; d(c) + r bounds d over the piece (1-Lipschitz). Returns false if B is empty.
    bool tighten(Piece& p) {
        // The corners' triangles first: often enough to drop the piece without a query.
        set_candidates(p, p.cand[0]);
        p.u = std::min(p.u, corner_bound(p));
        if (p.u < threshold()) return true;
        const Vec3 c = (p.c[0] + p.c[1] + p.c[2]) / 3.0;
        VoxelGrid::Nearest q = grid_.nearest(1 - side_, c, p.cand[0]);
        if (q.triangle == UINT32_MAX) return false;
        atomic_max(L_, q.dist2);  // a point of A at this distance: L <= h
        set_candidates(p, q.triangle);
        double r = 0;
        for (const Vec3& v : p.c) r = std::max(r, norm(v - c));
        const double lipschitz = std::sqrt(q.dist2) + r;
        p.u = std::min({p.u, corner_bound(p), lipschitz * lipschitz});
        p.centre_sq = q.dist2;
        p.tightened = true;
        return true;
    }

    void drop(const Piece& p) { atomic_max(bound_sq_[p.target], p.u); }

    // Whether p is longer than the smallest piece, 1/2^kMaxDepth of its target's longest edge (1.5
    // times it: four children halve every edge, so they stop at depth kMaxDepth whatever the
    // rounding; a thin piece, split in two, takes at most two splits to halve its longest edge).
    bool above_smallest(const Piece& p) const {
        constexpr double k = 1.5 / (1 << kMaxDepth);
        return p.depth < 3 * kMaxDepth && longest_edge2(p.c) > k * k * longest_edge2(A_.corners(p.target));
    }

    void process(Piece& p, PieceQueue& queue) {
        if (p.u < threshold()) return drop(p);
        if (p.depth == 0 && out_.copy[p.target]) return record_copy(p.target);
        if (!p.tightened && !tighten(p)) return;
        if (p.u < threshold()) return drop(p);
        // Split while the piece is larger than the triangles of B near it (a construction costs about
        // as many insertions as the sources it spans, a bound one query), and while its centroid is
        // below L down to a fraction of them: the bounds tighten as pieces shrink until one drops it.
        // A source smaller than a thousandth of its distance (a point, a tiny triangle) counts as
        // that large: below it, a smaller piece spans no fewer sources (those within reach of its
        // centroid), and splitting down to kMaxDepth made 4^10 pieces, each solved
        // (generate_pairs7.py "points_on_circle" 1269: 50 point triangles round a target 5e-10
        // across took minutes; a triangle 1e-9 across under one point, 1,048,577 solves and 2 s).
        // But where L is within the tie margin of 0 (near-coincident meshes far from the origin:
        // the margin's absolute part, 1e-11 of the coordinates, is above L), no bound can drop a
        // piece, and splitting only multiplies the solves: 4^10 pieces of each of eight targets
        // 1.2e-7 across, 1.6e-10 from a plane 2e7 from the origin, took hours (generate_pairs9.py
        // "cluster_vertex" 260). The piece is solved as it is.
        const double ratio = p.centre_sq >= threshold() ? kSplitRatio : kFineRatio;
        const double source2 = std::max(longest_edge2(B_.corners(p.cand[0])), 1e-6 * p.centre_sq);
        if (above_smallest(p) && threshold() > 0 && longest_edge2(p.c) > ratio * ratio * source2) {
            // Points 0-2 are the corners, 3-5 the edge midpoints; those the children use get their
            // nearest triangles (four children, or two for a thin piece: split_pattern).
            const Vec3 pt[6] = {p.c[0], p.c[1], p.c[2], 0.5 * (p.c[0] + p.c[1]), 0.5 * (p.c[1] + p.c[2]),
                                0.5 * (p.c[2] + p.c[0])};
            const SplitPattern sp = split_pattern(p.c);
            bool used[6] = {};
            for (int n = 0; n < sp.count; ++n)
                for (int k : sp.child[n]) used[k] = true;
            uint32_t tri[6] = {p.corner_tri[0], p.corner_tri[1], p.corner_tri[2], 0, 0, 0};
            for (int k = 3; k < 6; ++k) {
                if (!used[k]) continue;
                VoxelGrid::Nearest q = grid_.nearest(1 - side_, pt[k], tri[k - 3]);
                atomic_max(L_, q.dist2);
                tri[k] = q.triangle;
            }
            for (int n = 0; n < sp.count; ++n) {
                Piece child = p;  // the parent's bound holds over the child too
                for (int i = 0; i < 3; ++i) {
                    child.c[i] = pt[sp.child[n][i]];
                    child.corner_tri[i] = tri[sp.child[n][i]];
                }
                child.depth = p.depth + 1;
                child.tightened = false;
                if (!tighten(child)) return;
                if (child.u < threshold()) drop(child);
                else queue.push(child);
            }
            return;
        }
        solve_piece(p);
    }

    // A copy of a source (copies.h): solved whole, with TargetSolver's values for it (0 at the
    // frame's origin), so that paper mode, which runs the solver, has the same.
    void record_copy(uint32_t t) {
        std::lock_guard<std::mutex> lock(whole_mutex_);
        whole_[t] = {0.0, Vec2{0, 0}, 0.0};
        best_sq_[t] = 0.0;
    }

    void solve_piece(const Piece& p) {
        const double l = threshold();
        TargetSolver ts(grid_, side_, p.target, p.c);
        ts.stop_below(l);
        ts.run();
        ++solves_;
        if (ts.stopped_early()) {  // below L: its running maximum bounds it from above
            atomic_max(bound_sq_[p.target], ts.upper_sq());
            return;
        }
        atomic_max(L_, ts.max_sq());
        if (p.depth == 0) {  // the whole target, constructed as paper mode does: solve_ties need not redo it
            assert(p.c == A_.corners(p.target));
            std::lock_guard<std::mutex> lock(whole_mutex_);
            whole_[p.target] = {ts.max_sq(), ts.max_point_2d(), ts.slack()};
        }
        // Its domain mesh's own maximum bounds the piece where its candidates may fall short (slack()).
        atomic_max(bound_sq_[p.target], ts.claimed_sq());
        // With its rounding: the same maximum computed over the whole target may come out higher.
        atomic_max(best_sq_[p.target], ts.max_sq() + ts.rounding_sq());
        if (ts.slack() > 0) {
            std::lock_guard<std::mutex> lock(upper_mutex_);
            out_.piece_upper = std::max(out_.piece_upper, std::sqrt(ts.max_sq()) + ts.slack());
        }
    }

    // Targets whose pieces reach the tie margin of the final L are solved whole, as paper mode does.
    // Then every target that can reach the tie margin of the largest exact value E is solved whole
    // too: L counts true distances of points, E the domain meshes' maxima, which may lie below the
    // truth by their vertices' error (~1e-7 of a target's size), so E can be below L by more than
    // the margin (independent pair 11608: a target left unsolved held paper mode's witness). With
    // every target within the tie margin of E solved whole, the targets that tie with the witness
    // (and the witness itself) are paper mode's, whichever order the cascade ran in.
    void solve_ties(int threads) {
        const size_t n = A_.num_triangles();
        const double l = threshold();
        std::vector<uint32_t> ties;
        for (uint32_t t = 0; t < n; ++t) {
            // An upper bound until the target is solved whole below, widened by the tie margin: the
            // bounds are exact point-triangle distances, the solver's values carry rounding.
            const double b = std::sqrt(std::max(bound_sq_[t].load(), std::max(best_sq_[t].load(), 0.0)));
            out_.bound[t] = b * (1 + kTieMargin) + 1e-11 * (coord_ + 1);
            // A sliver target not solved whole: how far its true maximum may lie above its solved
            // pieces' values, as paper mode has it (solving it whole below records its own).
            out_.slack[t] = sliver_slack(A_.corners(t));
            if (best_sq_[t] >= l) ties.push_back(t);
        }
        for (;;) {
            parallel_for(ties.size(), threads, opt_.cancel, [&](size_t k) {
                uint32_t t = ties[k];
                if (const auto w = whole_.find(t); w != whole_.end()) {  // solved whole by the cascade
                    out_.record(t, w->second.max_sq, w->second.at, w->second.slack);
                    return;
                }
                TargetSolver ts(grid_, side_, t);  // no early stop: exactly paper mode's construction
                ts.run();
                ++solves_;
                out_.record(t, ts);
            });
            if (opt_.cancel && opt_.cancel->load()) return;
            double e = -1;  // the largest exact value so far
            for (uint32_t t = 0; t < n; ++t) e = std::max(e, out_.value_sq[t]);
            if (e < 0) break;  // nothing solved whole: the driver's safety net
            // Pieces were dropped or stopped below the threshold of L; where E < L some may still be
            // above that of E (the bounds are upper bounds of the exact values, as compared above).
            // So are the targets the certificate's confirmation of the top looks at (those that can
            // reach E within their domain meshes' vertex error): with their exact values, its set,
            // order and bound are paper mode's (independent pairs 2550, 2998, 3878: near-coincident
            // copies whose upper ends differed by up to 4e-11 relative between the modes).
            const double le = tie_threshold_sq(e, coord_);
            ties.clear();
            for (uint32_t t = 0; t < n; ++t) {
                if (out_.exact[t]) continue;
                if (std::max(bound_sq_[t].load(), best_sq_[t].load()) >= le ||
                    can_reach(A_.corners(t), out_.bound[t], out_.slack[t], std::sqrt(e)))
                    ties.push_back(t);
            }
            if (ties.empty()) break;
        }
    }

    const VoxelGrid& grid_;
    int side_;
    const TriangleMesh &A_, &B_;
    const HausdorffOptions& opt_;
    TargetTable& out_;
    double coord_ = 0;
    std::atomic<double> L_{0.0};
    std::atomic<size_t> solves_{0};
    std::mutex upper_mutex_;
    std::vector<std::atomic<double>> best_sq_;   // per target: largest value of a solved piece (+ rounding), -1: none
    std::vector<std::atomic<double>> bound_sq_;  // per target: largest bound of a dropped piece
    // Targets the cascade solved whole without an early stop (a depth-0 piece: paper mode's
    // construction, as solve_ties would run it): near-coincident meshes far from the origin, where
    // the tie margin is above L and nothing is dropped, had every target solved twice
    // (generate_pairs10.py "fan_thin" 135: 965 targets of ~770 insertions each, 16 s).
    struct Whole { double max_sq; Vec2 at; double slack; };
    std::unordered_map<uint32_t, Whole> whole_;
    std::mutex whole_mutex_;
};

}  // namespace

void TargetTable::resize(size_t n) {
    value_sq.assign(n, -1.0);
    where.assign(n, Vec2{});
    slack.assign(n, 0.0);
    bound.assign(n, 0.0);
    exact.assign(n, 0);
    copy.assign(n, 0);
}

void TargetTable::record(uint32_t t, const TargetSolver& whole) { record(t, whole.max_sq(), whole.max_point_2d(), whole.slack()); }

void TargetTable::record(uint32_t t, double max_sq, Vec2 at, double sliver_slack) {
    value_sq[t] = max_sq;
    where[t] = at;
    slack[t] = sliver_slack;
    bound[t] = std::sqrt(max_sq);
    exact[t] = 1;
}

double coordinate_magnitude(const TriangleMesh& A, const TriangleMesh& B) {
    Box3 box = A.bounds();
    box.add(B.bounds());
    return std::max({std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.lo.z), std::fabs(box.hi.x), std::fabs(box.hi.y),
                     std::fabs(box.hi.z)});
}

double tie_threshold_sq(double lower_sq, double coord) {
    const double tie_abs = 1e-11 * (coord + 1);
    const double l = std::max(0.0, std::sqrt(lower_sq) * (1 - kTieMargin) - tie_abs);
    return l * l;
}

double farthest_vertex_sq(const VoxelGrid& grid, int side, int threads, const std::atomic<bool>* cancel,
                          std::vector<uint32_t>* nearest_triangle, std::vector<double>* nearest_d2) {
    const TriangleMesh& A = grid.mesh(side);
    const size_t nv = A.positions.size();
    std::vector<char> used(nv, 0);
    for (const Tri& f : A.triangles)
        for (uint32_t i : f) used[i] = 1;
    std::vector<double> d2(nv, 0.0);
    if (nearest_triangle) nearest_triangle->assign(nv, UINT32_MAX);
    parallel_for(nv, threads, cancel, [&](size_t v) {
        if (!used[v]) return;
        VoxelGrid::Nearest q = grid.nearest(1 - side, A.positions[v]);
        d2[v] = q.dist2;
        if (nearest_triangle) (*nearest_triangle)[v] = q.triangle;
    });
    double m = 0;
    for (size_t v = 0; v < nv; ++v)
        if (used[v]) m = std::max(m, d2[v]);
    if (nearest_d2) *nearest_d2 = std::move(d2);
    return m;
}

void cascade_targets(const VoxelGrid& grid, int side, const HausdorffOptions& opt, TargetTable& out) {
    out.resize(grid.mesh(side).num_triangles());
    Cascade(grid, side, opt, out).run();
}

}  // namespace hlens
