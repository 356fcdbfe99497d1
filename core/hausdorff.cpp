// Straub 2007, Algorithm 1 (the loop over targets), plus the fast mode of the design notes
// ("Beyond the paper: exact and fast") and the certified interval ("Certified answer").
#include "hausdorff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

#include "parallel.h"
#include "point_triangle.h"
#include "target_solver.h"

namespace hlens {

const char* mode_name(Mode m) { return m == Mode::Paper ? "paper" : "fast"; }

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kTieMargin = 1e-9;

struct Progress {
    const HausdorffOptions& opt;
    size_t total;
    std::atomic<size_t> done{0};
    std::atomic<long long> last_ms{-1000};
    Clock::time_point start = Clock::now();
    void tick() {
        size_t d = ++done;
        if (!opt.progress) return;
        long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count();
        long long prev = last_ms.load();
        if ((ms - prev >= 100 || d == total) && last_ms.compare_exchange_strong(prev, ms)) opt.progress((double)d / total);
    }
};

// The largest coordinate magnitude of either mesh: rounding of positions scales with it.
double coordinate_magnitude(const TriangleMesh& A, const TriangleMesh& B) {
    Box3 box = A.bounds();
    box.add(B.bounds());
    return std::max({std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.lo.z), std::fabs(box.hi.x), std::fabs(box.hi.y),
                     std::fabs(box.hi.z)});
}

}  // namespace

