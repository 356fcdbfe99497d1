// Straub 2007, Algorithm 1: the loop over targets (paper mode here; fast mode's culling is in
// cascade.cpp), then the certified interval (certificate.cpp; design notes, "Certified answer").
#include "hausdorff.h"

#include <algorithm>
#include <chrono>
#include <atomic>
#include <cmath>
#include <numeric>

#include "cascade.h"
#include "certificate.h"
#include "copies.h"
#include "parallel.h"
#include "target_solver.h"

namespace hlens {

const char* mode_name(Mode m) { return m == Mode::Paper ? "paper" : "fast"; }

namespace {

using Clock = std::chrono::steady_clock;

// Paper mode, Algorithm 1: every target gets the full construction (a copy of a source triangle
// needs none: copies.h).
void paper_targets(const VoxelGrid& grid, int side, const HausdorffOptions& opt, TargetTable& out) {
    const size_t n = grid.mesh(side).num_triangles();
    const int threads = resolve_threads(opt.threads);
    out.resize(n);
    std::vector<double> vertex_d2;
    out.vertex_sq = farthest_vertex_sq(grid, side, threads, opt.cancel, nullptr, &vertex_d2);
    out.copy = copied_targets(grid, side, vertex_d2);
    ProgressTicker prog(opt.progress, n);
    std::atomic<size_t> solves{0};
    parallel_for(n, threads, opt.cancel, [&](size_t t) {
        if (out.copy[t]) {  // d = 0 on it, exactly (TargetSolver's values for it, with no search)
            out.record((uint32_t)t, 0.0, Vec2{0, 0}, 0.0);
            prog.tick();
            return;
        }
        TargetSolver ts(grid, side, (uint32_t)t);
        ts.run();
        out.record((uint32_t)t, ts);
        ++solves;
        prog.tick();
    });
    out.solves = solves;
}

// Safety net (never expected): if no target was solved whole, solve in decreasing order of the
// bound until the bound falls below the best exact value.
void solve_in_bound_order(const VoxelGrid& grid, int side, TargetTable& out) {
    std::vector<uint32_t> order(out.bound.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return out.bound[x] > out.bound[y]; });
    double best_exact = -1;
    for (uint32_t t : order) {
        if (out.bound[t] * out.bound[t] < best_exact) break;
        TargetSolver ts(grid, side, t);
        ts.run();
        out.record(t, ts);
        ++out.solves;
        best_exact = std::max(best_exact, ts.max_sq());
    }
}

}  // namespace

// Run the targets (paper or fast mode), then certify the result (certificate.h).
OneSidedResult one_sided(const VoxelGrid& grid, int side, const HausdorffOptions& opt) {
    auto t0 = Clock::now();
    const size_t n = grid.mesh(side).num_triangles();
    TargetTable tab;
    if (opt.mode == Mode::Paper) paper_targets(grid, side, opt, tab);
    else cascade_targets(grid, side, opt, tab);
    OneSidedResult r;
    r.cancelled = opt.cancel && opt.cancel->load();
    if (!r.cancelled && n > 0 && std::none_of(tab.value_sq.begin(), tab.value_sq.end(), [](double v) { return v >= 0; }))
        solve_in_bound_order(grid, side, tab);
    certify(grid, side, tab, opt.mode, r);
    // The witness's target holds the result, also where the certificate found it farther than
    // the target's domain mesh did (confirm_top.cpp).
    if (r.target < tab.bound.size() && r.distance > tab.bound[r.target]) tab.bound[r.target] = r.distance;
    r.target_max = std::move(tab.bound);
    r.target_exact = std::move(tab.exact);
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

HausdorffResult hausdorff(const TriangleMesh& A, const TriangleMesh& B, const HausdorffOptions& opt, bool one_sided_only) {
    auto t0 = Clock::now();
    const VoxelGrid grid(A, B, 1.0, opt.threads);
    HausdorffResult r = hausdorff(grid, opt, one_sided_only);
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

HausdorffResult hausdorff(const VoxelGrid& grid, const HausdorffOptions& opt, bool one_sided_only) {
    auto t0 = Clock::now();
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
