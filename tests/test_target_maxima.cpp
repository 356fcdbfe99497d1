// exact_target_maxima (core/target_maxima.h): the exact maximum distance over every target, what
// the debugger's colour map fills in. Checked against a TargetSolver run per target, hausdorff()
// in paper mode, fast mode's per-target upper bounds and the independent oracles of core/bounds.h
// (sampling lower bound and Lipschitz upper bound, per target); cancelling stops it.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include <hlens/bounds.h>
#include <hlens/hausdorff.h>
#include <hlens/target_maxima.h>
#include <hlens/target_solver.h>

#include "test_meshes.h"

using namespace hlens;
using namespace hlens_test;

namespace {

// A small random pair with shared edges on one side and a soup on the other.
void small_pair(unsigned seed, TriangleMesh& A, TriangleMesh& B) {
    std::mt19937 rng(seed);
    A = height_field(4, [&](double x, double y) { return 0.15 * std::sin(3 * x + seed) * std::cos(2 * y); });
    B = random_triangle_soup(rng, 14, 0.35, {0, 0, 0}, 0.9);
}

double solver_max(const VoxelGrid& grid, int side, uint32_t t) {
    TargetSolver ts(grid, side, t);
    ts.run();
    return std::sqrt(ts.max_sq());
}

}  // namespace

TEST(TargetMaxima, EqualsTheSolverOnEveryTargetAndHausdorffsDistance) {
    for (unsigned seed : {3u, 11u}) {
        TriangleMesh A, B;
        small_pair(seed, A, B);
        VoxelGrid grid(A, B);
        HausdorffOptions paper;
        paper.mode = Mode::Paper;
        HausdorffResult h = hausdorff(A, B, paper);
        for (int side = 0; side < 2; ++side) {
            const size_t n = grid.mesh(side).num_triangles();
            std::vector<double> got(n, -2);
            std::mutex m;
            TargetMaximaOptions opt;
            opt.threads = 2;
            opt.on_target = [&](uint32_t t, double d) {
                std::lock_guard<std::mutex> lock(m);
                EXPECT_EQ(got[t], -2) << "target " << t << " reported twice";
                got[t] = d;
            };
            TargetMaxima r = exact_target_maxima(grid, side, opt);
            ASSERT_EQ(r.max.size(), n);
            EXPECT_EQ(r.solved, n);
            EXPECT_FALSE(r.cancelled);
            for (uint32_t t = 0; t < n; ++t) {
                EXPECT_EQ(r.max[t], solver_max(grid, side, t)) << "side " << side << " target " << t;
                EXPECT_EQ(got[t], r.max[t]) << "on_target reports the value";
            }
            // The largest is the one-sided distance of paper mode, at its witness target.
            const OneSidedResult& os = side == 0 ? h.a_to_b : h.b_to_a;
            const auto top = std::max_element(r.max.begin(), r.max.end());
            EXPECT_DOUBLE_EQ(*top, os.distance);
            EXPECT_EQ((uint32_t)(top - r.max.begin()), os.target);
            // Paper mode's per-target values are these.
            for (uint32_t t = 0; t < n; ++t) EXPECT_DOUBLE_EQ(os.target_max[t], r.max[t]);
        }
    }
}

TEST(TargetMaxima, FastModeBoundsAreAboveAndItsExactTargetsEqual) {
    TriangleMesh A, B;
    small_pair(5, A, B);
    VoxelGrid grid(A, B);
    for (int side = 0; side < 2; ++side) {
        OneSidedResult fast = one_sided(grid, side);
        TargetMaxima r = exact_target_maxima(grid, side);
        size_t skipped = 0;
        for (size_t t = 0; t < r.max.size(); ++t) {
            if (fast.target_exact[t]) {
                EXPECT_DOUBLE_EQ(fast.target_max[t], r.max[t]) << t;
            } else {
                ++skipped;
                EXPECT_GE(fast.target_max[t], r.max[t] * (1 - 1e-12)) << "fast mode's bound of target " << t;
                EXPECT_LE(r.max[t], fast.distance * (1 + 1e-12));
            }
        }
        // (The fill-in only has something to do when fast mode skipped targets.)
        if (side == 0) {
            EXPECT_GT(skipped, 0u);
        }
    }
}

