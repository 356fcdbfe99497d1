// Exact surface statistics of the distance from one mesh to the other: area, mean, RMS, the area
// above a tolerance, area-weighted percentiles and a histogram, per mesh and per triangle.
//
// Issue 9, after Straub 2007 §5 ("future work": the mean squared distance as the integral of d^2
// over the domains). Every target T' of the measured mesh gets the paper's full construction
// (target_solver.h, never stopped early, as target_maxima.h runs it), and its finished domain
// mesh is integrated (integrals.h); a copy of a source triangle (copies.h) needs none: d = 0 on it. Percentiles are found by bisection on the exact area above t,
// each bracketed by 0 and the maximum at first: the first pass also estimates the distribution
// (each domain's mean and variance of d as a uniform law over its range), which gives the first
// guess; each further pass clips the targets whose distance range holds one of a few levels
// around each guess (then the regula falsi point of the bracket: Bracket in the .cpp), until every
// bracket is narrower than 1e-9 of the bounding-box diagonal. The estimate only says where to look:
// every bracket is certified by the exact areas at its ends. The first pass keeps the finished
// domain meshes, compacted (DomainMesh::compact), up to a memory budget (about 1 GB); the passes
// rebuild only the others. The area above a level is integrated without splitting a domain
// (level_area.cpp).
//
// Sliver targets (height below 1e-7 of their longest edge, handled as their edges by the solver)
// have no domain mesh: they are left out of the integrals and reported (sliver_targets,
// sliver_area), their area being at most 1e-7 of their longest edge squared.
#pragma once
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "voxel_grid.h"

namespace hlens {

struct StatsOptions {
    int threads = 0;                                   // 0: all cores
    std::vector<double> percentiles{50, 90, 95, 99};   // in [0, 100]
    int histogram_bins = 0;                            // 0: no histogram
    double histogram_max = -1;                         // upper edge; < 0: the largest distance
    double tolerance = -1;                             // < 0: none
    double known_max = -1;                             // the one-sided distance if known (else found first)
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double fraction)> progress;
};

struct TriangleStats {              // world units; all 0 for a sliver target
    double area = 0, int_d = 0, int_d2 = 0;
    double max = 0;                 // the exact maximum distance over the triangle
    double mean() const { return area > 0 ? int_d / area : 0; }
    double rms() const { return area > 0 ? std::sqrt(int_d2 / area) : 0; }
};

struct SurfaceStats {
    double area = 0, int_d = 0, int_d2 = 0;           // world units
    double err_area = 0, err_d2 = 0;                  // certified quadrature bounds (rounding aside)
    double err_d = 0;                                 // a-posteriori estimate (Gauss-Kronrod)
    double max = 0;                                   // the one-sided distance (largest target maximum)
    double mean() const { return area > 0 ? int_d / area : 0; }
    double rms() const { return area > 0 ? std::sqrt(int_d2 / area) : 0; }
    std::vector<double> percentiles;                  // the distance below which p% of the area lies
    std::vector<double> histogram_edges, histogram_area;
    double area_above = 0, fraction_above = 0;        // with a tolerance: where d > tolerance
    std::vector<TriangleStats> triangles;             // per triangle of the measured mesh
    std::vector<double> vertex_distance;              // per vertex (-1: used by no triangle)
    size_t sliver_targets = 0;
    double sliver_area = 0;
    double percentile_tolerance = 0;                  // bisection stops at this width (1e-9 diag)
    size_t rerun_targets = 0;                         // targets re-run for the percentiles (all passes)
    int percentile_passes = 0;                        // passes over the targets after the first
    double seconds_first_pass = 0, seconds_percentiles = 0;
    bool cancelled = false;
};

// Statistics of the distance from mesh `side` of the grid (0 = a, 1 = b) to the other.
SurfaceStats surface_stats(const VoxelGrid& grid, int side, const StatsOptions& opt = {});

}  // namespace hlens
