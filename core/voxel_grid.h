// The voxel grid of Straub 2007 §3.2, one per mesh: each voxel lists the triangles that touch it.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "mesh.h"

namespace hlens {

// Conservative triangle/box overlap (Akenine-Moeller separating axes). Every axis is tested with the
// projections of all three corners, so a degenerate triangle (zero normal or zero edges) is never
// rejected by a zero axis and a sliver's inaccurate normal is still a valid separating axis.
bool triangle_box_overlap(const Vec3& box_center, const Vec3& box_half, const Vec3& a, const Vec3& b,
                          const Vec3& c);

// The voxel grid of one mesh (Straub 2007 §3.2's grid, built per mesh): each voxel lists the
// triangles of that mesh that touch it. The paper puts both meshes in one grid over the box of
// A ∪ B; a grid per mesh, over that mesh's own box, keeps the voxels as fine as the mesh when the
// two are far apart or of very different sizes (one grid over both would put a small mesh far from
// the other in one voxel, and every query would scan all of it). A query from outside the box
// (the other mesh's points) starts at the nearest boundary voxels.
class MeshGrid {
public:
    // Grid over the bounding box of m (used vertices only). Cubic voxels of edge s from Straub's
    // k = s^2 n / (2(lw+lh+wh)); at most about 8n+64 voxels. Keeps a pointer to m: m must outlive it.
    // `threads`: for the build (0: all cores); the grid is the same whatever their number.
    explicit MeshGrid(const TriangleMesh& m, double triangles_per_voxel = 1.0, int threads = 0);

    int nx = 1, ny = 1, nz = 1;
    double voxel_size = 1;
    Vec3 origin;

    size_t num_voxels() const { return size_t(nx) * ny * nz; }
    size_t index(int i, int j, int k) const { return (size_t(k) * ny + j) * nx + i; }
    std::array<int, 3> coords(size_t index) const;
    Box3 voxel_box(size_t index) const;
    // The whole grid's box, enlarged by margin() (every listed triangle lies inside it).
    Box3 box() const;
    // Voxel containing p, clamped to the grid (so points outside get the nearest boundary voxel).
    std::array<int, 3> locate(const Vec3& p) const;
    // Box enlargement used for assignment: 1e-9 of the voxel size, plus rounding of large coordinates.
    double margin() const { return margin_; }

    // Triangles of the mesh touching voxel `index`, in increasing order. Conservative: a triangle is
    // listed wherever it comes within margin() of the voxel's box.
    const uint32_t* begin(size_t index) const { return items_.data() + offs_[index]; }
    const uint32_t* end(size_t index) const { return items_.data() + offs_[index + 1]; }
    size_t num_assignments() const { return items_.size(); }

    // Voxels that triangle t of the mesh touches (same test as the lists above), increasing.
    std::vector<size_t> voxels_of_triangle(uint32_t t) const;
    // The same for any triangle (e.g. a target of the other mesh, or a piece of one); empty when it
    // lies outside the grid.
    std::vector<size_t> voxels_of_triangle(const std::array<Vec3, 3>& corners) const;

    struct Nearest {
        uint32_t triangle;  // UINT32_MAX when the mesh has no triangles
        Vec3 point;
        double dist2;       // +inf when the mesh has no triangles
    };
    // Nearest point of the mesh to p (any p, inside the grid box or not). `hint` is an optional
    // triangle likely to be near p: it only speeds the search up.
    // Searches voxel shells outward from p's voxel; if a few shells do not settle it (p far from the
    // mesh), it continues best-first over an occupancy pyramid, so far queries do not scan O((d/s)^3)
    // empty voxels. Ties go to the lowest triangle index. Safe to call from several threads.
    Nearest nearest(const Vec3& p, uint32_t hint = UINT32_MAX) const;
    // The distance from the point origin + offset to the mesh with every triangle taken relative to
    // `origin` (an input point), so its rounding is that of |offset| and the distances, not of the
    // coordinates' magnitude: the least over the triangles whose box lies within `reach` of the
    // rounded point origin + offset, which must hold the nearest one (callers take nearest()'s
    // distance there plus how far the rounding moved the point). `triangle` (if given): the one at
    // that distance, the lowest index among equals. +inf if no triangle is within reach.
    double distance_relative(const Vec3& origin, const Vec3& offset, double reach, uint32_t* triangle = nullptr) const;
    // The same with each triangle's distance taken from below (triangle_distance_lower): a value
    // the true distance is never under, but for its rounding (the certified interval's lower end).
    double distance_lower_relative(const Vec3& origin, const Vec3& offset, double reach) const;

    const TriangleMesh& mesh() const { return *mesh_; }

private:
    template <class Dist> double least_within(const Vec3& origin, const Vec3& offset, double reach, uint32_t* triangle, Dist dist) const;
    template <class F> void for_each_voxel_of(const std::array<Vec3, 3>& corners, F&& f) const;
    const TriangleMesh* mesh_;
    double margin_ = 0;
    std::vector<size_t> offs_;         // CSR: list of voxel v is items_[offs_[v] .. offs_[v+1])
    std::vector<uint32_t> items_;
    struct FloatBox { float lo[3], hi[3]; };
    std::vector<FloatBox> boxes_;      // beside items_: the listed triangle's box, rounded outward
    // Occupancy pyramid: level 0 is the grid, level l+1 halves each dimension (rounding up); a cell
    // is set if any voxel below it lists a triangle.
    struct Level { int nx, ny, nz; std::vector<uint8_t> occ; };
    std::vector<Level> pyramid_;
};

// The grids of a pair of meshes: mesh 0 (A) and mesh 1 (B), each in its own MeshGrid. A target of
// mesh `side` looks for its sources in of(1 - side). A mesh's grid can be shared by several pairs
// (hlens-cli batch indexes its reference once).
class VoxelGrid {
public:
    // Keeps pointers to a and b: they must outlive it. Large meshes' grids are built on `threads`
    // threads (0: all cores).
    VoxelGrid(const TriangleMesh& a, const TriangleMesh& b, double triangles_per_voxel = 1.0, int threads = 0);
    // From grids already built (their meshes must outlive them).
    VoxelGrid(std::shared_ptr<const MeshGrid> a, std::shared_ptr<const MeshGrid> b) : grid_{std::move(a), std::move(b)} {}

    using Nearest = MeshGrid::Nearest;
    // The grid listing the triangles of mesh `side` (0 = a, 1 = b).
    const MeshGrid& of(int side) const { return *grid_[side]; }
    const std::shared_ptr<const MeshGrid>& shared(int side) const { return grid_[side]; }
    // Nearest point of mesh `side` to p: of(side).nearest(p, hint).
    Nearest nearest(int side, const Vec3& p, uint32_t hint = UINT32_MAX) const { return grid_[side]->nearest(p, hint); }
    const TriangleMesh& mesh(int side) const { return grid_[side]->mesh(); }

private:
    std::shared_ptr<const MeshGrid> grid_[2];
};

}  // namespace hlens
