// Tests of closest_point_on_triangle (suite PointTriangle) and of VoxelGrid (suite VoxelGrid).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include <hlens/mesh_io.h>
#include <hlens/point_triangle.h>
#include <hlens/voxel_grid.h>

#include "test_meshes.h"

using namespace hlens;

namespace {

// ---- oracles, written independently of the code under test ----

double seg_dist2(const Vec3& p, const Vec3& a, const Vec3& b) {
    Vec3 d = b - a;
    double l2 = dot(d, d);
    double t = l2 > 0 ? std::clamp(dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    Vec3 q = a + d * t;
    return dot(p - q, p - q);
}

// Min over a barycentric grid with n cells per edge and over the three edges (exact): always >= the true
// minimum, and within (longest edge / n) of it in distance.
double brute_dist2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n) {
    double best = std::min({seg_dist2(p, a, b), seg_dist2(p, b, c), seg_dist2(p, c, a)});
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            Vec3 q = a * (double(i) / n) + b * (double(j) / n) + c * (double(n - i - j) / n);
            best = std::min(best, norm2(p - q));
        }
    return best;
}

// Independent tight oracle for well-shaped triangles, in long double: project p on the plane by solving
// the 2x2 normal equations for barycentric coordinates; if outside, the minimum is on an edge.
double projection_dist2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    using LD = long double;
    LD e[3] = {LD(b.x) - a.x, LD(b.y) - a.y, LD(b.z) - a.z}, f[3] = {LD(c.x) - a.x, LD(c.y) - a.y, LD(c.z) - a.z},
       w[3] = {LD(p.x) - a.x, LD(p.y) - a.y, LD(p.z) - a.z};
    LD ee = 0, ef = 0, ff = 0;
    for (int i = 0; i < 3; ++i) { ee += e[i] * e[i]; ef += e[i] * f[i]; ff += f[i] * f[i]; }
    LD det = ee * ff - ef * ef, u = 0, v = 0, r[3];
    for (int step = 0; step < 3; ++step) {  // solve, then two rounds of iterative refinement on the residual
        LD re = 0, rf = 0;
        for (int i = 0; i < 3; ++i) { r[i] = w[i] - u * e[i] - v * f[i]; re += r[i] * e[i]; rf += r[i] * f[i]; }
        u += (re * ff - rf * ef) / det;
        v += (rf * ee - re * ef) / det;
    }
    if (u >= 0 && v >= 0 && u + v <= 1) {
        LD d2 = 0;
        for (int i = 0; i < 3; ++i) { r[i] = w[i] - u * e[i] - v * f[i]; d2 += r[i] * r[i]; }
        return double(d2);
    }
    return std::min({seg_dist2(p, a, b), seg_dist2(p, b, c), seg_dist2(p, c, a)});
}

bool well_shaped(const Vec3& a, const Vec3& b, const Vec3& c, double ratio) {
    double L2 = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
    return norm2(cross(b - a, c - a)) >= ratio * ratio * L2 * L2;
}

// Ericson, Real-Time Collision Detection 5.1.5: a second opinion for well-shaped triangles.
Vec3 ericson(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 ab = b - a, ac = c - a, ap = p - a;
    double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    Vec3 bp = p - b;
    double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    Vec3 cp = p - c;
    double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    double den = 1 / (va + vb + vc);
    return a + ab * (vb * den) + ac * (vc * den);
}

Vec3 rnd(std::mt19937& g, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(g), u(g), u(g)};
}

double longest(const Vec3& a, const Vec3& b, const Vec3& c) {
    return std::sqrt(std::max({norm2(b - a), norm2(c - b), norm2(a - c)}));
}

// Checks one query against the oracles.
void check_point(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    ClosestPoint cp = closest_point_on_triangle(p, a, b, c);
    const int n = 60;
    double L = longest(a, b, c), scale = L + norm(p - a);
    double brute = brute_dist2(p, a, b, c, n);
    ASSERT_LE(cp.dist2, brute + 1e-12) << "p=" << p.x << "," << p.y << "," << p.z;
    EXPECT_LE(std::sqrt(brute) - std::sqrt(cp.dist2), L / n + 1e-12);
    // The returned point is at the returned distance and on the triangle.
    EXPECT_NEAR(norm(p - cp.point), std::sqrt(cp.dist2), 1e-12 * scale);
    if (well_shaped(a, b, c, 1e-5)) {
        double r = projection_dist2(p, a, b, c);
        EXPECT_NEAR(std::sqrt(r), std::sqrt(cp.dist2), 1e-12 * scale);
        EXPECT_LE(projection_dist2(cp.point, a, b, c), 1e-24 * scale * scale);
    } else {  // then it is within rounding of an edge (or inside a sliver: within its height of an edge)
        double h = std::sqrt(norm2(cross(b - a, c - a))) / L;
        EXPECT_LE(std::sqrt(std::min({seg_dist2(cp.point, a, b), seg_dist2(cp.point, b, c), seg_dist2(cp.point, c, a)})),
                  h + 1e-12 * scale);
    }
}

