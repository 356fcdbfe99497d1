// "Export case": a target triangle and the source triangles relevant to it, as two meshes that
// reproduce the target's construction on their own (for bug reports and the debugger's menu).
#pragma once
#include <string>

#include "mesh.h"
#include "voxel_grid.h"

namespace hlens {

struct ExportedCase {
    TriangleMesh target;   // one triangle
    TriangleMesh sources;  // the sources the construction inserted, in insertion order
};

// Sources it never inserted lay beyond the search radius, so they cannot change d^2 over the
// target: the pair has the same maximum over the target as the whole meshes.
ExportedCase export_case(const VoxelGrid& grid, int side, uint32_t target);
void export_case(const VoxelGrid& grid, int side, uint32_t target, const std::string& target_obj, const std::string& sources_obj);

}  // namespace hlens
