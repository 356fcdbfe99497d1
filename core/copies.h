// Targets that are copies of source triangles (beyond the paper: a shortcut with no rounding).
// A triangle of the measured mesh whose three corners are, in any order, those of a triangle of
// the other mesh lies in that triangle: d = 0 on all of it, exactly, whatever any other source
// does. A mesh against itself, a re-export, the untouched part of a local edit or a simplification
// that keeps some faces: no construction is needed there.
#pragma once
#include <cstdint>
#include <vector>

#include "voxel_grid.h"

namespace hlens {

// Whether two triangles have the same three corners (equal coordinates), in any order.
bool same_corners(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

// For each target of mesh `side` of the grid, whether the other mesh has a triangle with the
// same three corners (equal coordinates). Only targets whose corners all lie at distance 0 from
// the other mesh can be copies: those whose corners' squared distances `vertex_d2` (per vertex,
// as farthest_vertex_sq gives them) are within rounding of 0 are looked up, and where there is
// none the other mesh is not read at all. (A vertex comes out at 1e-39 from a mesh that has it
// where its nearest triangle is not one of its own: camelhead, 32 targets in 22,704.) The match
// itself is exact.
std::vector<uint8_t> copied_targets(const VoxelGrid& grid, int side, const std::vector<double>& vertex_d2);

}  // namespace hlens
