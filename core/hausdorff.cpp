// Straub 2007, Algorithm 1 (the loop over targets; fast mode's culling is in cascade.cpp) and the
// certified interval (design notes, "Certified answer").
#include "hausdorff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <mutex>
#include <numeric>
#include <thread>

#include "cascade.h"
#include "parallel.h"
#include "point_triangle.h"
#include "target_solver.h"

namespace hlens {

const char* mode_name(Mode m) { return m == Mode::Paper ? "paper" : "fast"; }

namespace {

using Clock = std::chrono::steady_clock;

std::string format_g17(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The distance from the point origin + offset to the mesh of `grid`, computed without forming
// that point: each triangle is taken relative to `origin` (an input point), so the result is off
// by rounding relative to the distances involved, not to the coordinates' magnitude (which would
// be an ulp of 1e6 for a mesh of size 1 far from the origin). The grid's nearest point to the
// rounded sum bounds which triangles can be nearest; `to_point` is the nearest point.
double witness_distance(const MeshGrid& grid, const Vec3& origin, const Vec3& offset, Vec3& to_point) {
    const TriangleMesh& B = grid.mesh();
    const Vec3 p = origin + offset;
    const MeshGrid::Nearest q = grid.nearest(p);
    to_point = q.point;
    if (q.triangle == UINT32_MAX) return HUGE_VAL;
    // |p - (origin + offset)| <= half an ulp per axis; triangles farther than d0 + 2 eps from p
    // are farther from the exact point than the one found.
    const double eps = 0x1p-53 * (std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z)) * (1 + 1e-9);
    const double reach = (std::sqrt(q.dist2) + 3 * eps) * (1 + 1e-12);
    double best = HUGE_VAL;
    for (size_t t = 0; t < B.num_triangles(); ++t) {
        const auto c = B.corners(t);
        if (point_box_distance2(p, vmin(c[0], vmin(c[1], c[2])), vmax(c[0], vmax(c[1], c[2]))) > reach * reach) continue;
        best = std::min(best, closest_point_on_triangle(offset, c[0] - origin, c[1] - origin, c[2] - origin).dist2);
    }
    return std::sqrt(best);
}

// Paper mode, Algorithm 1: every target gets the full construction.
void paper_targets(const VoxelGrid& grid, int side, const HausdorffOptions& opt, TargetTable& out) {
    const size_t n = grid.mesh(side).num_triangles();
    const int threads = resolve_threads(opt.threads);
    out.resize(n);
    out.vertex_sq = farthest_vertex_sq(grid, side, threads, opt.cancel);
    ProgressTicker prog(opt.progress, n);
    std::atomic<size_t> solves{0};
    parallel_for(n, threads, opt.cancel, [&](size_t t) {
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

OneSidedResult one_sided(const VoxelGrid& grid, int side, const HausdorffOptions& opt) {
    auto t0 = Clock::now();
    const TriangleMesh& A = grid.mesh(side);
    const TriangleMesh& B = grid.mesh(1 - side);
    const size_t n = A.num_triangles();
    TargetTable tab;
    if (opt.mode == Mode::Paper) paper_targets(grid, side, opt, tab);
    else cascade_targets(grid, side, opt, tab);
    OneSidedResult r;
    r.cancelled = opt.cancel && opt.cancel->load();
    if (!r.cancelled && n > 0 && std::none_of(tab.value_sq.begin(), tab.value_sq.end(), [](double v) { return v >= 0; }))
        solve_in_bound_order(grid, side, tab);

    // The witness: the largest exact value, the lowest index among equals.
    double best = -1;
    for (size_t t = 0; t < n; ++t) {
        if (tab.value_sq[t] > best) { best = tab.value_sq[t]; r.target = (uint32_t)t; }
        r.exact_targets += tab.exact[t];
    }
    r.exact_solves = tab.solves;
    if (best >= 0) {
        r.distance = std::sqrt(best);
        // The witness in world coordinates, as TargetSolver::max_point() gives it, and its offset
        // from the target's frame origin (a corner of the target, an input point).
        const TargetFrame frame = TargetFrame::make(A.corners(r.target));
        const Vec2 w = tab.where[r.target];
        r.from_point = frame.to_world(w);
        const Vec3 offset = (w.x * frame.scale) * frame.e1 + (w.y * frame.scale) * frame.e2;
        Box3 box = A.bounds();
        box.add(B.bounds());
        // lower: the true distance from the witness to B, by exact point-triangle distances over
        // the whole of B, independently of the domain meshes, less their rounding (relative to
        // the distances: the witness is never formed in world coordinates, see witness_distance).
        Vec3 to_point;
        const double d_witness = witness_distance(grid.of(1 - side), frame.origin, offset, to_point);
        r.to_point = to_point;
        // (A sliver target's witness may lie off the sliver by up to its height, its slack.)
        r.lower = std::max(0.0, std::min(r.distance, d_witness - tab.slack[r.target] - 16 * 0x1p-52 * (box.diagonal() + d_witness)));
        // upper: the domain meshes' maximum, widened by a bound on the rounding of coordinates.
        double coord = coordinate_magnitude(A, B);
        r.upper = std::max(r.distance, tab.piece_upper);
        for (size_t t = 0; t < n; ++t)  // a sliver target's value may be short by its height
            if (tab.slack[t] > 0 && tab.value_sq[t] >= 0) r.upper = std::max(r.upper, std::sqrt(tab.value_sq[t]) + tab.slack[t]);
        r.upper += 1e-13 * (coord + box.diagonal()) + 1e-12 * r.distance;
        // A one-sided distance is never below its farthest vertex's distance.
        if (!r.cancelled && !(r.upper >= std::sqrt(tab.vertex_sq)))
            throw std::logic_error("internal error: one-sided distance " + format_g17(r.distance) + " (upper " +
                                   format_g17(r.upper) + ") is below the farthest vertex distance " +
                                   format_g17(std::sqrt(tab.vertex_sq)) + " (" + mode_name(opt.mode) + " mode)");
    }
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
