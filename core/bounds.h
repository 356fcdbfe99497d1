// Independent bounds on the one-sided distance h(A,B) = max_{p in A} min_{q in B} |p-q|, used as test
// oracles and by --verify. Built only on closest_point_on_triangle and the voxel grid.
// B is always grid.mesh(1 - sideA); A is normally grid.mesh(sideA) but may be any mesh.
#pragma once
#include <cstdint>

#include "mesh.h"
#include "voxel_grid.h"

namespace hlens {

// Lower bound: max over samples of A (each triangle's barycentric grid of (n+1)(n+2)/2 points, corners
// included) of the exact distance to B. value = 0 if A is empty, +inf if B is empty.
struct SampledBound {
    double value;
    Vec3 point;         // the sample achieving it
    uint32_t triangle;  // triangle of A holding `point` (UINT32_MAX if A is empty)
};
SampledBound sampled_lower_bound(const TriangleMesh& A, const VoxelGrid& grid, int sideA, int n_per_edge);

// Bounds by subdivision of A's triangles: h lies in [lower, upper], upper - lower <= abs_tol (plus a
// rounding allowance of ~1e-14 of the coordinates). On a piece with enclosing ball (c, r), d <= d(c) + r
// (d(., B) is 1-Lipschitz) and d <= max over the piece's corners of d(., T) for the triangle T nearest
// to c (d(., T) is convex). Pieces that cannot exceed the best distance found so far are dropped,
// the others split 4-way until r <= abs_tol.
struct LipschitzBound {
    double lower, upper;
    Vec3 witness;       // a point of A at distance `lower` from B
    uint32_t triangle;  // triangle of A holding it (UINT32_MAX if A is empty)
};
LipschitzBound lipschitz_bounds(const TriangleMesh& A, const VoxelGrid& grid, int sideA, double abs_tol);

}  // namespace hlens