// ---- small meshes ----

TriangleMesh cube_mesh(const Vec3& lo, const Vec3& hi) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

// Random triangles in [lo,hi]^3, with degenerate ones mixed in (points, segments, repeated corners).
TriangleMesh random_mesh(std::mt19937& g, int n, double lo, double hi, double size) {
    TriangleMesh m;
    std::uniform_int_distribution<int> kind(0, 9);
    for (int t = 0; t < n; ++t) {
        Vec3 a = rnd(g, lo, hi), b = a + rnd(g, -size, size), c = a + rnd(g, -size, size);
        switch (kind(g)) {
            case 0: b = c = a; break;                    // a point
            case 1: c = a + (b - a) * 0.3; break;        // collinear
            case 2: c = a + (b - a) * 1.7; break;        // collinear, c beyond b
            case 3: c = b; break;                        // two equal corners
            default: break;
        }
        uint32_t k = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, c});
        m.triangles.push_back({k, k + 1, k + 2});
    }
    m.positions.push_back({1e6, 1e6, 1e6});  // unused vertex: must not widen the grid
    return m;
}

TriangleMesh load_shared(const std::string& name) {
    std::string path = std::string(HLENS_SHARED_MESHES) + "/" + name;
    return hlens::load_mesh(path);
}

bool lists(const MeshGrid& g, size_t v, uint32_t t) { return std::binary_search(g.begin(v), g.end(v), t); }

// Every voxel whose closed box contains p (two per axis when p is on a voxel face).
std::vector<size_t> voxels_containing(const MeshGrid& g, const Vec3& p) {
    const int n[3] = {g.nx, g.ny, g.nz};
    std::vector<int> c[3];
    for (int i = 0; i < 3; ++i) {
        double f = (p[i] - g.origin[i]) / g.voxel_size;
        int lo = int(std::floor(f)), hi = lo;
        if (std::fabs(f - std::round(f)) < 1e-12) { lo = int(std::round(f)) - 1; hi = lo + 1; }
        for (int k = std::max(lo, 0); k <= std::min(hi, n[i] - 1); ++k) c[i].push_back(k);
        if (c[i].empty()) c[i].push_back(std::clamp(lo, 0, n[i] - 1));
    }
    std::vector<size_t> r;
    for (int i : c[0]) for (int j : c[1]) for (int k : c[2]) r.push_back(g.index(i, j, k));
    return r;
}

// Every triangle is listed in every voxel its surface touches, and voxels_of_triangle agrees with the lists.
void check_coverage(const MeshGrid& g, int samples_per_edge = 24) {
    const TriangleMesh& m = g.mesh();
    for (uint32_t t = 0; t < m.num_triangles(); ++t) {
        auto c = m.corners(t);
        const int n = samples_per_edge;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                Vec3 p = c[0] * (double(i) / n) + c[1] * (double(j) / n) + c[2] * (double(n - i - j) / n);
                for (size_t v : voxels_containing(g, p)) ASSERT_TRUE(lists(g, v, t)) << "triangle " << t << " voxel " << v;
            }
        std::vector<size_t> vs = g.voxels_of_triangle(t);
        ASSERT_FALSE(vs.empty());
        for (size_t v : vs) {
            ASSERT_TRUE(lists(g, v, t));
            // Not absurdly conservative: the triangle comes within a half voxel diagonal of the centre.
            Box3 b = g.voxel_box(v);
            Vec3 ctr = (b.lo + b.hi) * 0.5;
            EXPECT_LE(closest_point_on_triangle(ctr, c[0], c[1], c[2]).dist2, 0.75 * g.voxel_size * g.voxel_size * (1 + 1e-6));
        }
    }
    size_t total = 0;
    for (uint32_t t = 0; t < m.num_triangles(); ++t) total += g.voxels_of_triangle(t).size();
    EXPECT_EQ(total, g.num_assignments());
}

void check_coverage(const VoxelGrid& g, int samples_per_edge = 24) {
    for (int side = 0; side < 2; ++side) check_coverage(g.of(side), samples_per_edge);
}

