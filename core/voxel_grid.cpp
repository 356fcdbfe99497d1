#include "voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "parallel.h"
#include "point_triangle.h"

namespace hlens {

bool triangle_box_overlap(const Vec3& bc, const Vec3& h, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 v[3] = {a - bc, b - bc, c - bc};
    for (int i = 0; i < 3; ++i)  // box face normals = the bounding boxes overlap
        if (std::min({v[0][i], v[1][i], v[2][i]}) > h[i] || std::max({v[0][i], v[1][i], v[2][i]}) < -h[i])
            return false;
    // Projections of all three corners on each axis: a zero axis gives 0 vs radius 0, which never separates.
    auto separates = [&](const Vec3& ax) {
        double p0 = dot(ax, v[0]), p1 = dot(ax, v[1]), p2 = dot(ax, v[2]);
        double r = h.x * std::fabs(ax.x) + h.y * std::fabs(ax.y) + h.z * std::fabs(ax.z);
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    const Vec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    for (const Vec3& d : e)  // the nine cross products (unit axis x edge)
        if (separates({0, -d.z, d.y}) || separates({d.z, 0, -d.x}) || separates({-d.y, d.x, 0})) return false;
    return !separates(cross(e[0], e[1]));  // triangle normal
}

MeshGrid::MeshGrid(const TriangleMesh& mesh, double k, int threads) : mesh_(&mesh) {
    threads = mesh.num_triangles() > 20000 ? resolve_threads(threads) : 1;  // small meshes: not worth threads
    if (!(k > 0)) k = 1;
    const Box3 box = mesh.bounds();
    const double nm = std::max<double>(1, mesh.num_triangles());
    if (box.empty()) {
        origin = {0, 0, 0};
        voxel_size = 1;
    } else {
        Vec3 ext = box.extent();
        double diag = norm(ext), cap = 8 * nm + 64;
        double s = std::sqrt(2 * k * (ext.x * ext.y + ext.x * ext.z + ext.y * ext.z) / nm);
        // A box that is (nearly) a line has ~zero area: size voxels along its length instead. The
        // diag/cap floor keeps the counts below finite before the cap loop.
        s = std::max({s, k * diag / nm, diag / cap});
        if (!(s > 0)) s = 1;  // a single point
        double n[3];
        for (;;) {
            for (int i = 0; i < 3; ++i) n[i] = std::max(1.0, std::ceil(ext[i] / s));
            double count = n[0] * n[1] * n[2];
            if (count <= cap) break;
            s *= std::max(1.0001, std::cbrt(count / cap));
        }
        nx = int(n[0]); ny = int(n[1]); nz = int(n[2]);
        voxel_size = s;
        // Centre the mesh in the grid, so a flat mesh lies mid-layer rather than on voxel faces.
        for (int i = 0; i < 3; ++i) origin[i] = box.lo[i] - 0.5 * (n[i] * s - ext[i]);
    }
    Vec3 far = origin + Vec3(nx, ny, nz) * voxel_size;
    double M = std::max({std::fabs(origin.x), std::fabs(origin.y), std::fabs(origin.z), std::fabs(far.x),
                         std::fabs(far.y), std::fabs(far.z)});
    // Relative to the voxel (touching faces go to both voxels) plus the rounding of coordinates of size M.
    margin_ = 1e-9 * voxel_size + 4e-15 * M;

    const size_t nv = num_voxels();
    // Two passes over the triangles, in chunks on `threads` threads: count, then fill (each with
    // atomic increments); then each voxel's list is sorted, so it is the same whatever the threads.
    const uint32_t nt = (uint32_t)mesh.num_triangles();
    const size_t chunk = 4096, chunks = (nt + chunk - 1) / chunk;
    auto triangles_of = [&](size_t c, auto&& f) {
        for (uint32_t t = uint32_t(c * chunk); t < std::min<size_t>(nt, (c + 1) * chunk); ++t) f(t);
    };
    offs_.assign(nv + 1, 0);
    parallel_for(chunks, threads, nullptr, [&](size_t c) {
        triangles_of(c, [&](uint32_t t) {
            for_each_voxel_of(mesh.corners(t), [&](size_t v) { __atomic_fetch_add(&offs_[v + 1], 1, __ATOMIC_RELAXED); });
        });
    });
    for (size_t v = 0; v < nv; ++v) offs_[v + 1] += offs_[v];
    items_.resize(offs_[nv]);
    std::vector<size_t> pos(offs_.begin(), offs_.end() - 1);
    parallel_for(chunks, threads, nullptr, [&](size_t c) {
        triangles_of(c, [&](uint32_t t) {
            for_each_voxel_of(mesh.corners(t), [&](size_t v) { items_[__atomic_fetch_add(&pos[v], 1, __ATOMIC_RELAXED)] = t; });
        });
    });
    // Each listed triangle's box beside it, rounded outward to float: nearest() rejects most
    // triangles from the list alone, without fetching their corners.
    boxes_.resize(items_.size());
    const size_t vchunk = 65536;
    parallel_for((nv + vchunk - 1) / vchunk, threads, nullptr, [&](size_t c) {
        for (size_t v = c * vchunk; v < std::min(nv, (c + 1) * vchunk); ++v) {
            if (threads > 1) std::sort(items_.begin() + offs_[v], items_.begin() + offs_[v + 1]);
            for (size_t i = offs_[v]; i < offs_[v + 1]; ++i) {
                const Box3 b = mesh.triangle_bounds(items_[i]);
                for (int k = 0; k < 3; ++k) {
                    boxes_[i].lo[k] = std::nextafter((float)b.lo[k], -HUGE_VALF);
                    boxes_[i].hi[k] = std::nextafter((float)b.hi[k], HUGE_VALF);
                }
            }
        }
    });
    // Occupancy pyramid for far queries.
    pyramid_.push_back({nx, ny, nz, std::vector<uint8_t>(nv)});
    for (size_t v = 0; v < nv; ++v) pyramid_[0].occ[v] = offs_[v + 1] > offs_[v];
    while (pyramid_.back().nx > 1 || pyramid_.back().ny > 1 || pyramid_.back().nz > 1) {
        const Level& f = pyramid_.back();
        Level c{(f.nx + 1) / 2, (f.ny + 1) / 2, (f.nz + 1) / 2, {}};
        c.occ.assign(size_t(c.nx) * c.ny * c.nz, 0);
        for (int kk = 0; kk < f.nz; ++kk)
            for (int j = 0; j < f.ny; ++j)
                for (int i = 0; i < f.nx; ++i)
                    if (f.occ[(size_t(kk) * f.ny + j) * f.nx + i]) c.occ[(size_t(kk / 2) * c.ny + j / 2) * c.nx + i / 2] = 1;
        pyramid_.push_back(std::move(c));
    }
}

VoxelGrid::VoxelGrid(const TriangleMesh& a, const TriangleMesh& b, double k, int threads) {
    // One after the other, each on all the threads (a mesh of a million triangles and one of a
    // quarter of that, each on its own thread, left one core idle for most of the build).
    grid_[0] = std::make_shared<const MeshGrid>(a, k, threads);
    grid_[1] = std::make_shared<const MeshGrid>(b, k, threads);
}

std::array<int, 3> MeshGrid::coords(size_t idx) const {
    return {int(idx % nx), int((idx / nx) % ny), int(idx / (size_t(nx) * ny))};
}

Box3 MeshGrid::box() const {
    const Vec3 m(margin_, margin_, margin_);
    return {origin - m, origin + Vec3(nx, ny, nz) * voxel_size + m};
}

Box3 MeshGrid::voxel_box(size_t idx) const {
    auto c = coords(idx);
    Box3 b;
    b.lo = origin + Vec3(c[0], c[1], c[2]) * voxel_size;
    b.hi = b.lo + Vec3(voxel_size, voxel_size, voxel_size);
    return b;
}

std::array<int, 3> MeshGrid::locate(const Vec3& p) const {
    const int n[3] = {nx, ny, nz};
    std::array<int, 3> r;
    for (int i = 0; i < 3; ++i) {
        double f = std::floor((p[i] - origin[i]) / voxel_size);
        r[i] = f < 0 ? 0 : (f >= n[i] - 1 ? n[i] - 1 : int(f));  // also maps NaN to 0
    }
    return r;
}

template <class F>
void MeshGrid::for_each_voxel_of(const std::array<Vec3, 3>& corners, F&& f) const {
    const auto& [a, b, c] = corners;
    Box3 tb;
    for (const Vec3& p : corners) tb.add(p);
    const int n[3] = {nx, ny, nz};
    int lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        double l = std::floor((tb.lo[i] - margin_ - origin[i]) / voxel_size);
        double h = std::floor((tb.hi[i] + margin_ - origin[i]) / voxel_size);
        lo[i] = int(std::max(0.0, std::min(l, n[i] - 1.0)));
        hi[i] = int(std::max(0.0, std::min(h, n[i] - 1.0)));
    }
    if (lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) { f(index(lo[0], lo[1], lo[2])); return; }
    const double hs = 0.5 * voxel_size + margin_;
    const Vec3 half(hs, hs, hs);
    for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i) {
                Vec3 centre = origin + Vec3(i + 0.5, j + 0.5, k + 0.5) * voxel_size;
                if (triangle_box_overlap(centre, half, a, b, c)) f(index(i, j, k));
            }
}

