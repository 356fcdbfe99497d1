// Tests of the independent bounds on h(A,B) (suite Bounds).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

#include <hlens/bounds.h>
#include <hlens/mesh_io.h>
#include <hlens/point_triangle.h>
#include <hlens/voxel_grid.h>

#include "test_meshes.h"

using namespace hlens;
using hlens_test::brute_distance;

namespace {

TriangleMesh mesh_of(std::vector<Vec3> pos, std::vector<Tri> tris) {
    TriangleMesh m;
    m.positions = std::move(pos);
    m.triangles = std::move(tris);
    return m;
}

Vec3 rnd(std::mt19937& g, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(g), u(g), u(g)};
}

// Random triangles, some degenerate, some nearly parallel slivers.
TriangleMesh random_mesh(std::mt19937& g, int n, double lo, double hi, double size) {
    TriangleMesh m;
    std::uniform_int_distribution<int> kind(0, 9);
    for (int t = 0; t < n; ++t) {
        Vec3 a = rnd(g, lo, hi), b = a + rnd(g, -size, size), c = a + rnd(g, -size, size);
        int k = kind(g);
        if (k == 0) b = c = a;
        if (k == 1) c = a + (b - a) * 0.4;
        if (k == 2) c = a + (b - a) * 0.5 + rnd(g, -1e-9, 1e-9);
        uint32_t i = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, c});
        m.triangles.push_back({i, i + 1, i + 2});
    }
    return m;
}

TriangleMesh load_shared(const std::string& name) {
    std::string path = std::string(HLENS_SHARED_MESHES) + "/" + name;
    return hlens::load_mesh(path);
}

// Checks h(A,B) = expected (or only the bounds' consistency when expected < 0) in both the sampled and
// the Lipschitz bounds, and returns the Lipschitz interval.
LipschitzBound check_bounds(const TriangleMesh& A, const TriangleMesh& B, double tol, double expected = -1,
                            int n_per_edge = 12) {
    LipschitzBound first{};
    for (int sideA : {0, 1}) {  // the same pair with A as either side of the grid
        const TriangleMesh &a = A, &b = B;
        VoxelGrid gs = sideA == 0 ? VoxelGrid(A, B) : VoxelGrid(B, A);
        SampledBound s = sampled_lower_bound(a, gs, sideA, n_per_edge);
        LipschitzBound l = lipschitz_bounds(a, gs, sideA, tol);
        double slack = 1e-12 * (1 + l.upper);
        EXPECT_LE(l.lower, l.upper);
        EXPECT_LE(l.upper - l.lower, tol + slack);
        EXPECT_LE(s.value, l.upper + slack);
        // The witnesses are points of A at the reported distance from B.
        EXPECT_NEAR(brute_distance(l.witness, b), l.lower, slack);
        EXPECT_NEAR(brute_distance(s.point, b), s.value, slack);
        auto c = a.corners(l.triangle);
        EXPECT_LE(closest_point_on_triangle(l.witness, c[0], c[1], c[2]).dist2, 1e-24 * (1 + norm2(l.witness)));
        if (expected >= 0) {
            EXPECT_LE(l.lower, expected + slack);
            EXPECT_GE(l.upper, expected - slack);
            EXPECT_LE(s.value, expected + slack);
        }
        if (sideA == 0) first = l;
        else EXPECT_EQ(l.lower, first.lower);  // the grid's side does not matter
    }
    return first;
}

}  // namespace

