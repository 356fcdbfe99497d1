// The whole-mesh driver: one-sided distances h(A,B), h(B,A) and the symmetric Hausdorff distance.
//
// Straub 2007, Algorithm 1: the one-sided distance is the maximum over targets T' of A of the
// maximum of d^2 over T' (see target_solver.h). Two modes, which must agree:
//  - paper: every target gets the full construction;
//  - fast:  targets and parts of targets whose upper bound is below a rising lower bound are
//           dropped, the pieces left are solved exactly, and every target whose value can equal
//           the result is solved whole at the end (cascade.h), so the result, its witness and
//           the certified interval are paper mode's whatever the timing.
// Targets run on all cores; the result does not depend on the thread count.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh.h"
#include "voxel_grid.h"

namespace hlens {

enum class Mode { Paper, Fast };

struct HausdorffOptions {
    Mode mode = Mode::Fast;
    int threads = 0;                                  // 0: all cores
    std::function<void(double fraction)> progress;    // called from worker threads, throttled
    const std::atomic<bool>* cancel = nullptr;        // set to true to stop early (result invalid)
};

struct OneSidedResult {
    double distance = 0;          // h(from, to)
    double lower = 0, upper = 0;  // certified interval: lower <= h <= upper
    uint32_t target = 0;          // witness triangle of the measured mesh
    Vec3 from_point, to_point;    // witness point on the measured mesh, its nearest point on the other
    size_t exact_targets = 0;     // targets whose maximum was computed exactly
    size_t exact_solves = 0;      // exact constructions run (fast mode: whole targets and pieces)
    double seconds = 0;
    // Per target of the measured mesh: the maximum distance over it, exact where target_exact[i],
    // otherwise an upper bound that is below the result (fast mode skipped it).
    std::vector<double> target_max;
    std::vector<uint8_t> target_exact;
    bool cancelled = false;
};

// One-sided distance from mesh `from_side` of the grid (0 = a, 1 = b) to the other.
OneSidedResult one_sided(const VoxelGrid& grid, int from_side, const HausdorffOptions& opt = {});

struct HausdorffResult {
    OneSidedResult a_to_b, b_to_a;
    double hausdorff = 0;         // max of the two (only when both were computed)
    double seconds = 0;
};

// h(A,B) and, unless one_sided_only, h(B,A) and the symmetric distance.
HausdorffResult hausdorff(const TriangleMesh& A, const TriangleMesh& B, const HausdorffOptions& opt = {},
                          bool one_sided_only = false);
// The same on grids already built (A = grid.mesh(0), B = grid.mesh(1)); `seconds` excludes the grids.
HausdorffResult hausdorff(const VoxelGrid& grid, const HausdorffOptions& opt = {}, bool one_sided_only = false);

const char* mode_name(Mode m);

}  // namespace hlens