TEST(TargetMaxima, EachValueIsBetweenTheSamplingAndLipschitzBounds) {
    TriangleMesh A, B;
    small_pair(7, A, B);
    VoxelGrid grid(A, B);
    const double diag = std::max(A.bounds().diagonal(), B.bounds().diagonal());
    for (int side = 0; side < 2; ++side) {
        const TriangleMesh& M = grid.mesh(side);
        TargetMaxima r = exact_target_maxima(grid, side);
        for (uint32_t t = 0; t < M.num_triangles(); ++t) {
            // The bounds of the one-triangle mesh {t} against the other mesh of the grid.
            TriangleMesh one = mesh_of({M.positions[M.triangles[t][0]], M.positions[M.triangles[t][1]],
                                        M.positions[M.triangles[t][2]]},
                                       {{0, 1, 2}});
            SampledBound sb = sampled_lower_bound(one, grid, side, 10);
            LipschitzBound lb = lipschitz_bounds(one, grid, side, 1e-6 * diag);
            EXPECT_GE(r.max[t], sb.value - 1e-12 * diag) << "side " << side << " target " << t;
            EXPECT_GE(r.max[t], lb.lower - 1e-12 * diag) << "side " << side << " target " << t;
            EXPECT_LE(r.max[t], lb.upper + 1e-12 * diag) << "side " << side << " target " << t;
        }
    }
}

TEST(TargetMaxima, OrderAndThreadsDoNotChangeTheValues) {
    TriangleMesh A, B;
    small_pair(9, A, B);
    VoxelGrid grid(A, B);
    TargetMaximaOptions one;
    one.threads = 1;
    TargetMaxima ref = exact_target_maxima(grid, 0, one);
    std::vector<uint32_t> order(ref.max.size());
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(1));
    std::vector<uint32_t> seen;
    TargetMaximaOptions shuffled;
    shuffled.threads = 1;
    shuffled.order = order;
    shuffled.on_target = [&](uint32_t t, double) { seen.push_back(t); };
    TargetMaxima r = exact_target_maxima(grid, 0, shuffled);
    EXPECT_EQ(seen, order) << "one thread solves the targets in the order given";
    EXPECT_EQ(r.max, ref.max);
    // A partial order solves only those; the others stay -1.
    TargetMaximaOptions part;
    part.threads = 2;
    part.order = {order[0], order[1], order[2]};
    TargetMaxima p = exact_target_maxima(grid, 0, part);
    EXPECT_EQ(p.solved, 3u);
    EXPECT_FALSE(p.cancelled);
    for (uint32_t t = 0; t < p.max.size(); ++t) {
        const bool in = std::find(part.order.begin(), part.order.end(), t) != part.order.end();
        EXPECT_EQ(p.max[t], in ? ref.max[t] : -1.0) << t;
    }
    // Bad orders are refused.
    part.order = {0, 0};
    EXPECT_THROW(exact_target_maxima(grid, 0, part), std::invalid_argument);
    part.order = {(uint32_t)ref.max.size()};
    EXPECT_THROW(exact_target_maxima(grid, 0, part), std::invalid_argument);
}

TEST(TargetMaxima, CancelStopsIt) {
    TriangleMesh A, B;
    small_pair(13, A, B);
    VoxelGrid grid(A, B);
    TargetMaxima ref = exact_target_maxima(grid, 0);
    const size_t n = ref.max.size();
    ASSERT_GT(n, 10u);
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        std::atomic<size_t> calls{0};
        double last_fraction = -1;
        TargetMaximaOptions opt;
        opt.threads = threads;
        opt.cancel = &cancel;
        opt.progress = [&](double f) { last_fraction = f; };
        opt.on_target = [&](uint32_t, double) {
            if (++calls == 5) cancel = true;
        };
        TargetMaxima r = exact_target_maxima(grid, 0, opt);
        EXPECT_TRUE(r.cancelled);
        // Workers check the flag before taking a target: at most one more per other thread.
        EXPECT_GE(r.solved, 5u);
        EXPECT_LE(r.solved, 5u + (threads - 1));
        EXPECT_EQ(r.solved, calls.load());
        size_t known = 0;
        for (size_t t = 0; t < n; ++t)
            if (r.max[t] >= 0) {
                ++known;
                EXPECT_EQ(r.max[t], ref.max[t]) << t;
            }
        EXPECT_EQ(known, r.solved);
        EXPECT_LT(last_fraction, 1.0);
    }
    // Cancelled before it starts: nothing is solved.
    std::atomic<bool> cancel{true};
    TargetMaximaOptions opt;
    opt.cancel = &cancel;
    TargetMaxima r = exact_target_maxima(grid, 0, opt);
    EXPECT_EQ(r.solved, 0u);
    EXPECT_TRUE(r.cancelled);
    // Not cancelled: the progress callback ends at 1.
    double last = -1;
    TargetMaximaOptions full;
    full.progress = [&](double f) { last = f; };
    exact_target_maxima(grid, 0, full);
    EXPECT_EQ(last, 1.0);
}

TEST(TargetMaxima, OrderByDecreasingBound) {
    const std::vector<double> bound = {0.5, 2.0, 1.0, 2.0, 0.1};
    EXPECT_EQ(order_by_decreasing_bound(bound), (std::vector<uint32_t>{1, 3, 2, 0, 4}));
    EXPECT_EQ(order_by_decreasing_bound(bound, {0, 1, 0, 0, 1}), (std::vector<uint32_t>{3, 2, 0}));
    EXPECT_TRUE(order_by_decreasing_bound({}).empty());
}