// nearest() against brute force over all triangles, at points inside and far outside `box` (the
// box of both meshes: queries come from the other mesh too).
void check_nearest(const MeshGrid& g, Box3 box, int npoints, unsigned seed) {
    std::mt19937 gen(seed);
    const TriangleMesh& m = g.mesh();
    Vec3 ctr = (box.lo + box.hi) * 0.5;
    double diag = std::max(box.diagonal(), 1e-3);
    std::uniform_int_distribution<uint32_t> pick(0, uint32_t(m.num_triangles() - 1));
    for (int q = 0; q < npoints; ++q) {
        double spread = q % 4 == 3 ? 50 * diag : (q % 4 == 2 ? 2 * diag : 0.6 * diag);
        Vec3 p = ctr + rnd(gen, -spread, spread);
        if (q % 5 == 0) { auto c = m.corners(pick(gen)); p = c[0] * 0.25 + c[1] * 0.25 + c[2] * 0.5; }  // on the mesh
        double brute = HUGE_VAL;
        for (uint32_t t = 0; t < m.num_triangles(); ++t) {
            auto c = m.corners(t);
            brute = std::min(brute, closest_point_on_triangle(p, c[0], c[1], c[2]).dist2);
        }
        MeshGrid::Nearest r = g.nearest(p);
        ASSERT_EQ(r.dist2, brute) << "query " << q;
        auto c = m.corners(r.triangle);
        EXPECT_EQ(closest_point_on_triangle(p, c[0], c[1], c[2]).dist2, r.dist2);
        EXPECT_NEAR(norm2(p - r.point), r.dist2, 1e-9 * (r.dist2 + diag * diag * 1e-6));
        MeshGrid::Nearest h = g.nearest(p, pick(gen));  // a hint never changes the answer
        EXPECT_EQ(h.dist2, brute);
    }
}

void check_nearest(const VoxelGrid& g, int side, int npoints, unsigned seed) {
    Box3 box = g.mesh(0).bounds();
    box.add(g.mesh(1).bounds());
    check_nearest(g.of(side), box, npoints, seed);
    for (int k = 0; k < 3; ++k) {  // the pair answers as its grid does
        const Vec3 p = g.mesh(side).corners(0)[k] * 0.5 + box.hi * 0.5;
        EXPECT_EQ(g.nearest(side, p).dist2, g.of(side).nearest(p).dist2);
    }
}

}  // namespace

// ===================================================================== PointTriangle

TEST(PointTriangle, HandCases) {
    Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    ClosestPoint r = closest_point_on_triangle({0.5, 0.5, 3}, a, b, c);  // above the face
    EXPECT_DOUBLE_EQ(r.dist2, 9);
    EXPECT_NEAR(norm(r.point - Vec3(0.5, 0.5, 0)), 0, 1e-15);
    r = closest_point_on_triangle({-1, -1, 0}, a, b, c);  // beyond a corner
    EXPECT_EQ(r.point, a);
    EXPECT_DOUBLE_EQ(r.dist2, 2);
    r = closest_point_on_triangle({2, 2, 1}, a, b, c);  // beyond the hypotenuse
    EXPECT_NEAR(norm(r.point - Vec3(1, 1, 0)), 0, 1e-15);
    EXPECT_DOUBLE_EQ(r.dist2, 3);
    r = closest_point_on_triangle({5, -1, 0}, a, b, c);  // beyond corner b
    EXPECT_EQ(r.point, b);
    r = closest_point_on_triangle({1, 1, 0}, a, b, c);  // on the triangle
    EXPECT_EQ(r.dist2, 0);
}

TEST(PointTriangle, RandomTrianglesMatchBruteForce) {
    std::mt19937 g(1);
    for (int it = 0; it < 300; ++it) {
        Vec3 a = rnd(g, -1, 1), b = rnd(g, -1, 1), c = rnd(g, -1, 1);
        double far = it % 3 == 0 ? 20 : 2;
        for (int k = 0; k < 4; ++k) check_point(rnd(g, -far, far), a, b, c);
        check_point(a * 0.2 + b * 0.3 + c * 0.5 + rnd(g, -1e-3, 1e-3), a, b, c);  // very close to the face
    }
}

TEST(PointTriangle, AgreesWithEricsonOnWellShapedTriangles) {
    std::mt19937 g(2);
    for (int it = 0; it < 2000; ++it) {
        Vec3 a = rnd(g, -1, 1), b = rnd(g, -1, 1), c = rnd(g, -1, 1);
        double L = longest(a, b, c);
        if (norm(cross(b - a, c - a)) < 0.1 * L * L) continue;  // not well shaped
        Vec3 p = rnd(g, -3, 3);
        ClosestPoint r = closest_point_on_triangle(p, a, b, c);
        Vec3 e = ericson(p, a, b, c);
        EXPECT_NEAR(norm(r.point - e), 0, 1e-12);
        EXPECT_NEAR(r.dist2, norm2(p - e), 1e-12);
    }
}