TEST(Bounds, ParallelTriangles) {
    // A in z = 0 lies under the larger B in z = 2: every point of A is exactly 2 from B.
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{-5, -5, 2}, {10, -5, 2}, {-5, 10, 2}}, {{0, 1, 2}});
    LipschitzBound l = check_bounds(A, B, 1e-3, 2.0);
    EXPECT_NEAR(l.lower, 2, 1e-12);
    EXPECT_NEAR(l.upper, 2, 1e-12);  // d(., B) = d(., that one triangle) is convex: the corners bound it
    VoxelGrid g(A, B);
    EXPECT_NEAR(sampled_lower_bound(A, g, 0, 5).value, 2, 1e-12);
    // h(B,A): d(., A) is convex (A is one triangle), so its max over B is at a corner: (10,-5,2) or
    // (-5,10,2), whose nearest points on A are (1,0,0) and (0,1,0): sqrt(81 + 25 + 4).
    LipschitzBound r = lipschitz_bounds(B, g, 1, 1e-3);
    EXPECT_NEAR(r.lower, std::sqrt(110.0), 1e-12);
    EXPECT_LE(r.upper - std::sqrt(110.0), 1e-3 + 1e-12);
    EXPECT_NEAR(sampled_lower_bound(B, g, 1, 3).value, std::sqrt(110.0), 1e-12);
}

TEST(Bounds, TriangleToPoint) {
    // B is the single point 0 (a triangle with three equal corners): h(A,B) = max |p| over the unit right
    // triangle = 1, at the corners (1,0,0) and (0,1,0) (not sqrt 2: that is the hypotenuse's length).
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    TriangleMesh P = mesh_of({{0, 0, 0}}, {{0, 0, 0}});
    LipschitzBound l = check_bounds(A, P, 1e-4, 1.0);
    EXPECT_NEAR(l.lower, 1, 1e-15);
    check_bounds(P, A, 1e-4, 0.0);  // the point lies on A
    // A tiny triangle B = (0,0,0),(e,0,0),(0,e,0) instead: d(., B) is convex, so the max is at a corner
    // of A; the corner (1,0,0) is 1 - e from B's corner (e,0,0).
    const double e = 1e-3;
    TriangleMesh T = mesh_of({{0, 0, 0}, {e, 0, 0}, {0, e, 0}}, {{0, 1, 2}});
    l = check_bounds(A, T, 1e-4, 1 - e);
    EXPECT_NEAR(l.lower, 1 - e, 1e-15);
    check_bounds(T, A, 1e-4, 0.0);
}

TEST(Bounds, MaximumInsideTheTriangle) {
    // A equilateral with side 1; B = its three corners (degenerate triangles): the farthest point from
    // all corners is the centre, at the circumradius 1/sqrt(3).
    const double h3 = std::sqrt(3.0) / 2;
    std::vector<Vec3> pos = {{0, 0, 0}, {1, 0, 0}, {0.5, h3, 0}};
    TriangleMesh A = mesh_of(pos, {{0, 1, 2}});
    TriangleMesh corners = mesh_of(pos, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
    LipschitzBound l = check_bounds(A, corners, 1e-6, 1 / std::sqrt(3.0), 30);
    EXPECT_NEAR(l.lower, 1 / std::sqrt(3.0), 1e-6);
    VoxelGrid g(A, corners);
    EXPECT_NEAR(sampled_lower_bound(A, g, 0, 30).value, 1 / std::sqrt(3.0), 1e-12);  // samples the centre
    // B = its three edges (triangles with a repeated corner): the maximum is the inradius sqrt(3)/6.
    TriangleMesh edges = mesh_of(pos, {{0, 1, 1}, {1, 2, 2}, {2, 0, 0}});
    l = check_bounds(A, edges, 1e-6, std::sqrt(3.0) / 6, 30);
    EXPECT_NEAR(l.lower, std::sqrt(3.0) / 6, 1e-6);
}

TEST(Bounds, IdenticalMeshesGiveZero) {
    std::mt19937 gen(1);
    TriangleMesh A = random_mesh(gen, 50, -1, 1, 0.5);
    VoxelGrid g(A, A);
    // Zero up to rounding of the sample points (a barycentric combination is not exactly on the plane).
    // For the Lipschitz bound alone this is the slowest case (d(c) + r > 0 = L everywhere, so every
    // piece would be split down to abs_tol); the corner bound over the nearest triangle ends it at once.
    LipschitzBound l = lipschitz_bounds(A, g, 0, 1e-6);
    EXPECT_LE(l.lower, 1e-15);
    EXPECT_LE(l.upper, 1e-13);  // just the rounding allowance
    EXPECT_LE(sampled_lower_bound(A, g, 0, 8).value, 1e-15);
}

TEST(Bounds, EmptyMeshes) {
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}), E;
    VoxelGrid g(A, E);
    EXPECT_EQ(lipschitz_bounds(A, g, 0, 1e-3).upper, HUGE_VAL);
    EXPECT_EQ(sampled_lower_bound(A, g, 0, 3).value, HUGE_VAL);
    EXPECT_EQ(lipschitz_bounds(E, g, 1, 1e-3).upper, 0);
    EXPECT_EQ(sampled_lower_bound(E, g, 1, 3).value, 0);
}

