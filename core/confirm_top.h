// The certified interval's upper end, checked independently of the domain meshes: a branch and
// bound over the targets whose value can reach the result (see confirm_top.cpp).
#pragma once
#include <array>
#include <cstdint>

#include "vec.h"
#include "voxel_grid.h"

namespace hlens {

struct TargetTable;

struct TopConfirmation {
    double upper = 0;          // the closed targets' bound: over them the distance is at most this
    double open_upper = -1;    // the open targets' bounds from their unfinished subdivisions; -1: none
    bool raised = false;       // a point farther than `best` was found: the witness below
    uint32_t target = 0;       // its target,
    Vec3 origin, offset;       // and the point origin + offset (origin: a corner of the target)
    double value = 0;          // its distance to the other mesh, as computed here
    size_t targets = 0, closed = 0, nodes = 0;  // targets looked at, closed, and sub-triangles
    size_t edge_nodes = 0;     // segments of the open targets' longest edges (edge_bound)
};

// Whether a target (its corners, its value or bound in the table, its slack) can reach `L` within
// its domain mesh's vertex error: the targets confirm_top looks at. Fast mode solves whole every
// target that can reach the result (cascade.cpp), so the set, and the confirmation, are paper mode's.
bool can_reach(const std::array<Vec3, 3>& corners, double bound, double slack, double L);

// `best`: the result the domain meshes give (the largest exact value). `tol`: a sub-triangle is
// done once its bound is within tol of the largest distance measured, or its radius below tol; a
// target is closed when all its sub-triangles are done within the node budget, else open.
// `coord`: the coordinates' magnitude (coordinate_magnitude), which says where a world point's
// rounding matters at `tol`.
TopConfirmation confirm_top(const VoxelGrid& grid, int side, const TargetTable& tab, double best, double tol, double coord);

// An upper bound of d(., g's mesh) over `target` (world corners): its longest edge's, by segments
// down to `tol` from `L`, plus its height over that edge (confirm_top bounds an open target so).
double longest_edge_bound(const MeshGrid& g, const std::array<Vec3, 3>& target, double L, double tol, double coord);

// A local search from the witness `point` (on target `target`, whose distance is `value`) for a
// farther point nearby (`tol`, `coord`: confirm_top's): a domain mesh's maximum at a corner of domains may
// sit ~1e-7 of the target's size off. True (and the point origin + offset, its distance
// `polished`) if one is farther by more than rounding.
bool polish_witness(const VoxelGrid& grid, int side, uint32_t target, const Vec3& point, double value, double tol,
                    double coord, Vec3& origin, Vec3& offset, double& polished);

}  // namespace hlens
