// The exact maximum distance over every target triangle of one mesh: Straub 2007, Algorithm 1
// (M. Straub, "Exact computation of the Hausdorff distance between triangular meshes",
// Eurographics 2007 short papers), run to the end for each target T' -- the full construction of
// target_solver.h, never stopped early -- and kept per target instead of reduced to the largest.
//
// This is what the debugger's error colour map needs: hausdorff()'s fast mode knows the one-sided
// distance after solving only the few targets that can reach it, and has only upper bounds for the
// others (OneSidedResult::target_max where !target_exact). exact_target_maxima() fills in the rest,
// in parallel, cancellable, reporting each target as soon as it is known, in a given order (e.g.
// decreasing upper bound, so the targets that matter most come first).
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "voxel_grid.h"

namespace hlens {

struct TargetMaximaOptions {
    int threads = 0;                                  // 0: all cores
    const std::atomic<bool>* cancel = nullptr;        // set to true to stop (targets in progress finish)
    std::function<void(double fraction)> progress;    // from worker threads, at most every 100 ms
    // Called from the worker thread that solved `target`, as soon as its maximum is known
    // (max_distance = sqrt of TargetSolver::max_sq(), the value hausdorff() reports for it).
    std::function<void(uint32_t target, double max_distance)> on_target;
    // The targets to solve, in this order (each at most once; out-of-range indices are an error).
    // Empty: every target, 0 .. n-1.
    std::vector<uint32_t> order;
};

struct TargetMaxima {
    // Per target of the measured mesh: the exact maximum distance over it; -1 where it was not
    // solved (not in `order`, or cancelled before its turn).
    std::vector<double> max;
    size_t solved = 0;          // targets solved
    bool cancelled = false;     // the cancel flag was set before every target in `order` was solved
};

// The exact maximum of the distance to mesh 1 - side over each target triangle of mesh `side` of
// the grid (0 = a, 1 = b). The values do not depend on the thread count or the order.
TargetMaxima exact_target_maxima(const VoxelGrid& grid, int side, const TargetMaximaOptions& opt = {});

// The targets t with !skip[t] (skip may be empty: none skipped), by decreasing bound[t], ties by
// increasing index: e.g. fast mode's target_max and target_exact, so the targets whose value may
// be largest are solved first and those already exact are left out.
std::vector<uint32_t> order_by_decreasing_bound(const std::vector<double>& bound, const std::vector<uint8_t>& skip = {});

}  // namespace hlens