TEST(PointTriangle, DegenerateTriangles) {
    std::mt19937 g(3);
    for (int it = 0; it < 200; ++it) {
        Vec3 a = rnd(g, -1, 1), b = rnd(g, -1, 1), p = rnd(g, -2, 2);
        std::uniform_real_distribution<double> u(-2, 3);
        check_point(p, a, a, a);                 // a point
        EXPECT_EQ(closest_point_on_triangle(p, a, a, a).point, a);
        check_point(p, a, b, b);                 // two equal corners: segment
        check_point(p, b, a, a);
        check_point(p, a, b, a + (b - a) * u(g));  // collinear, third corner anywhere on the line
        check_point(p, a + (b - a) * u(g), a, b);
        // Slivers: below the degeneracy threshold (edge fallback) and just above it (face path).
        Vec3 n = cross(b - a, rnd(g, -1, 1));
        n = n / norm(n);
        for (double h : {1e-14, 1e-11, 1e-8, 1e-5}) {
            Vec3 c = a + (b - a) * u(g) + n * (h * norm(b - a));
            check_point(p, a, b, c);
            check_point(a * 0.5 + b * 0.5 + n * 0.1, a, b, c);
            check_point(a * 0.5 + b * 0.5 + n * (h * norm(b - a) * 0.3), a, b, c);  // inside the sliver
        }
    }
}

TEST(PointTriangle, FarFromOriginAndTinyTriangles) {
    std::mt19937 g(4);
    for (int it = 0; it < 100; ++it) {
        Vec3 off = rnd(g, -1e5, 1e5);
        Vec3 a = off + rnd(g, -1e-3, 1e-3), b = off + rnd(g, -1e-3, 1e-3), c = off + rnd(g, -1e-3, 1e-3);
        Vec3 p = off + rnd(g, -2e-3, 2e-3);
        ClosestPoint r = closest_point_on_triangle(p, a, b, c);
        // Rounding of coordinates near 1e5 is ~1e-11: compare distances, not squared distances.
        double brute = brute_dist2(p, a, b, c, 60);
        EXPECT_LE(std::sqrt(r.dist2), std::sqrt(brute) + 1e-10);
        if (well_shaped(a, b, c, 1e-3)) {
            EXPECT_NEAR(std::sqrt(projection_dist2(p, a, b, c)), std::sqrt(r.dist2), 1e-10);
        }
    }
}

// ===================================================================== VoxelGrid

TEST(VoxelGrid, SizeFollowsStraubFormula) {
    TriangleMesh a = cube_mesh({0, 0, 0}, {1, 1, 1});
    // One grid per mesh. Box 1x1x1, n = 12: k = s^2 * 12 / (2*3)  =>  s = sqrt(k/2).
    MeshGrid g1(a, 0.5);
    EXPECT_DOUBLE_EQ(g1.voxel_size, 0.5);
    EXPECT_EQ(g1.nx, 2); EXPECT_EQ(g1.ny, 2); EXPECT_EQ(g1.nz, 2);
    EXPECT_EQ(g1.origin, Vec3(0, 0, 0));
    MeshGrid g4(a, 2.0);
    EXPECT_DOUBLE_EQ(g4.voxel_size, 1.0);
    EXPECT_EQ(g4.num_voxels(), 1u);
    MeshGrid gq(a, 0.125);
    EXPECT_DOUBLE_EQ(gq.voxel_size, 0.25);
    EXPECT_EQ(gq.num_voxels(), 64u);
    // k = 1e-3 asks for s = 0.0224 (45^3 voxels): capped at 8*12+64 = 160 voxels.
    MeshGrid gc(a, 1e-3);
    EXPECT_LE(gc.num_voxels(), 160u);
    EXPECT_GE(gc.num_voxels(), 27u);
    // Box 2x1x1: lw+lh+wh = 5, so s = sqrt(2*5/12) = 0.9129 -> 3 x 2 x 2 voxels, centred on the box.
    TriangleMesh w = cube_mesh({0, 0, 0}, {2, 1, 1});
    MeshGrid g2(w, 1.0);
    EXPECT_DOUBLE_EQ(g2.voxel_size, std::sqrt(10.0 / 12));
    EXPECT_EQ(g2.nx, 3); EXPECT_EQ(g2.ny, 2); EXPECT_EQ(g2.nz, 2);
    EXPECT_NEAR(g2.origin.x, 1 - 1.5 * g2.voxel_size, 1e-15);
    // A pair: each mesh in a grid of its own, as if alone.
    TriangleMesh b = cube_mesh({0.25, 0.25, 0.25}, {0.75, 0.75, 0.75});
    VoxelGrid pair(w, b, 1.0);
    EXPECT_EQ(pair.of(0).voxel_size, g2.voxel_size);
    EXPECT_EQ(pair.of(0).origin, g2.origin);
    EXPECT_DOUBLE_EQ(pair.of(1).voxel_size, 0.5 * std::sqrt(0.5));  // box 0.5^3: s = 0.5 sqrt(k/2)
    EXPECT_EQ(&pair.mesh(1), &b);
    check_coverage(g1);
    check_coverage(gq);
    check_coverage(g2);
    check_coverage(pair);
}

