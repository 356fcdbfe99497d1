// An upper bound of the distance to a mesh over a triangle that nearly parallel triangles of the mesh
// cover when seen along its normal (confirm_top.cpp uses it where a piece lies over many sources:
// see cover_bound.cpp).
#pragma once
#include <array>

#include "vec.h"
#include "voxel_grid.h"

namespace hlens {

// An upper bound of d(o + x, mesh of g) over the triangle o + q (q relative to o, an input point),
// or HUGE_VAL: the triangles of the mesh listed in q's voxels whose own bound is at most `goal` are
// projected along q's normal; where their union covers q but for a strip of rounding along its
// edges, every point's line along the normal meets one of them, and the bound is the largest of
// their distances along the normal over the parts of q they cover, plus the strip's width.
// `slack` becomes the bound's rounding (it is not in the returned value). `whole`: the triangle q is
// a piece of (relative to o), whose normal is usually known better than q's: q is seen along it
// first, and along its own normal where that does not close it; then, where q is too thin for
// those normals or thinner than the goal, along a well-shaped source's normal, over a thin
// triangle on its longest edge, plus its height.
double cover_bound(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q, double goal, double& slack,
                   const std::array<Vec3, 3>* whole = nullptr);

}  // namespace hlens
