// Straub 2007, Algorithm 1, per target: one full TargetSolver run for every target T' of the
// measured mesh (the paper's construction of max d^2 over T'), kept per target.
#include "target_maxima.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "parallel.h"
#include "target_solver.h"

namespace hlens {

TargetMaxima exact_target_maxima(const VoxelGrid& grid, int side, const TargetMaximaOptions& opt) {
    if (side != 0 && side != 1) throw std::invalid_argument("exact_target_maxima: side must be 0 or 1");
    const size_t n = grid.mesh(side).num_triangles();
    std::vector<uint32_t> all;
    const std::vector<uint32_t>* order = &opt.order;
    if (opt.order.empty()) {
        all.resize(n);
        std::iota(all.begin(), all.end(), 0u);
        order = &all;
    }
    std::vector<uint8_t> seen(n, 0);
    for (uint32_t t : *order) {
        if (t >= n)
            throw std::invalid_argument("exact_target_maxima: target " + std::to_string(t) + " is out of range (" +
                                        std::to_string(n) + " triangles)");
        if (seen[t]++) throw std::invalid_argument("exact_target_maxima: target " + std::to_string(t) + " is listed twice");
    }

    TargetMaxima r;
    r.max.assign(n, -1.0);
    std::atomic<size_t> solved{0};
    ProgressTicker prog(opt.progress, order->size());
    // Each target writes only its own slot of r.max, so no lock is needed.
    parallel_for(order->size(), resolve_threads(opt.threads), opt.cancel, [&](size_t i) {
        const uint32_t t = (*order)[i];
        TargetSolver ts(grid, side, t);
        ts.run();
        const double d = std::sqrt(ts.max_sq());
        r.max[t] = d;
        ++solved;
        if (opt.on_target) opt.on_target(t, d);
        prog.tick();
    });
    r.solved = solved.load();
    r.cancelled = r.solved < order->size();
    return r;
}

std::vector<uint32_t> order_by_decreasing_bound(const std::vector<double>& bound, const std::vector<uint8_t>& skip) {
    std::vector<uint32_t> order;
    order.reserve(bound.size());
    for (size_t t = 0; t < bound.size(); ++t)
        if (t >= skip.size() || !skip[t]) order.push_back((uint32_t)t);
    // NaN bounds (never expected) go last rather than breaking the ordering.
    auto key = [&](uint32_t t) { return std::isnan(bound[t]) ? -HUGE_VAL : bound[t]; };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return key(x) > key(y); });
    return order;
}

}  // namespace hlens