std::vector<size_t> MeshGrid::voxels_of_triangle(uint32_t t) const { return voxels_of_triangle(mesh_->corners(t)); }

std::vector<size_t> MeshGrid::voxels_of_triangle(const std::array<Vec3, 3>& corners) const {
    std::vector<size_t> r;
    for_each_voxel_of(corners, [&](size_t v) { r.push_back(v); });
    return r;
}

// Kept whole (~95 lines) on purpose: the hottest query of the library, whose three phases (the
// hint, the shells around p's voxel, best-first over the occupancy pyramid) share the running
// best and the closures that test a voxel and a triangle against it; split, they would pass that
// state around on every call.
double MeshGrid::distance_relative(const Vec3& origin, const Vec3& offset, double reach, uint32_t* triangle) const {
    return least_within(origin, offset, reach, triangle, [](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
        return std::sqrt(closest_point_on_triangle(p, a, b, c).dist2);
    });
}

double MeshGrid::distance_lower_relative(const Vec3& origin, const Vec3& offset, double reach) const {
    return least_within(origin, offset, reach, nullptr, triangle_distance_lower);
}

// The least of dist(offset, corners - origin) over the triangles whose box lies within `reach` of
// origin + offset (distance_relative).
template <class Dist>
double MeshGrid::least_within(const Vec3& origin, const Vec3& offset, double reach, uint32_t* triangle, Dist dist) const {
    const TriangleMesh& m = *mesh_;
    const Vec3 w = origin + offset;
    double best = HUGE_VAL;
    uint32_t at = UINT32_MAX;
    auto consider = [&](uint32_t t) {
        const Box3 tb = m.triangle_bounds(t);
        if (!(point_box_distance2(w, tb.lo, tb.hi) <= reach * reach)) return;
        const auto c = m.corners(t);
        // Compared as distances: triangles whose squared distances differ in the last bit may tie.
        const double d = dist(offset, c[0] - origin, c[1] - origin, c[2] - origin);
        if (d < best || (d == best && t < at)) best = d, at = t;
    };
    // The voxels the ball touches hold every triangle within reach; far from the mesh a scan of
    // all triangles is cheaper. Both consider the same triangles (those whose box is in reach).
    const Vec3 r{reach, reach, reach};
    const auto lo = locate(w - r), hi = locate(w + r);
    const double voxels = double(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
    if (voxels > double(m.num_triangles())) {
        for (uint32_t t = 0; t < m.num_triangles(); ++t) consider(t);
    } else {
        for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int i = lo[0]; i <= hi[0]; ++i) {
                    const size_t v = index(i, j, k);
                    for (const uint32_t* t = begin(v); t != end(v); ++t) consider(*t);
                }
    }
    if (triangle) *triangle = at;
    return best;
}