TEST(Bounds, RandomPairs) {
    std::mt19937 gen(2);
    for (int rep = 0; rep < 12; ++rep) {
        double shift = rep % 3 == 0 ? 0.0 : 0.7;
        TriangleMesh A = random_mesh(gen, 30, -1, 1, 0.6), B = random_mesh(gen, 25, -1 + shift, 1 + shift, 0.4);
        double diag = A.bounds().diagonal();
        LipschitzBound coarse = check_bounds(A, B, 2e-2 * diag);
        LipschitzBound fine = check_bounds(A, B, 1e-4 * diag, -1, 20);
        // Both intervals hold h(A,B), so they intersect; the finer one is at least as tight.
        EXPECT_LE(std::max(coarse.lower, fine.lower), std::min(coarse.upper, fine.upper) + 1e-12);
        VoxelGrid g(A, B);
        EXPECT_LE(sampled_lower_bound(A, g, 0, 40).value, fine.upper + 1e-12);
        EXPECT_GE(fine.lower, sampled_lower_bound(A, g, 0, 1).value);  // L starts from every vertex
    }
}

TEST(Bounds, RealMeshAgainstPerturbedCopy) {
    TriangleMesh A = load_shared("spot.obj");
    TriangleMesh B = A;
    std::mt19937 gen(3);
    double diag = A.bounds().diagonal();
    for (Vec3& p : B.positions) p += rnd(gen, -2e-3 * diag, 2e-3 * diag);
    auto t0 = std::chrono::steady_clock::now();
    LipschitzBound l = check_bounds(A, B, 1e-4 * diag, -1, 6);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("[ info ] spot vs perturbed: h in [%.9g, %.9g] (diag %.4g), checks %.2f s\n", l.lower, l.upper, diag, sec);
    EXPECT_GT(l.lower, 0);
    EXPECT_LT(l.upper, 1e-2 * diag);
}

// The bracket on a large pair is as tight as asked. How long it takes is not asserted here (speed is
// measured by benchmarks, never by timed tests; under the sanitizers this takes minutes).
TEST(Bounds, LargeMeshPair) {
    TriangleMesh A = load_shared("nefertiti.obj");
    ASSERT_GT(A.num_triangles(), 90000u);
    TriangleMesh B = A;
    std::mt19937 gen(4);
    double diag = A.bounds().diagonal();
    for (Vec3& p : B.positions) p += rnd(gen, -1e-3 * diag, 1e-3 * diag);
    auto t0 = std::chrono::steady_clock::now();
    VoxelGrid g(A, B);
    auto t1 = std::chrono::steady_clock::now();
    LipschitzBound ab = lipschitz_bounds(A, g, 0, 1e-3 * diag);
    auto t2 = std::chrono::steady_clock::now();
    LipschitzBound ba = lipschitz_bounds(B, g, 1, 1e-3 * diag);
    auto t3 = std::chrono::steady_clock::now();
    auto s = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
    std::printf("[ info ] nefertiti (%zu tris) vs perturbed copy, tol 1e-3 diag: grid %.2f s, h(A,B) in [%.6g, %.6g] "
                "%.2f s, h(B,A) in [%.6g, %.6g] %.2f s\n",
                A.num_triangles(), s(t0, t1), ab.lower, ab.upper, s(t1, t2), ba.lower, ba.upper, s(t2, t3));
    EXPECT_LE(ab.upper - ab.lower, 1e-3 * diag * (1 + 1e-9));
    EXPECT_LE(ba.upper - ba.lower, 1e-3 * diag * (1 + 1e-9));
}
