// Fast mode: cull targets and parts of targets by cascading bounds, solve exactly only where the
// maximum can be (design notes, "Beyond the paper: exact and fast"; the bounds are those of the
// bounded-error tools, Tang et al. 2009 and Sacht & Jacobson 2024, used here only to decide where
// the exact construction of Straub 2007 §3 must run).
#pragma once
#include <cstdint>
#include <vector>

#include "hausdorff.h"
#include "target_solver.h"
#include "voxel_grid.h"

namespace hlens {

// What the per-target loop found, per target of the measured mesh (world units).
struct TargetTable {
    std::vector<double> value_sq;   // exact max of d^2 over the target, -1 where not solved whole
    std::vector<Vec2> where;        // where value_sq is attained, in the target's frame (TargetSolver's)
    std::vector<double> slack;      // sliver targets: how far the true maximum may lie above (both
                                    // modes: fast mode sets it also for targets not solved whole)
    std::vector<double> bound;      // max distance over the target: exact, or an upper bound
    std::vector<uint8_t> exact;     // bound[t] is the exact maximum
    std::vector<uint8_t> copy;      // a copy of a source triangle (copies.h): 0 everywhere, exactly
    double piece_upper = 0;         // max over solved pieces of sqrt(value) + slack (a cancelled run's upper end)
    double vertex_sq = 0;           // the farthest used vertex's squared distance (a lower bound)
    size_t solves = 0;              // exact constructions run (whole targets and pieces)
    void resize(size_t n);
    void record(uint32_t t, const TargetSolver& whole);  // target t solved whole
    void record(uint32_t t, double max_sq, Vec2 at, double sliver_slack);  // the same from its values
};

// Fills `out` for mesh `side` of the grid measured against the other mesh. Every target whose
// exact maximum can equal the result (within a tie margin far above rounding of the largest exact
// value, and of the lower bound L the cascade reached) is solved whole, exactly as paper mode
// solves it, so the result, its witness and the targets tied with it are paper mode's.
void cascade_targets(const VoxelGrid& grid, int side, const HausdorffOptions& opt, TargetTable& out);

// The farthest used vertex of mesh `side` from the other mesh (squared), and for each vertex its
// nearest triangle there (UINT32_MAX for unused vertices) and squared distance (0 if unused).
double farthest_vertex_sq(const VoxelGrid& grid, int side, int threads, const std::atomic<bool>* cancel,
                          std::vector<uint32_t>* nearest_triangle = nullptr, std::vector<double>* nearest_d2 = nullptr);

// The largest coordinate magnitude of either mesh: rounding of positions scales with it.
double coordinate_magnitude(const TriangleMesh& A, const TriangleMesh& B);

// The margin below the lower bound within which a target is treated as a possible tie: relative
// (far above rounding of distances) and absolute (rounding of coordinates of magnitude `coord`).
double tie_threshold_sq(double lower_sq, double coord);

}  // namespace hlens
