#include "case_export.h"

#include "mesh_io.h"
#include "target_solver.h"

namespace hlens {

ExportedCase export_case(const VoxelGrid& grid, int side, uint32_t target) {
    TargetSolver ts(grid, side, target);
    ts.run();
    ExportedCase c;
    auto t = grid.mesh(side).corners(target);
    c.target = make_mesh({t[0], t[1], t[2]}, {{0, 1, 2}}, "target " + std::to_string(target));
    std::vector<Vec3> p;
    std::vector<Tri> f;
    for (uint32_t s : ts.inserted_sources()) {
        auto sc = ts.source_corners(s);
        uint32_t base = (uint32_t)p.size();
        p.insert(p.end(), sc.begin(), sc.end());
        f.push_back({base, base + 1, base + 2});
    }
    c.sources = make_mesh(p, f, "sources of target " + std::to_string(target));
    return c;
}

void export_case(const VoxelGrid& grid, int side, uint32_t target, const std::string& target_obj, const std::string& sources_obj) {
    ExportedCase c = export_case(grid, side, target);
    save_obj(c.target, target_obj);
    save_obj(c.sources, sources_obj);
}

}  // namespace hlens