// A large mesh's grid is built on several threads (atomic counts and fills, then each voxel's
// list sorted): it must be the one-thread grid, list for list, and in increasing order.
TEST(VoxelGrid, BuiltOnThreadsIsTheSameGrid) {
    const TriangleMesh m = hlens_test::height_field(120, [](double x, double y) { return 0.2 * std::sin(5 * x) * std::cos(4 * y); });
    ASSERT_GT(m.num_triangles(), 20000u);  // below that the build stays on one thread
    const MeshGrid one(m, 1.0, 1), two(m, 1.0, 2);
    ASSERT_EQ(one.num_voxels(), two.num_voxels());
    ASSERT_EQ(one.num_assignments(), two.num_assignments());
    for (size_t v = 0; v < one.num_voxels(); ++v) {
        ASSERT_TRUE(std::equal(one.begin(v), one.end(v), two.begin(v), two.end(v))) << "voxel " << v;
        ASSERT_TRUE(std::is_sorted(two.begin(v), two.end(v))) << "voxel " << v;
    }
    for (const Vec3 p : {Vec3{0.3, 0.4, 0.5}, Vec3{-1, 2, 0}, Vec3{0.9, 0.1, -0.2}})
        EXPECT_EQ(one.nearest(p).triangle, two.nearest(p).triangle);
}

TEST(VoxelGrid, IndexCoordsRoundTrip) {
    TriangleMesh a = cube_mesh({0, 0, 0}, {3, 2, 1});
    MeshGrid g(a, 0.1);
    for (size_t v = 0; v < g.num_voxels(); ++v) {
        auto c = g.coords(v);
        ASSERT_EQ(g.index(c[0], c[1], c[2]), v);
        Box3 box = g.voxel_box(v);
        EXPECT_EQ(g.locate((box.lo + box.hi) * 0.5), c);
    }
}

TEST(VoxelGrid, TrianglesOnVoxelFacesGoToBothVoxels) {
    // Cube grid with s = 0.5 and origin 0: the planes x, y, z = 0.5 are voxel faces.
    TriangleMesh b = cube_mesh({0, 0, 0}, {1, 1, 1});
    b.triangles.resize(10);  // keep n = 12 (box still the unit cube), so s = 0.5 at k = 0.5
    b.positions.insert(b.positions.end(), {{0.5, 0.1, 0.1}, {0.5, 0.9, 0.2}, {0.5, 0.3, 0.9},   // in x = 0.5
                                           {0.1, 0.5, 0.5}, {0.9, 0.5, 0.5}, {0.5, 0.5, 0.5}});  // on an edge line
    b.triangles.push_back({8, 9, 10});
    b.triangles.push_back({11, 12, 13});
    MeshGrid g(b, 0.5);
    ASSERT_DOUBLE_EQ(g.voxel_size, 0.5);
    ASSERT_EQ(g.origin, Vec3(0, 0, 0));
    auto in_plane = g.voxels_of_triangle(10);
    EXPECT_EQ(in_plane.size(), 8u);  // the x = 0.5 triangle spans all y,z quadrants on both sides
    auto on_line = g.voxels_of_triangle(11);
    EXPECT_EQ(on_line.size(), 8u);   // the segment y = z = 0.5 touches all four voxels around it, twice along x
    check_coverage(g, 40);
}

TEST(VoxelGrid, RandomMeshesCoverageAndNearest) {
    std::mt19937 gen(5);
    for (int rep = 0; rep < 4; ++rep) {
        TriangleMesh a = random_mesh(gen, 60, -1, 1, 0.6), b = random_mesh(gen, 40, -0.5, 1.5, 0.3);
        for (double k : {1.0, 0.2}) {
            VoxelGrid g(a, b, k);
            check_coverage(g);
            check_nearest(g, 0, 200, 100 + rep);
            check_nearest(g, 1, 200, 200 + rep);
        }
    }
}

