#include "bounds.h"

#include "point_triangle.h"

#include <algorithm>
#include <cfloat>
#include <limits>

namespace hlens {

static constexpr double kInf = std::numeric_limits<double>::infinity();

SampledBound sampled_lower_bound(const TriangleMesh& A, const VoxelGrid& grid, int sideA, int n) {
    const int sideB = 1 - sideA;
    n = std::max(n, 1);
    SampledBound best{A.triangles.empty() ? 0.0 : -1.0, Vec3(), UINT32_MAX};
    if (!A.triangles.empty() && grid.mesh(sideB).triangles.empty()) return {kInf, A.corners(0)[0], 0};
    std::vector<double> vd(A.positions.size(), -1);  // corner distances, shared between triangles
    uint32_t hint = UINT32_MAX;
    auto sample = [&](const Vec3& p, uint32_t t) -> double {
        VoxelGrid::Nearest q = grid.nearest(sideB, p, hint);
        hint = q.triangle;  // consecutive samples are close: the last nearest triangle prunes the search
        double d = std::sqrt(q.dist2);
        if (d > best.value) best = {d, p, t};
        return d;
    };
    for (uint32_t t = 0; t < A.num_triangles(); ++t) {
        const Tri& f = A.triangles[t];
        auto c = A.corners(t);
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                int k = n - i - j;
                int corner = i == n ? 0 : (j == n ? 1 : (k == n ? 2 : -1));
                if (corner >= 0) {  // corners exactly, and each vertex once
                    if (vd[f[corner]] < 0) vd[f[corner]] = sample(c[corner], t);
                    continue;
                }
                sample(c[0] * (double(i) / n) + c[1] * (double(j) / n) + c[2] * (double(k) / n), t);
            }
    }
    return best;
}

// Smallest ball around a triangle: the midpoint of the longest edge if the third corner is inside that
// circle (right or obtuse, including degenerate), else the circumcentre (acute, hence non-degenerate).
// The radius is measured from the centre actually computed, so it is valid whatever the rounding.
static void enclosing_ball(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& centre, double& r) {
    const Vec3* v[3] = {&a, &b, &c};
    double l[3] = {norm2(b - c), norm2(c - a), norm2(a - b)};  // edge opposite corner i
    int o = l[0] >= l[1] && l[0] >= l[2] ? 0 : (l[1] >= l[2] ? 1 : 2);
    Vec3 m = (*v[(o + 1) % 3] + *v[(o + 2) % 3]) * 0.5;
    if (norm2(*v[o] - m) <= 0.25 * l[o]) {
        centre = m;
    } else {
        Vec3 u = a - c, w = b - c, n = cross(u, w);
        centre = c + cross(w * norm2(u) - u * norm2(w), n) / (2 * norm2(n));
    }
    r = std::sqrt(std::max({norm2(a - centre), norm2(b - centre), norm2(c - centre)}));
}

// d(p, B) <= d(p, T) for any triangle T of B, and d(., T) is convex, so its maximum over a triangle of A
// is at a corner. With T the nearest triangle of a nearby point this is often far tighter than the
// Lipschitz bound: it is exact where A's triangle sees only T (parallel offsets, coinciding meshes).
static double corner_bound(const std::array<Vec3, 3>& v, const TriangleMesh& B, uint32_t T) {
    return T < B.num_triangles() ? corner_distance_bound(v, B.corners(T)) : kInf;
}