MeshGrid::Nearest MeshGrid::nearest(const Vec3& p, uint32_t hint) const {
    const TriangleMesh& M = *mesh_;
    Nearest best{UINT32_MAX, p, std::numeric_limits<double>::infinity()};
    if (M.triangles.empty()) return best;
    auto consider = [&](uint32_t t) {
        auto [a, b, c] = M.corners(t);
        if (point_box_distance2(p, vmin(a, vmin(b, c)), vmax(a, vmax(b, c))) > best.dist2) return;
        ClosestPoint cp = closest_point_on_triangle(p, a, b, c);
        if (cp.dist2 < best.dist2 || (cp.dist2 == best.dist2 && t < best.triangle)) best = {t, cp.point, cp.dist2};
    };
    if (hint < M.num_triangles()) consider(hint);

    const auto c0 = locate(p);
    const int n[3] = {nx, ny, nz};
    const double s = voxel_size, m = margin_;
    const Box3 grid_box = box();
    const Vec3 glo = grid_box.lo, ghi = grid_box.hi;
    auto visit = [&](int i, int j, int k) {
        Vec3 lo = origin + Vec3(i, j, k) * s - Vec3(m, m, m);
        if (point_box_distance2(p, lo, lo + Vec3(s + 2 * m, s + 2 * m, s + 2 * m)) > best.dist2) return;
        size_t v = index(i, j, k);
        const FloatBox* fb = boxes_.data() + offs_[v];
        for (const uint32_t* t = begin(v); t != end(v); ++t, ++fb) {
            double d2 = 0;
            for (int a = 0; a < 3; ++a) {
                const double g = std::max({0.0, fb->lo[a] - p[a], p[a] - fb->hi[a]});
                d2 += g * g;
            }
            if (d2 <= best.dist2) consider(*t);
        }
    };
    constexpr int kShells = 2;  // shells 0..kShells settle queries near the mesh
    for (int R = 0; R <= kShells; ++R) {
        if (R > 0) {
            // Voxels at Chebyshev distance >= R from c0 lie in the six slabs of the grid box beyond the
            // cube of radius R-1: their true distance from p bounds everything not yet visited.
            double lb2 = std::numeric_limits<double>::infinity();
            for (int ax = 0; ax < 3; ++ax) {
                if (c0[ax] + R <= n[ax] - 1) {
                    Vec3 lo = glo;
                    lo[ax] = origin[ax] + (c0[ax] + R) * s - m;
                    lb2 = std::min(lb2, point_box_distance2(p, lo, ghi));
                }
                if (c0[ax] - R >= 0) {
                    Vec3 hi = ghi;
                    hi[ax] = origin[ax] + (c0[ax] - R + 1) * s + m;
                    lb2 = std::min(lb2, point_box_distance2(p, glo, hi));
                }
            }
            if (lb2 == std::numeric_limits<double>::infinity() || lb2 > best.dist2) return best;  // none left, or too far
        }
        const int k0 = std::max(0, c0[2] - R), k1 = std::min(nz - 1, c0[2] + R);
        const int j0 = std::max(0, c0[1] - R), j1 = std::min(ny - 1, c0[1] + R);
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j) {
                if (std::abs(k - c0[2]) == R || std::abs(j - c0[1]) == R) {
                    for (int i = std::max(0, c0[0] - R); i <= std::min(nx - 1, c0[0] + R); ++i) visit(i, j, k);
                } else {
                    if (c0[0] - R >= 0) visit(c0[0] - R, j, k);
                    if (R > 0 && c0[0] + R <= nx - 1) visit(c0[0] + R, j, k);
                }
            }
    }

    // Not settled: best-first over the occupancy pyramid, nearest cell first, skipping the shells done.
    struct Cell { double d2; int level, i, j, k; };
    auto farther = [](const Cell& x, const Cell& y) { return x.d2 > y.d2; };
    std::vector<Cell> heap;
    auto push = [&](int level, int i, int j, int k) {
        const Level& L = pyramid_[level];
        if (!L.occ[(size_t(k) * L.ny + j) * L.nx + i]) return;
        if (level == 0 && std::abs(i - c0[0]) <= kShells && std::abs(j - c0[1]) <= kShells &&
            std::abs(k - c0[2]) <= kShells)
            return;
        Vec3 lo = origin + Vec3(i, j, k) * (s * (1 << level)) - Vec3(m, m, m);
        Vec3 hi = vmin(origin + Vec3(i + 1, j + 1, k + 1) * (s * (1 << level)), origin + Vec3(nx, ny, nz) * s) + Vec3(m, m, m);
        double d2 = point_box_distance2(p, lo, hi);
        if (d2 > best.dist2) return;
        heap.push_back({d2, level, i, j, k});
        std::push_heap(heap.begin(), heap.end(), farther);
    };
    push(int(pyramid_.size()) - 1, 0, 0, 0);
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), farther);
        Cell c = heap.back();
        heap.pop_back();
        if (c.d2 > best.dist2) break;  // every cell left is farther still
        if (c.level == 0) { visit(c.i, c.j, c.k); continue; }
        const Level& F = pyramid_[c.level - 1];
        for (int k = 2 * c.k; k <= std::min(2 * c.k + 1, F.nz - 1); ++k)
            for (int j = 2 * c.j; j <= std::min(2 * c.j + 1, F.ny - 1); ++j)
                for (int i = 2 * c.i; i <= std::min(2 * c.i + 1, F.nx - 1); ++i) push(c.level - 1, i, j, k);
    }
    return best;
}

}  // namespace hlens