TEST(VoxelGrid, FlatAndDegenerateMeshes) {
    std::mt19937 gen(6);
    TriangleMesh flat_a, flat_b;  // all z = 0
    for (TriangleMesh* m : {&flat_a, &flat_b}) {
        *m = random_mesh(gen, 50, -1, 1, 0.4);
        m->positions.pop_back();
        for (Vec3& p : m->positions) p.z = 0;
    }
    VoxelGrid g(flat_a, flat_b);
    EXPECT_EQ(g.of(0).nz, 1);
    EXPECT_GT(g.of(0).nx * g.of(0).ny, 4);
    check_coverage(g);
    check_nearest(g, 0, 200, 7);
    check_nearest(g, 1, 200, 8);

    TriangleMesh line;  // every triangle on the x axis
    for (int i = 0; i < 30; ++i) {
        line.positions.insert(line.positions.end(), {{i * 0.1, 0, 0}, {i * 0.1 + 0.05, 0, 0}, {i * 0.1 + 0.13, 0, 0}});
        line.triangles.push_back({uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2)});
    }
    VoxelGrid gl(line, line);
    EXPECT_EQ(gl.of(1).ny, 1); EXPECT_EQ(gl.of(1).nz, 1);
    EXPECT_GT(gl.of(1).nx, 10);
    check_coverage(gl);
    check_nearest(gl, 0, 200, 9);

    TriangleMesh point;  // one point, used by several triangles
    point.positions = {{1, 2, 3}};
    point.triangles = {{0, 0, 0}, {0, 0, 0}};
    VoxelGrid gp(point, point);
    EXPECT_EQ(gp.of(0).num_voxels(), 1u);
    EXPECT_GT(gp.of(0).voxel_size, 0);
    check_coverage(gp);
    VoxelGrid::Nearest r = gp.nearest(1, {4, 6, 3});
    EXPECT_EQ(r.dist2, 25);
    EXPECT_EQ(r.point, Vec3(1, 2, 3));

    TriangleMesh empty;
    VoxelGrid ge(empty, point);
    EXPECT_EQ(ge.nearest(0, {0, 0, 0}).triangle, UINT32_MAX);
    EXPECT_EQ(ge.nearest(0, {0, 0, 0}).dist2, HUGE_VAL);
    EXPECT_EQ(ge.nearest(1, {1, 2, 4}).dist2, 1);
    VoxelGrid gee(empty, empty);
    EXPECT_EQ(gee.of(0).num_voxels(), 1u);
    EXPECT_EQ(gee.nearest(1, {0, 0, 0}).triangle, UINT32_MAX);
}

TEST(VoxelGrid, FarFromOrigin) {
    std::mt19937 gen(10);
    TriangleMesh a = random_mesh(gen, 40, -1, 1, 0.5), b = random_mesh(gen, 40, -1, 1, 0.5);
    for (TriangleMesh* m : {&a, &b}) {
        m->positions.pop_back();
        for (Vec3& p : m->positions) p += Vec3(3e6, -1e6, 2e6);
    }
    VoxelGrid g(a, b);
    check_coverage(g);
    check_nearest(g, 0, 100, 11);
}

// distance_relative: the distance from origin + offset with every triangle taken relative to
// origin, over the triangles within reach of the rounded point. The referee is brute force over
// every triangle, relative to origin as well: its value, and a triangle attaining it, the lowest
// index among equals. Points near the mesh (the voxels around them) and far from it (a scan), 3e6
// from the origin, where an ulp of the coordinates is 5e-10.
TEST(VoxelGrid, DistanceRelativeIsTheBruteForceDistanceInTheFrame) {
    std::mt19937 gen(21);
    TriangleMesh m = random_mesh(gen, 400, -1, 1, 0.3);
    m.positions.pop_back();
    for (Vec3& p : m.positions) p += Vec3(3e6, -1e6, 2e6);
    const MeshGrid g(m);
    int scanned = 0, near = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 origin = m.positions[gen() % m.positions.size()];
        const double spread = i % 2 ? 0.3 : 40.0;
        const Vec3 offset = rnd(gen, -spread, spread);
        double brute = HUGE_VAL;
        for (size_t t = 0; t < m.num_triangles(); ++t) {
            const auto c = m.corners(t);
            brute = std::min(brute, std::sqrt(closest_point_on_triangle(offset, c[0] - origin, c[1] - origin, c[2] - origin).dist2));
        }
        const MeshGrid::Nearest q = g.nearest(origin + offset);
        const double eps = 0x1p-52 * (std::fabs(origin.x) + std::fabs(origin.y) + std::fabs(origin.z) + 1e3);
        const double reach = std::sqrt(q.dist2) + 4 * eps;
        (reach > 2 ? scanned : near)++;
        uint32_t t = UINT32_MAX;
        const double d = g.distance_relative(origin, offset, reach, &t);
        ASSERT_EQ(d, brute) << i;
        ASSERT_LT(t, m.num_triangles());
        const auto c = m.corners(t);
        EXPECT_EQ(std::sqrt(closest_point_on_triangle(offset, c[0] - origin, c[1] - origin, c[2] - origin).dist2), d) << i;
    }
    EXPECT_GT(scanned, 0);
    EXPECT_GT(near, 0);
}