OneSidedResult one_sided(const VoxelGrid& grid, int side, const HausdorffOptions& opt) {
    auto t0 = Clock::now();
    const TriangleMesh& A = grid.mesh(side);
    const TriangleMesh& B = grid.mesh(1 - side);
    const size_t n = A.num_triangles();
    const int threads = resolve_threads(opt.threads);
    OneSidedResult r;
    r.target_max.assign(n, 0.0);
    r.target_exact.assign(n, 0);
    std::vector<double> value_sq(n, -1.0);  // exact max of d^2 per target (world units), -1: not solved
    std::vector<Vec3> where(n);
    std::vector<double> slack(n, 0.0);

    auto solve = [&](uint32_t t, double stop_below) {
        TargetSolver ts(grid, side, t);
        if (stop_below >= 0) ts.stop_below(stop_below);
        ts.run();
        if (ts.stopped_early()) {
            r.target_max[t] = std::sqrt(ts.max_sq());
            return -1.0;
        }
        value_sq[t] = ts.max_sq();
        where[t] = ts.max_point();
        slack[t] = ts.slack();
        r.target_max[t] = std::sqrt(ts.max_sq());
        r.target_exact[t] = 1;
        return ts.max_sq();
    };

    if (opt.mode == Mode::Paper) {
        Progress prog{opt, n};
        parallel_for(n, threads, opt.cancel, [&](size_t t) { solve((uint32_t)t, -1); prog.tick(); });
    } else {
        // Lower bound: the farthest used vertex of A; and for each vertex its nearest triangle of B.
        const size_t nv = A.positions.size();
        std::vector<char> used(nv, 0);
        for (const Tri& f : A.triangles)
            for (uint32_t i : f) used[i] = 1;
        std::vector<uint32_t> nearest_tri(nv, UINT32_MAX);
        std::vector<double> nearest_d2(nv, 0);
        parallel_for(nv, threads, opt.cancel, [&](size_t v) {
            if (!used[v]) return;
            VoxelGrid::Nearest q = grid.nearest(1 - side, A.positions[v]);
            nearest_tri[v] = q.triangle;
            nearest_d2[v] = q.dist2;
        });
        std::atomic<double> L{0.0};
        for (size_t v = 0; v < nv; ++v)
            if (used[v]) atomic_max(L, nearest_d2[v]);
        // Upper bound per target, over its four midpoint sub-triangles S: for any triangle T of B,
        // max over S of d(., T) is at a corner of S (convexity), so
        //   U = max_S min_{T near S} max_{corners v of S} |v - T|^2  >=  max over T' of d^2.
        std::vector<double> U(n, HUGE_VAL);
        parallel_for(n, threads, opt.cancel, [&](size_t t) {
            auto c = A.corners(t);
            const Tri& f = A.triangles[t];
            Vec3 p[6] = {c[0], c[1], c[2], 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0])};
            // Any set of triangles gives a bound; the corners' nearest ones need no new query
            // (a query far from B is the expensive part when the meshes are far apart).
            const uint32_t near[3] = {nearest_tri[f[0]], nearest_tri[f[1]], nearest_tri[f[2]]};
            static const int sub[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
            double u = 0;
            for (const auto& S : sub) {
                double best = HUGE_VAL;
                for (uint32_t cand : near) {
                    if (cand == UINT32_MAX) continue;
                    auto sc = B.corners(cand);
                    double m = 0;
                    for (int j : S) m = std::max(m, closest_point_on_triangle(p[j], sc[0], sc[1], sc[2]).dist2);
                    best = std::min(best, m);
                }
                u = std::max(u, best);
            }
            U[t] = u;
        });
        std::vector<uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return U[x] > U[y]; });
        const double tie_abs = 1e-11 * (coordinate_magnitude(A, B) + 1);
        Progress prog{opt, n};
        parallel_for(n, threads, opt.cancel, [&](size_t k) {
            uint32_t t = order[k];
            // With a margin far above rounding (relative, and absolute for coordinates far from
            // the origin): a target whose maximum could equal the result (a tie, or the same value
            // computed another way) is always solved exactly.
            double lr = std::max(0.0, std::sqrt(L.load()) * (1 - kTieMargin) - tie_abs);
            double l = lr * lr;
            if (U[t] < l) {
                r.target_max[t] = std::sqrt(U[t]);
            } else {
                double v = solve(t, l);
                if (v >= 0) atomic_max(L, v);
            }
            prog.tick();
        });
    }
    r.cancelled = opt.cancel && opt.cancel->load();
    if (opt.mode == Mode::Fast && !r.cancelled && n > 0 &&
        std::none_of(value_sq.begin(), value_sq.end(), [](double v) { return v >= 0; })) {
        // Safety net (never expected): solve exactly in decreasing order of the upper bound until
        // the bound falls below the best exact value.
        std::vector<uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return r.target_max[x] > r.target_max[y]; });
        double best_exact = -1;
        for (uint32_t t : order) {
            if (r.target_max[t] * r.target_max[t] < best_exact) break;
            best_exact = std::max(best_exact, solve(t, -1));
        }
    }

    // The witness: the largest exact value, the lowest index among equals.
    double best = -1;
    for (size_t t = 0; t < n; ++t) {
        if (value_sq[t] > best) { best = value_sq[t]; r.target = (uint32_t)t; }
        r.exact_targets += r.target_exact[t];
    }
    if (best >= 0) {
        r.distance = std::sqrt(best);
        r.from_point = where[r.target];
        // lower: the true distance from the witness point to B, by exact point-triangle distances
        // over the whole of B, independently of the domain meshes.
        VoxelGrid::Nearest q = grid.nearest(1 - side, r.from_point);
        r.to_point = q.point;
        r.lower = std::min(r.distance, std::sqrt(q.dist2));
        // upper: the domain meshes' maximum, widened by a bound on the rounding of coordinates.
        Box3 box = A.bounds();
        box.add(B.bounds());
        double coord = coordinate_magnitude(A, B);
        r.upper = r.distance;
        for (size_t t = 0; t < n; ++t)  // a sliver target's value may be short by its height
            if (slack[t] > 0 && value_sq[t] >= 0) r.upper = std::max(r.upper, std::sqrt(value_sq[t]) + slack[t]);
        r.upper += 1e-13 * (coord + box.diagonal()) + 1e-12 * r.distance;
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

HausdorffResult hausdorff(const TriangleMesh& A, const TriangleMesh& B, const HausdorffOptions& opt, bool one_sided_only) {
    auto t0 = Clock::now();
    VoxelGrid grid(A, B);
    HausdorffResult r;
    r.a_to_b = one_sided(grid, 0, opt);
    if (!one_sided_only) {
        r.b_to_a = one_sided(grid, 1, opt);
        r.hausdorff = std::max(r.a_to_b.distance, r.b_to_a.distance);
    } else {
        r.hausdorff = r.a_to_b.distance;
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

}  // namespace hlens
