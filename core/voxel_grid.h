// The voxel grid of Straub 2007 §3.2: each voxel lists the triangles of each mesh that touch it.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mesh.h"

namespace hlens {

// Conservative triangle/box overlap (Akenine-Moeller separating axes). Every axis is tested with the
// projections of all three corners, so a degenerate triangle (zero normal or zero edges) is never
// rejected by a zero axis and a sliver's inaccurate normal is still a valid separating axis.
bool triangle_box_overlap(const Vec3& box_center, const Vec3& box_half, const Vec3& a, const Vec3& b,
                          const Vec3& c);

class VoxelGrid {
public:
    // Grid over the bounding box of a ∪ b (used vertices only). Cubic voxels of edge s from Straub's
    // k = s^2 (n+m) / (2(lw+lh+wh)); at most about 8(n+m)+64 voxels. The grid keeps pointers to a and b:
    // they must outlive it.
    VoxelGrid(const TriangleMesh& a, const TriangleMesh& b, double triangles_per_voxel = 1.0);

    int nx = 1, ny = 1, nz = 1;
    double voxel_size = 1;
    Vec3 origin;

    size_t num_voxels() const { return size_t(nx) * ny * nz; }
    size_t index(int i, int j, int k) const { return (size_t(k) * ny + j) * nx + i; }
    std::array<int, 3> coords(size_t index) const;
    Box3 voxel_box(size_t index) const;
    // Voxel containing p, clamped to the grid (so points outside get the nearest boundary voxel).
    std::array<int, 3> locate(const Vec3& p) const;
    // Box enlargement used for assignment: 1e-9 of the voxel size, plus rounding of large coordinates.
    double margin() const { return margin_; }

    // Triangles of mesh `side` (0 = a, 1 = b) touching voxel `index`, in increasing order. Conservative:
    // a triangle is listed wherever it comes within margin() of the voxel's box.
    const uint32_t* begin(int side, size_t index) const { return items_[side].data() + offs_[side][index]; }
    const uint32_t* end(int side, size_t index) const { return items_[side].data() + offs_[side][index + 1]; }
    size_t num_assignments(int side) const { return items_[side].size(); }

    // Voxels that triangle t of mesh `side` touches (same test as the lists above), increasing.
    std::vector<size_t> voxels_of_triangle(int side, uint32_t t) const;
    // The same for any triangle (e.g. a piece of one).
    std::vector<size_t> voxels_of_triangle(const std::array<Vec3, 3>& corners) const;

    struct Nearest {
        uint32_t triangle;  // UINT32_MAX when mesh `side` has no triangles
        Vec3 point;
        double dist2;       // +inf when mesh `side` has no triangles
    };
    // Nearest point of mesh `side` to p (any p, inside the grid box or not). `hint` is an optional
    // triangle of that mesh likely to be near p: it only speeds the search up.
    // Searches voxel shells outward from p's voxel; if a few shells do not settle it (p far from the
    // mesh), it continues best-first over an occupancy pyramid, so far queries do not scan O((d/s)^3)
    // empty voxels. Ties go to the lowest triangle index. Safe to call from several threads.
    Nearest nearest(int side, const Vec3& p, uint32_t hint = UINT32_MAX) const;

    const TriangleMesh& mesh(int side) const { return *mesh_[side]; }

private:
    template <class F> void for_each_voxel_of(int side, uint32_t t, F&& f) const;
    template <class F> void for_each_voxel_of(const std::array<Vec3, 3>& corners, F&& f) const;
    const TriangleMesh* mesh_[2];
    double margin_ = 0;
    std::vector<size_t> offs_[2];      // CSR: list of voxel v is items_[offs_[v] .. offs_[v+1])
    std::vector<uint32_t> items_[2];
    struct FloatBox { float lo[3], hi[3]; };
    std::vector<FloatBox> boxes_[2];   // beside items_: the listed triangle's box, rounded outward
    // Occupancy pyramid: level 0 is the grid, level l+1 halves each dimension (rounding up); a cell
    // is set if any voxel below it lists a triangle of that side.
    struct Level { int nx, ny, nz; std::vector<uint8_t> occ[2]; };
    std::vector<Level> pyramid_;
};

}  // namespace hlens