TEST(VoxelGrid, RealMeshNearest) {
    TriangleMesh spot = load_shared("spot.obj");
    ASSERT_EQ(spot.num_triangles(), 5856u);
    std::mt19937 gen(12);
    TriangleMesh other = random_mesh(gen, 300, -0.5, 0.5, 0.2);  // overlaps spot's box
    VoxelGrid g(spot, other);
    EXPECT_LE(g.of(0).num_voxels(), 8 * 5856 + 64u);
    EXPECT_LE(g.of(1).num_voxels(), 8 * 300 + 64u);
    check_coverage(g, 6);
    check_nearest(g, 0, 400, 13);
    check_nearest(g, 1, 200, 14);
}

// The grid of two large meshes: bounded size, correct nearest queries. How long the build takes is
// measured by the benchmark voxel_grid/nefertiti (bench/bench_hausdorff.cpp), not asserted here.
TEST(VoxelGrid, BuildTwoLargeMeshes) {
    TriangleMesh a = load_shared("nefertiti.obj");
    ASSERT_GT(a.num_triangles(), 90000u);
    TriangleMesh b = a;
    std::mt19937 gen(15);
    double diag = a.bounds().diagonal();
    for (Vec3& p : b.positions) p += rnd(gen, -1e-3 * diag, 1e-3 * diag);
    VoxelGrid g(a, b);
    for (int side = 0; side < 2; ++side) {
        const MeshGrid& m = g.of(side);
        std::printf("[ info ] grid for %zu triangles: %d x %d x %d voxels, %zu assignments\n", a.num_triangles(), m.nx,
                    m.ny, m.nz, m.num_assignments());
        EXPECT_LE(m.num_voxels(), 8 * a.num_triangles() + 64);
    }
    check_nearest(g, 1, 30, 16);
}

// A small mesh far from a large one: each keeps the voxels it would have alone (one grid over both
// would put the large mesh in a voxel or two), and queries from the other mesh's side stay exact.
TEST(VoxelGrid, MeshesFarApartKeepTheirOwnVoxels) {
    std::mt19937 gen(17);
    TriangleMesh big = random_mesh(gen, 3000, -1, 1, 0.05), small = random_mesh(gen, 20, -1, 1, 0.5);
    big.positions.pop_back();
    for (Vec3& p : small.positions) p = p * 0.01 + Vec3(300, -200, 100);
    const VoxelGrid g(small, big);
    const MeshGrid alone(big);
    EXPECT_EQ(g.of(1).voxel_size, alone.voxel_size);
    EXPECT_EQ(g.of(1).num_voxels(), alone.num_voxels());
    size_t most = 0;
    for (size_t v = 0; v < g.of(1).num_voxels(); ++v) most = std::max<size_t>(most, g.of(1).end(v) - g.of(1).begin(v));
    EXPECT_LT(most, big.num_triangles() / 20);
    check_coverage(g, 6);
    check_nearest(g, 1, 100, 18);
    check_nearest(g, 0, 100, 19);
}

// triangle_distance_lower on slivers in the plane z = 0 (a = 0, b = (1,0,0), c = (t, h, 0)), where
// the truth is exact: |z| where p's foot lies in the triangle (2D orientation tests, exact for these
// coordinates to far below h), else the distance to the nearest edge. The bound is never above the
// truth (but for a few ulps of the sizes) and never below it by more than the height.
TEST(PointTriangle, LowerBoundHoldsOnSlivers) {
    // The hand case behind it: a foot inside a sliver 9e-13 high, which closest_point_on_triangle
    // takes as its edges, 4.9e-13 where the distance is 2e-13.
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, 9e-13, 0}, q{0.5, 4.5e-13, 2e-13};
    EXPECT_GT(std::sqrt(closest_point_on_triangle(q, a, b, c).dist2), 4.9e-13);
    EXPECT_LE(triangle_distance_lower(q, a, b, c), 2e-13);
    EXPECT_GE(triangle_distance_lower(q, a, b, c), 2e-13 - 9e-13);
    std::mt19937 g(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (double h : {1e-15, 1e-13, 9e-13, 1e-11, 1e-9, 1e-6, 1e-3}) {
        for (int it = 0; it < 400; ++it) {
            const double t = 0.2 + 0.6 * u(g);
            const Vec3 c2{t, h, 0};
            const double x = -0.1 + 1.2 * u(g), y = h * (-2 + 5 * u(g));
            const double zs[] = {0, 1e-15, 1e-13, 1e-9, 1e-3, 0.5};
            const double z = zs[it % 6] * (u(g) < 0.5 ? -1 : 1);
            const Vec3 p{x, y, z};
            using LD = long double;
            auto side = [](LD ax, LD ay, LD bx, LD by, LD px, LD py) { return (bx - ax) * (py - ay) - (by - ay) * (px - ax); };
            const bool inside = side(0, 0, 1, 0, x, y) >= 0 && side(1, 0, t, h, x, y) >= 0 && side(t, h, 0, 0, x, y) >= 0;
            const double truth = inside ? std::fabs(z) : std::sqrt(std::min({seg_dist2(p, a, b), seg_dist2(p, b, c2), seg_dist2(p, c2, a)}));
            const double lower = triangle_distance_lower(p, a, b, c2);
            SCOPED_TRACE(testing::Message() << "h " << h << " p " << x << " " << y << " " << z << " truth " << truth);
            EXPECT_LE(lower, truth + 1e-15);  // a few ulps of the sizes (1), as the edges' distances have
            EXPECT_GE(lower, truth - h - 1e-15 * (1 + std::fabs(z)));
        }
    }
}

