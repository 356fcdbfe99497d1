// The certified interval of a one-sided distance (design notes, "Certified answer"): from the
// per-target table the loop over targets filled (Straub 2007, Algorithm 1, paper or fast mode),
// the witness (the largest exact value), the lower end (the witness's true distance to the other
// mesh, by exact point-triangle distances, less its rounding) and the upper end (the domain
// meshes' maximum, widened by a bound on the rounding of coordinates).
#pragma once
#include "hausdorff.h"
#include "voxel_grid.h"

namespace hlens {

struct TargetTable;

// Fills r.distance, r.target, r.from_point, r.to_point, r.lower, r.upper, r.exact_targets and
// r.exact_solves from `tab` (mesh `side` of the grid measured against the other; r.cancelled
// already set). Throws std::logic_error if the upper end is below the farthest vertex's distance
// (never expected: it would be a bug of the construction).
void certify(const VoxelGrid& grid, int side, const TargetTable& tab, Mode mode, OneSidedResult& r);

// A certified lower bound of the distance from the point p, taken exactly as given (a vertex of
// mesh `side`), to the other mesh: as the interval's lower end is computed (each triangle's
// distance from below, less the rounding), so 0 where p lies on that mesh, whatever the rounding
// of a plain point-triangle distance (which puts a shared vertex some 1e-19 away).
double point_distance_lower(const VoxelGrid& grid, int side, const Vec3& p);

}  // namespace hlens