// Kept whole (~80 lines): the corner pass (per-triangle bounds and their order) and the
// subdivision share the running lower bound, its witness and the rounding slack.
LipschitzBound lipschitz_bounds(const TriangleMesh& A, const VoxelGrid& grid, int sideA, double abs_tol) {
    const int sideB = 1 - sideA;
    const TriangleMesh& B = grid.mesh(sideB);
    if (A.triangles.empty()) return {0, 0, Vec3(), UINT32_MAX};
    if (B.triangles.empty()) return {kInf, kInf, A.corners(0)[0], 0};
    Box3 box = A.bounds();
    const double M = std::max({std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.lo.z),
                               std::fabs(box.hi.x), std::fabs(box.hi.y), std::fabs(box.hi.z)});
    abs_tol = std::max(abs_tol, 1e-9 * box.diagonal());  // subdivision must end
    if (!(abs_tol > 0)) abs_tol = 1e-300;                // A is a single point: r = 0 ends it at once

    LipschitzBound res{-1, -1, Vec3(), UINT32_MAX};
    // Rounding allowance (centres, midpoints: sub-triangles may miss slivers of width ~eps*M, distances).
    // It is added to `upper`, so a piece bounded by lower + slack can be dropped.
    auto slack = [&] { return 64 * DBL_EPSILON * (M + res.lower); };
    auto raise = [&](double d, const Vec3& p, uint32_t t) {
        if (d > res.lower) { res.lower = d; res.witness = p; res.triangle = t; }
    };
    // Corner distances give L and, per triangle, the bound min_i d(v_i) + (farthest corner from v_i).
    std::vector<double> vd(A.positions.size(), -1);
    std::vector<uint32_t> vhint(A.positions.size(), UINT32_MAX);
    uint32_t hint = UINT32_MAX;
    for (uint32_t t = 0; t < A.num_triangles(); ++t)
        for (int i = 0; i < 3; ++i) {
            uint32_t v = A.triangles[t][i];
            if (vd[v] >= 0) continue;
            VoxelGrid::Nearest q = grid.nearest(sideB, A.positions[v], hint);
            vd[v] = std::sqrt(q.dist2);
            vhint[v] = hint = q.triangle;
            raise(vd[v], A.positions[v], t);
        }
    std::vector<double> ub(A.num_triangles()), prio(A.num_triangles());
    std::vector<uint32_t> order;
    for (uint32_t t = 0; t < A.num_triangles(); ++t) {
        const Tri& f = A.triangles[t];
        auto c = A.corners(t);
        double e01 = norm(c[1] - c[0]), e12 = norm(c[2] - c[1]), e20 = norm(c[0] - c[2]);
        ub[t] = std::min({vd[f[0]] + std::max(e01, e20), vd[f[1]] + std::max(e01, e12), vd[f[2]] + std::max(e12, e20)});
        for (int i = 0; i < 3 && ub[t] > res.lower; ++i)
            if (i == 0 || vhint[f[i]] != vhint[f[i - 1]]) ub[t] = std::min(ub[t], corner_bound(c, B, vhint[f[i]]));
        prio[t] = std::max({vd[f[0]], vd[f[1]], vd[f[2]]});
        if (ub[t] > res.lower + slack()) order.push_back(t);  // most triangles end here
    }
    // Far triangles first: L rises early, so later triangles are discarded at once.
    std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return prio[x] > prio[y]; });

    struct Sub { Vec3 a, b, c; uint32_t hint; };
    std::vector<Sub> stack;
    double upper = -1;
    for (uint32_t t : order) {
        if (ub[t] <= res.lower + slack()) continue;
        auto c = A.corners(t);
        stack.push_back({c[0], c[1], c[2], vhint[A.triangles[t][0]]});
        while (!stack.empty()) {
            Sub s = stack.back();
            stack.pop_back();
            Vec3 centre;
            double r;
            enclosing_ball(s.a, s.b, s.c, centre, r);
            VoxelGrid::Nearest q = grid.nearest(sideB, centre, s.hint);
            double d = std::sqrt(q.dist2);
            raise(d, centre, t);
            const double keep = res.lower + slack();
            double u = d + r;
            if (u > keep) {
                const std::array<Vec3, 3> v{s.a, s.b, s.c};
                u = std::min(u, corner_bound(v, B, q.triangle));
                if (u > keep && s.hint != q.triangle) u = std::min(u, corner_bound(v, B, s.hint));
            }
            if (u <= keep) continue;
            if (!(r > abs_tol)) { upper = std::max(upper, u); continue; }  // (a NaN radius ends too)
            Vec3 ab = (s.a + s.b) * 0.5, bc = (s.b + s.c) * 0.5, ca = (s.c + s.a) * 0.5;
            stack.push_back({s.a, ab, ca, q.triangle});
            stack.push_back({ab, s.b, bc, q.triangle});
            stack.push_back({ca, bc, s.c, q.triangle});
            stack.push_back({ab, bc, ca, q.triangle});
        }
    }
    res.upper = std::max(upper, res.lower) + slack();
    return res;
}

}  // namespace hlens