#if defined(__SIZEOF_FLOAT128__)
// Thin triangles turned every way, against a truth in quad precision (__float128, 113 bits: the
// barycentric solve loses (L / h)^2, at most 1e22 here, and keeps 1e-12). Points lie near the
// longest edge, off the plane by up to the edge's length or by almost nothing. Above the height
// at which it takes a triangle as its edges, closest_point_on_triangle is accurate to a few ulps
// of the sizes (its plane from the longest edge and the re-orthogonalised height: the rounding
// is that of a triangle moved by an ulp); triangle_distance_lower is never above the truth and,
// near a thin triangle's plane, below it by no more than its margin.
TEST(PointTriangle, ThinTrianglesAgreeWithQuadPrecision) {
    using Q = __float128;
    struct QV { Q x, y, z; };
    auto qv = [](const Vec3& a) { return QV{a.x, a.y, a.z}; };
    auto sub = [](QV a, QV b) { return QV{a.x - b.x, a.y - b.y, a.z - b.z}; };
    auto dotq = [](QV a, QV b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    auto seg = [&](QV p, QV a, QV b) {
        const QV d = sub(b, a), w = sub(p, a);
        const Q l = dotq(d, d);
        Q t = l > 0 ? dotq(w, d) / l : 0;
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        const QV r{w.x - t * d.x, w.y - t * d.y, w.z - t * d.z};
        return dotq(r, r);
    };
    auto truth2 = [&](const Vec3& P, const Vec3& A, const Vec3& B, const Vec3& C) {
        const QV p = qv(P), a = qv(A), b = qv(B), c = qv(C), e = sub(b, a), f = sub(c, a), w = sub(p, a);
        const Q ee = dotq(e, e), ef = dotq(e, f), ff = dotq(f, f), we = dotq(w, e), wf = dotq(w, f), det = ee * ff - ef * ef;
        Q best = seg(p, a, b);
        best = std::min(best, seg(p, b, c));
        best = std::min(best, seg(p, c, a));
        if (det > 0) {
            const Q u = (we * ff - wf * ef) / det, v = (wf * ee - we * ef) / det;
            if (u >= 0 && v >= 0 && u + v <= 1) {
                const QV r{w.x - u * e.x - v * f.x, w.y - u * e.y - v * f.y, w.z - u * e.z - v * f.z};
                best = std::min(best, dotq(r, r));
            }
        }
        return (double)best;
    };
    std::mt19937 g(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int it = 0; it < 6000; ++it) {
        const double hl = std::pow(10.0, -11 + it % 6);  // height / length, 1e-11 .. 1e-6
        const Vec3 a = rnd(g, -1, 1), d = rnd(g, -1, 1), m = rnd(g, -1, 1), b = a + d;
        const double L = norm(d);
        Vec3 n = cross(d, m);
        n = n / norm(n);
        Vec3 side = cross(n, d);
        side = side / norm(side);
        const Vec3 c = a + d * (0.3 + 0.2 * (u(g) + 1)) + side * (hl * L);
        const double z = it % 2 ? u(g) * L : u(g) * 1e-9 * L;
        const Vec3 p = a + d * (0.2 + 0.3 * (u(g) + 1)) + side * (u(g) * 1e-6 * L) + n * z;
        const double truth = std::sqrt(truth2(p, a, b, c)), size = L + norm(p - a);
        SCOPED_TRACE(testing::Message() << "h/L " << hl << " truth " << truth);
        EXPECT_NEAR(std::sqrt(closest_point_on_triangle(p, a, b, c).dist2), truth, 1e-15 * size);
        const double lower = triangle_distance_lower(p, a, b, c);
        EXPECT_LE(lower, truth + 1e-15 * size);
        EXPECT_GE(lower, truth - 1e-10 * size);
    }
}
#endif
