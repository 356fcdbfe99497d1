// The exact per-target solver and the whole-mesh driver against independent oracles:
// hand-derived values, the sampling lower bound and the Lipschitz upper bound (core/bounds.h,
// which uses only exact point-triangle distances), and the domain mesh's invariants after every
// insertion.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <hlens/bounds.h>
#include <hlens/cascade.h>
#include <hlens/case_export.h>
#include <hlens/confirm_top.h>
#include <hlens/hausdorff.h>
#include <hlens/mesh_io.h>
#include <hlens/target_solver.h>

#include "test_meshes.h"

using namespace hlens;
using namespace hlens_test;

namespace {

// Solve every target of A against B with the invariants checked after every insertion.
double solve_all_checked(const TriangleMesh& A, const TriangleMesh& B, Vec3* where = nullptr) {
    VoxelGrid grid(A, B);
    double best = -1;
    for (uint32_t t = 0; t < A.num_triangles(); ++t) {
        TargetSolver ts(grid, 0, t);
        ts.validate_each_insertion(true);
        ts.run();
        if (ts.max_sq() > best) {
            best = ts.max_sq();
            if (where) *where = ts.max_point();
        }
    }
    return std::sqrt(best);
}

// The exact value must lie between the sampling lower bound and the Lipschitz upper bound.
void expect_between_bounds(const TriangleMesh& A, const TriangleMesh& B, double exact, const char* what) {
    VoxelGrid grid(A, B);
    double diag = std::max(A.bounds().diagonal(), B.bounds().diagonal());
    LipschitzBound lb = lipschitz_bounds(A, grid, 0, 1e-6 * diag);
    SampledBound sb = sampled_lower_bound(A, grid, 0, 12);
    EXPECT_GE(exact, sb.value - 1e-12 * diag) << what;
    EXPECT_GE(exact, lb.lower - 1e-12 * diag) << what;
    EXPECT_LE(exact, lb.upper + 1e-12 * diag) << what;
}

}  // namespace

// ---------------------------------------------------------------- hand-derived cases

TEST(SolverHand, ParallelTriangles) {
    // A lies in z = 0 inside the shadow of B at z = 2: every point of A is exactly 2 from B.
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{-5, -5, 2}, {10, -5, 2}, {-5, 10, 2}}, {{0, 1, 2}});
    EXPECT_NEAR(solve_all_checked(A, B), 2.0, 1e-12);
    HausdorffResult r = hausdorff(A, B);
    EXPECT_NEAR(r.a_to_b.distance, 2.0, 1e-12);
    // h(B,A): the farthest point of B from A is a corner of B; by hand, the corner (10,-5,2) is
    // nearest to A's corner (1,0,0): sqrt(81 + 25 + 4).
    EXPECT_NEAR(r.b_to_a.distance, std::sqrt(110.0), 1e-12);
    EXPECT_NEAR(r.hausdorff, std::sqrt(110.0), 1e-12);
}

TEST(SolverHand, PerpendicularSharingEdge) {
    // A in z = 0, B in y = 0, sharing the edge from the origin to (1,0,0). A point (x,y,0) of A
    // projects to (x,0,0) on the shared edge, so its distance is y: the maximum is 1 at (0,1,0).
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 1, 2}});
    Vec3 w;
    EXPECT_NEAR(solve_all_checked(A, B, &w), 1.0, 1e-12);
    EXPECT_NEAR(w.x, 0.0, 1e-9);
    EXPECT_NEAR(w.y, 1.0, 1e-9);
    HausdorffResult r = hausdorff(A, B);
    EXPECT_NEAR(r.a_to_b.distance, 1.0, 1e-12);
    EXPECT_NEAR(r.b_to_a.distance, 1.0, 1e-12);  // by the symmetry x <-> x, y <-> z
}

TEST(SolverHand, PerpendicularSharingVertex) {
    // B = {(-a, 0, z) : 0 <= a <= z <= 1} in the plane y = 0 touches A only at the origin.
    // From A: the nearest point of B to (x, y, 0) is the origin, so h(A,B) = 1 (corners).
    // From B: the nearest point of A to (-a, 0, z) is the origin, so h(B,A) = |(-1,0,1)| = sqrt 2.
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{0, 0, 0}, {0, 0, 1}, {-1, 0, 1}}, {{0, 1, 2}});
    HausdorffResult r = hausdorff(A, B);
    EXPECT_NEAR(r.a_to_b.distance, 1.0, 1e-12);
    EXPECT_NEAR(r.b_to_a.distance, std::sqrt(2.0), 1e-12);
}

TEST(SolverHand, TriangleOverFlatFan) {
    // A flat fan of 8 triangles in z = 0 around the origin, radius 3; A at height 1.5 inside it.
    std::vector<Vec3> p{{0, 0, 0}};
    std::vector<Tri> t;
    for (int k = 0; k < 8; ++k) p.push_back({3 * std::cos(k * M_PI / 4), 3 * std::sin(k * M_PI / 4), 0});
    for (uint32_t k = 0; k < 8; ++k) t.push_back({0, 1 + k, 1 + (k + 1) % 8});
    TriangleMesh B = mesh_of(p, t);
    TriangleMesh A = mesh_of({{-1, -0.5, 1.5}, {1, -0.7, 1.5}, {0.2, 1.1, 1.5}}, {{0, 1, 2}});
    EXPECT_NEAR(solve_all_checked(A, B), 1.5, 1e-12);
    // All sources lie in one plane: their face polynomials are equal, so the domains merge into one.
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.run();
    EXPECT_GE(ts.insertions(), 2);
    EXPECT_EQ(ts.domain_mesh()->num_live_faces(), 1);
    EXPECT_EQ(ts.domain_mesh()->num_live_edges(), 3);
    EXPECT_EQ(ts.validate(), "");
}

TEST(SolverHand, MaximumStrictlyInsideTarget) {
    // B = the three corners of an equilateral A (as point triangles). d is the distance to the
    // nearest corner, largest at the circumcentre: 1/sqrt(3) for unit sides, inside A.
    double h = std::sqrt(3.0) / 2;
    TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}}, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
    Vec3 w;
    EXPECT_NEAR(solve_all_checked(A, B, &w), 1 / std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(w.x, 0.5, 1e-9);
    EXPECT_NEAR(w.y, h / 3, 1e-9);
}

TEST(SolverHand, ClosedConicInsideADomain) {
    // B = the point p = (0, 0, 0.5) and a large triangle in the plane z = -1. On the target plane
    // z = 0: |P - p|^2 = x^2 + y^2 + 0.25 and the plane's d^2 = 1, equal on the circle
    // x^2 + y^2 = 0.75. Inside it p is nearer, outside the plane: d = 1 at most, reached outside.
    // The circle is a closed conic inside one domain: the plane's domain has a hole.
    TriangleMesh A = mesh_of({{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{0, 0, 0.5}, {-10, -10, -1}, {10, -10, -1}, {0, 10, -1}}, {{0, 0, 0}, {1, 2, 3}});
    EXPECT_NEAR(solve_all_checked(A, B), 1.0, 1e-12);
    // The domain mesh holds the circle as a closed conic: a domain with a hole.
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.run();
    int holes = 0, conic_arcs = 0;
    for (const auto& f : ts.domain_mesh()->faces())
        if (f.alive) holes += (int)f.loops.size() - 1;
    for (const auto& e : ts.domain_mesh()->edges())
        if (e.alive && e.curve_kind == CurveKind::Ellipse) ++conic_arcs;
    EXPECT_EQ(holes, 1);
    EXPECT_GE(conic_arcs, 2);
    EXPECT_EQ(ts.validate(), "");
}

TEST(SolverHand, TwoPointsEqualDistanceOnAnEdge) {
    // B = the points p = (0,0,0) and q = (4,0,0); A = the triangle (2,-3,1), (2,3,1), (1,0,1)
    // at height 1. Equal distance on the plane x = 2, which holds an edge of A. The maximum of
    // min(|P-p|, |P-q|) over A is at the corners (2, +-3, 1): sqrt(4 + 9 + 1) = sqrt(14).
    TriangleMesh A = mesh_of({{2, -3, 1}, {2, 3, 1}, {1, 0, 1}}, {{0, 1, 2}});
    TriangleMesh B = mesh_of({{0, 0, 0}, {4, 0, 0}}, {{0, 0, 0}, {1, 1, 1}});
    EXPECT_NEAR(solve_all_checked(A, B), std::sqrt(14.0), 1e-12);
}

// ---------------------------------------------------------------- randomised against the bounds

TEST(SolverRandom, PairsOfTriangles) {
    std::mt19937 rng(7);
    for (int i = 0; i < 60; ++i) {
        TriangleMesh A = random_triangle_soup(rng, 1, 1.0, {0, 0, 0}, 0.0);
        TriangleMesh B = random_triangle_soup(rng, 1, 1.0, {0, 0, 0}, 0.5);
        double exact = solve_all_checked(A, B);
        expect_between_bounds(A, B, exact, "random pair");
    }
}

TEST(SolverRandom, SmallSoups) {
    std::mt19937 rng(11);
    for (int i = 0; i < 25; ++i) {
        TriangleMesh A = random_triangle_soup(rng, 3, 0.6, {0, 0, 0}, 0.5);
        TriangleMesh B = random_triangle_soup(rng, 12, 0.5, {0, 0, 0}, 0.8);
        double exact = solve_all_checked(A, B);
        expect_between_bounds(A, B, exact, "random soups");
    }
}

TEST(SolverRandom, TargetsOverHeightFields) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int i = 0; i < 20; ++i) {
        double a = 0.4 * U(rng), b = 0.4 * U(rng);
        TriangleMesh B = height_field(5, [&](double x, double y) { return a * std::sin(3 * x) + b * x * y; });
        TriangleMesh A = random_triangle_soup(rng, 2, 0.5, {0, 0, 0}, 0.5);
        double exact = solve_all_checked(A, B);
        expect_between_bounds(A, B, exact, "height field");
    }
}

TEST(SolverRandom, CoplanarAndOverlapping) {
    // A in the plane of a flat B, inside it: distance 0 on the overlap. Then slightly lifted.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-0.8, 0.8);
    TriangleMesh B = height_field(4, [](double, double) { return 0.0; });
    for (double lift : {0.0, 1e-9, 1e-3, 0.2}) {
        for (int i = 0; i < 6; ++i) {
            TriangleMesh A = mesh_of({{U(rng), U(rng), lift}, {U(rng), U(rng), lift}, {U(rng), U(rng), lift}}, {{0, 1, 2}});
            double exact = solve_all_checked(A, B);  // (the thorough validate() holds at lift 1e-3 too now)
            EXPECT_NEAR(exact, lift, 1e-12);
        }
    }
}

TEST(SolverRandom, NearlyDegenerate) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int i = 0; i < 20; ++i) {
        double eps = std::pow(10.0, -2 - (i % 8));
        // A sliver target, nearly parallel sources, a duplicated face, and a sliver source.
        Vec3 a{U(rng), U(rng), 0}, b{U(rng), U(rng), 0};
        Vec3 c = 0.5 * (a + b) + Vec3{eps * U(rng), eps * U(rng), eps};
        TriangleMesh A = mesh_of({a, b, c}, {{0, 1, 2}});
        std::vector<Vec3> p{{-1.5, -1.5, 0.3}, {1.5, -1.5, 0.3 + eps}, {0, 1.5, 0.3 - eps}, {-1.5, -1.5, 0.3}, {1.5, -1.5, 0.3 + eps},
                            {0, 1.5, 0.3 - eps}, {U(rng), U(rng), -0.2}, {U(rng), U(rng), -0.2 + eps}};
        p.push_back(0.5 * (p[6] + p[7]) + Vec3{0, 0, eps});
        TriangleMesh B = mesh_of(p, {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
        double exact = solve_all_checked(A, B);
        expect_between_bounds(A, B, exact, "nearly degenerate");
        double back = solve_all_checked(B, A);
        expect_between_bounds(B, A, back, "nearly degenerate, reversed");
    }
}

// A target with no area (a segment: two of its corners the same point) against 24 sources along
// it (200 in the last four trials: many pieces, so the envelope's bins), two with a corner at its ends: in odd trials points (zero-area triangles, whose distances
// along the segment have no region ends inside it, so the largest value lies where two of them
// cross), in even ones small random triangles, every fourth a sliver. Its maximum
// (degenerate_maximum: piece ends and crossings of the sources' lower envelope, highest bound
// first, dropped once no bound is above the best) is at least the largest of 20,001 brute-force
// distances sampled along the segment and at most that plus half their spacing (d is 1-Lipschitz).
TEST(SolverRandom, SegmentTargetLiesBetweenSamplingAndLipschitz) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int trial = 0; trial < 16; ++trial) {
        const Vec3 a{0, 0, 0}, b{1, 0.3, 0.1};
        const TriangleMesh A = mesh_of({a, b}, {{0, 1, 0}});
        std::vector<Vec3> p;
        std::vector<Tri> t;
        const uint32_t sources = trial < 12 ? 24 : 200;  // many pieces: the envelope's bins (EnvelopeBins)
        for (uint32_t k = 0; k < sources; ++k) {
            const Vec3 c = k < 2 ? (k ? b : a) : a + (0.5 + 0.5 * U(rng)) * (b - a) + Vec3{0.1 * U(rng), 0.1 * U(rng), 0.1 * U(rng)};
            const double size = trial % 2 ? 0.0 : 0.05 + 0.1 * (1 + U(rng)), thin = k % 4 == 0 ? 1e-9 : 1.0;
            const Vec3 u{U(rng), U(rng), U(rng)}, v{U(rng), U(rng), U(rng)};
            p.insert(p.end(), {c, c + size * u, c + size * (u + thin * v)});
            t.push_back({3 * k, 3 * k + 1, 3 * k + 2});
        }
        const TriangleMesh B = mesh_of(p, t);
        VoxelGrid grid(A, B);
        TargetSolver ts(grid, 0, 0);
        ts.run();
        ASSERT_EQ(ts.domain_mesh(), nullptr) << "the target should have no domain mesh";
        const int n = 20000;
        double sampled = 0;
        for (int i = 0; i <= n; ++i) sampled = std::max(sampled, brute_distance(a + (double(i) / n) * (b - a), B));
        const double d = std::sqrt(ts.max_sq()), half_spacing = 0.5 * norm(b - a) / n;
        EXPECT_GE(d, sampled - 1e-12) << "trial " << trial;
        EXPECT_LE(d, sampled + half_spacing + 1e-12) << "trial " << trial;
    }
}

// A segment 9 from a strip of 2,500 slivers on a circle, every one within the search radius, its
// maximum flat: degenerate_maximum ran after every insertion, crossed thousands of pieces whose
// tops rose above the best and evaluated each crossing against every source (minutes; about 1e10
// distance evaluations). The oracle as in Cascade.ThinTargetsAreHalvedNotQuartered: the largest
// distance is (R - cz) cos(theta / 2), below the circle's centre. The count: the envelope's bins
// (257 points a source and edge, as the sources double) and the candidates.
TEST(SolverRandom, SegmentUnderManySliversIsNotCubic) {
    const int n = 2500;
    const double R = 18, cz = 9, span = 2.5 / R, theta = 2 * span / n;
    const TriangleMesh A = mesh_of({{-1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, {{0, 1, 2}});
    const TriangleMesh B = sliver_arc(n, R, cz, span);
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.run();
    ASSERT_EQ(ts.domain_mesh(), nullptr) << "the target should have no domain mesh";
    const double h = (R - cz) * std::cos(theta / 2);
    EXPECT_NEAR(std::sqrt(ts.max_sq()), h, 1e-12 * h);
    EXPECT_LT(ts.distance_evaluations(), 20'000'000u);
}

// ---------------------------------------------------------------- stepping and events

TEST(SolverSteps, EventsInOrderAndStateBetweenSteps) {
    TriangleMesh B = height_field(4, [](double x, double y) { return 0.2 * std::sin(2 * x + y); });
    TriangleMesh A = mesh_of({{-0.5, -0.4, 0.5}, {0.6, -0.3, 0.4}, {0.1, 0.7, 0.6}}, {{0, 1, 2}});
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.record_events();
    double last_radius = HUGE_VAL;
    int steps = 0;
    while (ts.step()) {
        ++steps;
        EXPECT_EQ(ts.validate(), "");
        EXPECT_LE(ts.search_radius(), last_radius * (1 + 1e-12));  // the radius only shrinks
        last_radius = ts.search_radius();
        EXPECT_EQ(ts.insertions(), steps);
    }
    const auto& ev = ts.events();
    ASSERT_FALSE(ev.empty());
    EXPECT_EQ(ev.front().kind, EventKind::TargetBegun);
    EXPECT_EQ(ev.back().kind, EventKind::TargetFinished);
    for (size_t i = 0; i < ev.size(); ++i) EXPECT_EQ(ev[i].step, (long)i);
    // Each chosen source is followed by its regions, and the count matches the insertions.
    int chosen = 0;
    for (size_t i = 0; i < ev.size(); ++i)
        if (ev[i].kind == EventKind::SourceChosen) {
            ++chosen;
            ASSERT_LT(i + 1, ev.size());
            EXPECT_EQ(ev[i + 1].kind, EventKind::RegionsProjected);
            EXPECT_EQ(ev[i + 1].source, ev[i].source);
            EXPECT_EQ(ev[i + 1].regions.size(), 7u);
        }
    EXPECT_EQ(chosen, ts.insertions());
    // Voxels are visited nearest first.
    double last = -1;
    for (const Event& e : ev)
        if (e.kind == EventKind::VoxelVisited) {
            EXPECT_GE(e.distance, last);
            last = e.distance;
        }
    // Stepping by events gives the same stream and the same result.
    TargetSolver again(grid, 0, 0);
    size_t n = 0;
    while (const Event* e = again.step_event()) {
        ASSERT_LT(n, ev.size());
        EXPECT_EQ(e->kind, ev[n].kind);
        ++n;
    }
    EXPECT_EQ(n, ev.size());
    EXPECT_DOUBLE_EQ(again.max_sq(), ts.max_sq());
    // Stepping back by replay: the state after the k-th source_chosen's insertion matches a
    // solver stepped k times.
    for (const Event& e : ev)
        if (e.kind == EventKind::SearchRadiusShrunk) {
            auto back = TargetSolver::replay_to(grid, 0, 0, e.step);
            TargetSolver fwd(grid, 0, 0);
            for (int k = 0; k < e.insertion; ++k) fwd.step();
            EXPECT_EQ(back->insertions(), e.insertion);
            EXPECT_DOUBLE_EQ(back->max_sq(), fwd.max_sq());
            EXPECT_DOUBLE_EQ(back->search_radius(), e.radius);
            EXPECT_EQ(back->domain_mesh()->num_live_faces(), fwd.domain_mesh()->num_live_faces());
        }
    EXPECT_NEAR(std::sqrt(ts.max_sq()), std::sqrt(grid.nearest(1, ts.max_point()).dist2), 1e-12);
}

// A target much smaller than a voxel of the sources' grid, near its middle: the voxels around it
// lie farther than the search radius by the gap between their boxes and the target's box, so the
// search visits only the voxels that box meets (by the distance between voxel indices alone, all
// of its neighbours lie at distance 0 and were visited). The result is unchanged.
TEST(SolverSteps, SmallTargetVisitsOnlyTheVoxelsItsBoxMeets) {
    TriangleMesh B = height_field(4, [](double x, double y) { return 0.2 * std::sin(2 * x + y); });
    VoxelGrid probe_grid(B, B);
    const MeshGrid& g = probe_grid.of(1);
    const size_t mid = g.index(g.nx / 2, g.ny / 2, g.nz / 2);
    const Box3 vb = g.voxel_box(mid);
    const Vec3 c = (vb.lo + vb.hi) * 0.5;
    const Vec3 on = probe_grid.nearest(1, c).point;  // the surface point nearest the voxel's centre
    const double s = 1e-3 * g.voxel_size;
    TriangleMesh A = mesh_of({{on.x, on.y, on.z + s}, {on.x + s, on.y, on.z + s}, {on.x, on.y + s, on.z + s}}, {{0, 1, 2}});
    VoxelGrid grid(A, B);
    const MeshGrid& gb = grid.of(1);
    ASSERT_EQ(gb.voxel_size, g.voxel_size);  // the same grid over B
    TargetSolver ts(grid, 0, 0);
    ts.record_events();
    ts.run();
    int visited = 0;
    for (const Event& e : ts.events()) {
        if (e.kind != EventKind::VoxelVisited) continue;
        ++visited;
        EXPECT_LE(e.distance, ts.search_radius() * (1 + 1e-9));
    }
    // The voxels the target's box meets (at most 8, as it is far smaller than a voxel).
    const auto lo = gb.locate(A.bounds().lo), hi = gb.locate(A.bounds().hi);
    const int meets = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
    EXPECT_LE(visited, meets);
    EXPECT_GE(visited, 1);
    EXPECT_EQ(ts.validate(), "");
    EXPECT_NEAR(std::sqrt(ts.max_sq()), std::sqrt(grid.nearest(1, ts.max_point()).dist2), 1e-12);
    for (const Vec3& p : A.positions) EXPECT_LE(std::sqrt(grid.nearest(1, p).dist2), ts.search_radius() * (1 + 1e-12));
}

// ---------------------------------------------------------------- whole meshes

TEST(Driver, PaperAndFastAgreeAndThreadsDoNotMatter) {
    std::mt19937 rng(17);
    for (int i = 0; i < 4; ++i) {
        TriangleMesh A = height_field(6, [&](double x, double y) { return 0.1 * std::sin(3 * x + i) * std::cos(2 * y); });
        TriangleMesh B = random_triangle_soup(rng, 40, 0.3, {0, 0, 0}, 1.0);
        HausdorffOptions paper, fast1, fast2;
        paper.mode = Mode::Paper;
        fast1.threads = 1;
        fast2.threads = 2;
        HausdorffResult p = hausdorff(A, B, paper), f1 = hausdorff(A, B, fast1), f2 = hausdorff(A, B, fast2);
        for (OneSidedResult HausdorffResult::*side : {&HausdorffResult::a_to_b, &HausdorffResult::b_to_a}) {
            EXPECT_DOUBLE_EQ((p.*side).distance, (f1.*side).distance);
            EXPECT_EQ((p.*side).target, (f1.*side).target);
            EXPECT_DOUBLE_EQ((f1.*side).distance, (f2.*side).distance);
            EXPECT_EQ((f1.*side).target, (f2.*side).target);
            EXPECT_LE((p.*side).lower, (p.*side).distance);
            EXPECT_GE((p.*side).upper, (p.*side).distance);
            EXPECT_LE((p.*side).upper - (p.*side).lower, 1e-9 * std::max(A.bounds().diagonal(), B.bounds().diagonal()));
            EXPECT_LE((f1.*side).exact_targets, (p.*side).exact_targets);
        }
        expect_between_bounds(A, B, p.a_to_b.distance, "mesh a->b");
        expect_between_bounds(B, A, p.b_to_a.distance, "mesh b->a");
        // Every per-target value bounds the maximum over that target from above, and exact ones
        // equal it: check the witness target directly.
        EXPECT_DOUBLE_EQ(p.a_to_b.target_max[p.a_to_b.target], p.a_to_b.distance);
    }
}

TEST(Driver, RealMeshAgainstPerturbedCopy) {
    TriangleMesh A = load_mesh(std::string(HLENS_SHARED_MESHES) + "/spot.obj");
    TriangleMesh B = A;
    // Move every vertex by a deterministic pseudo-random offset of up to 1% of the diagonal.
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> U(-1, 1);
    double diag = A.bounds().diagonal();
    for (Vec3& p : B.positions) p += Vec3{U(rng), U(rng), U(rng)} * (0.01 * diag);
    HausdorffOptions paper, fast;
    paper.mode = Mode::Paper;
    HausdorffResult p = hausdorff(A, B, paper), f = hausdorff(A, B, fast);
    EXPECT_DOUBLE_EQ(p.a_to_b.distance, f.a_to_b.distance);
    EXPECT_DOUBLE_EQ(p.b_to_a.distance, f.b_to_a.distance);
    EXPECT_LT(f.a_to_b.exact_targets, A.num_triangles());  // fast mode skipped most targets
    VoxelGrid grid(A, B);
    LipschitzBound ab = lipschitz_bounds(A, grid, 0, 1e-7 * diag), ba = lipschitz_bounds(B, grid, 1, 1e-7 * diag);
    EXPECT_GE(p.a_to_b.distance, ab.lower - 1e-12 * diag);
    EXPECT_LE(p.a_to_b.distance, ab.upper + 1e-12 * diag);
    EXPECT_GE(p.b_to_a.distance, ba.lower - 1e-12 * diag);
    EXPECT_LE(p.b_to_a.distance, ba.upper + 1e-12 * diag);
    EXPECT_LE(p.a_to_b.upper - p.a_to_b.lower, 1e-9 * diag);
}

TEST(Driver, DistanceToItselfIsZeroOnMessyMeshes) {
    // Every target coincides with a source: coplanar, shared-edge and duplicated configurations
    // everywhere. woody is flat (zero-thickness box), suzanne has quads and a non-manifold edge,
    // beetle has 47 non-manifold edges.
    for (const char* name : {"woody.obj", "suzanne.obj", "beetle.obj"}) {
        SCOPED_TRACE(name);
        TriangleMesh A = load_mesh(std::string(HLENS_SHARED_MESHES) + "/" + name);
        HausdorffResult r = hausdorff(A, A);
        double diag = A.bounds().diagonal();
        EXPECT_LE(r.a_to_b.distance, 1e-12 * diag);
        EXPECT_LE(r.b_to_a.distance, 1e-12 * diag);
        // The top is confirmed by subdivision down to 1e-10 of the diagonal (confirm_top.cpp).
        EXPECT_LE(r.a_to_b.upper, 1e-10 * diag);
    }
}

// The demo pair's B -> A maximum lies where three domains of target 22 meet, and the nearest-first
// run once placed that corner 6e-10 off (a crossing snapped onto a vertex): its value came out
// 1.2e-11 low, below the certified upper end. The referee here is brute force: a local search
// over point distances to every triangle of A, from the reported point, must find nothing
// farther than the upper end, and the reported distance must be the brute-force distance of the
// reported point.
TEST(Driver, CertifiedIntervalHoldsWhereDomainsMeet) {
    const TriangleMesh A = load_mesh(std::string(HLENS_SOURCE_DIR) + "/assets/demo_a.obj");
    const TriangleMesh B = load_mesh(std::string(HLENS_SOURCE_DIR) + "/assets/demo_b.obj");
    for (Mode mode : {Mode::Fast, Mode::Paper}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = hausdorff(A, B, opt).b_to_a;
        const double truth_here = brute_distance(r.from_point, A);
        EXPECT_NEAR(r.distance, truth_here, 1e-15);
        EXPECT_LE(r.lower, truth_here);
        // A local search on the target (8 directions in its plane, steps 1e-5 down to 1e-16).
        const auto c = B.corners(r.target);
        const Vec3 e1 = (c[1] - c[0]) / norm(c[1] - c[0]), n = cross(c[1] - c[0], c[2] - c[0]);
        const Vec3 e2 = cross(n, e1) / norm(cross(n, e1));
        Vec3 p = r.from_point;
        double best = truth_here;
        for (double h = 1e-5; h > 1e-16; h *= 0.5)
            for (bool moved = true; moved;) {
                moved = false;
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy) {
                        const Vec3 q = p + (dx * h) * e1 + (dy * h) * e2;
                        if (closest_point_on_triangle(q, c[0], c[1], c[2]).dist2 > 1e-30) continue;  // off the target
                        const double d = brute_distance(q, A);
                        if (d > best) { best = d; p = q; moved = true; }
                    }
            }
        EXPECT_LE(best, r.upper) << "a point farther than the certified upper end";
        EXPECT_LE(best - r.distance, 1e-13) << "the reported distance is short of a maximum next to it";
        EXPECT_LE(r.upper - r.lower, 1e-9 * (A.bounds().diagonal()));
    }
}

// The confirmation of the top bounds a target over a crease and a coplanar seam of B without
// splitting it down to the tolerance, and finds the maximum when the domain meshes fall short.
// B is an asymmetric valley (slopes 0.3 and 0.7 about x = 0.5, each side two triangles); A one
// tilted triangle reaching just past the crease. The table claims a maximum 1e-7 below the truth.
// The referee: brute-force distances from 66 samples of A, climbed to their local maximum, with
// every point taken relative to A's first corner (so that far from the origin it stays exact).
TEST(ConfirmTop, ClosesOverCreasesAndFindsAMissedMaximum) {
    for (double far : {0.0, 1e6}) {
        SCOPED_TRACE("offset " + std::to_string(far));
        const Vec3 off = Vec3{3, -2, 1} * far;
        auto valley = [](double x) { return x < 0.5 ? 0.3 * (0.5 - x) : 0.7 * (x - 0.5); };
        std::vector<Vec3> bp;
        for (double x : {0.0, 0.5, 1.0})
            for (double y : {0.0, 1.0}) bp.push_back(Vec3{x, y, valley(x)} + off);
        const TriangleMesh B = mesh_of(bp, {{0, 2, 3}, {0, 3, 1}, {2, 4, 5}, {2, 5, 3}});
        auto tilted = [](double x, double y) { return Vec3{x, y, 0.4 + 0.9 * (x - 0.5)}; };
        const TriangleMesh A = mesh_of({tilted(0.2, 0.2) + off, tilted(0.51, 0.5) + off, tilted(0.2, 0.8) + off}, {{0, 1, 2}});
        // The referee, relative to A's corner o.
        const Vec3 o = A.positions[0];
        TriangleMesh Bo = B;
        for (Vec3& p : Bo.positions) p = p - o;
        const Vec3 e1 = A.positions[1] - o, e2 = A.positions[2] - o;
        double truth = 0, bu = 0, bv = 0;
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; i + j <= 10; ++j) {
                const double d = brute_distance((i / 10.0) * e1 + (j / 10.0) * e2, Bo);
                if (d > truth) truth = d, bu = i / 10.0, bv = j / 10.0;
            }
        for (double h = 0.05; h > 1e-15; h *= 0.5)
            for (bool moved = true; moved;) {
                moved = false;
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy) {
                        const double u = bu + dx * h, v = bv + dy * h;
                        if (u < 0 || v < 0 || u + v > 1) continue;
                        const double d = brute_distance(u * e1 + v * e2, Bo);
                        if (d > truth) truth = d, bu = u, bv = v, moved = true;
                    }
            }
        VoxelGrid grid(A, B);
        TargetTable tab;
        tab.resize(1);
        tab.bound[0] = truth - 1e-7;
        const double diag = 1.5, tol = 1e-10 * diag;
        const TopConfirmation top = confirm_top(grid, 0, tab, tab.bound[0], tol, coordinate_magnitude(A, B));
        EXPECT_EQ(top.closed, top.targets);
        EXPECT_EQ(top.closed, 1u);
        EXPECT_LT(top.nodes, 2048u) << "the seams should not need splitting down to the tolerance";
        EXPECT_GE(top.upper, truth);
        EXPECT_LE(top.upper, truth + 2 * tol);
        EXPECT_TRUE(top.raised);
        EXPECT_NEAR(top.value, truth, 1e-13);
    }
}

TEST(Driver, OverlappingCoplanarTriangulations) {
    // Two different triangulations of the same flat square: h = 0 both ways. Then one of them
    // lifted at one interior vertex by 0.3: h(A,B) = 0.3 exactly, at that vertex (d is the
    // height over the plane, largest where A is highest).
    TriangleMesh A = height_field(5, [](double, double) { return 0.0; });
    TriangleMesh B = height_field(3, [](double, double) { return 0.0; });
    HausdorffResult r = hausdorff(A, B);
    EXPECT_LE(r.hausdorff, 1e-14);
    A.positions[2 * 6 + 2].z = 0.3;  // interior vertex (i=2, j=2) of the 5x5 grid
    HausdorffResult s = hausdorff(A, B);
    EXPECT_NEAR(s.a_to_b.distance, 0.3, 1e-14);
    EXPECT_NEAR(s.a_to_b.from_point.z, 0.3, 1e-12);
    expect_between_bounds(A, B, s.a_to_b.distance, "lifted vertex");
    expect_between_bounds(B, A, s.b_to_a.distance, "lifted vertex, reversed");
}

TEST(ExportCase, ReproducesTheTargetsMaximumOnItsOwn) {
    TriangleMesh B = height_field(6, [](double x, double y) { return 0.25 * std::sin(2 * x) * std::cos(3 * y); });
    TriangleMesh A = height_field(3, [](double x, double y) { return 0.3 + 0.1 * x * y; });
    VoxelGrid grid(A, B);
    // Names of this process's own (concurrent runs share the temporary directory), removed after.
    const std::string stem = ::testing::TempDir() + "/hlens_case_" + std::to_string((long)getpid());
    const std::string tpath = stem + "_t.obj", spath = stem + "_s.obj";
    for (uint32_t t : {0u, 7u, 17u}) {
        TargetSolver whole(grid, 0, t);
        whole.run();
        export_case(grid, 0, t, tpath, spath);
        TriangleMesh a = load_mesh(tpath, {false}), b = load_mesh(spath, {false});
        std::remove(tpath.c_str());
        std::remove(spath.c_str());
        EXPECT_EQ(a.num_triangles(), 1u);
        EXPECT_EQ((int)b.num_triangles(), whole.insertions());
        EXPECT_LT(b.num_triangles(), B.num_triangles());  // only the relevant ones
        VoxelGrid g2(a, b);
        TargetSolver alone(g2, 0, 0);
        alone.run();
        EXPECT_NEAR(alone.max_sq(), whole.max_sq(), 1e-12 * whole.max_sq());
    }
}

TEST(Driver, FarFromTheOrigin) {
    // The same pair moved to coordinates around 1e6: rounding of positions grows with them, and
    // fast mode must still solve the targets that hold the result (it once skipped them all).
    std::mt19937 rng(29);
    TriangleMesh A = height_field(6, [](double x, double y) { return 0.2 * std::sin(2 * x + y); });
    TriangleMesh B = random_triangle_soup(rng, 30, 0.4, {0, 0, 0}, 1.0);
    HausdorffResult near = hausdorff(A, B);
    Vec3 shift{1e6, -2e6, 5e5};
    for (Vec3& p : A.positions) p += shift;
    for (Vec3& p : B.positions) p += shift;
    HausdorffOptions paper;
    paper.mode = Mode::Paper;
    HausdorffResult fast = hausdorff(A, B), full = hausdorff(A, B, paper);
    EXPECT_DOUBLE_EQ(fast.a_to_b.distance, full.a_to_b.distance);
    EXPECT_DOUBLE_EQ(fast.b_to_a.distance, full.b_to_a.distance);
    // Positions moved by 1e6 carry rounding of about 1e-10: the distances agree to that.
    EXPECT_NEAR(fast.a_to_b.distance, near.a_to_b.distance, 1e-8);
    EXPECT_NEAR(fast.b_to_a.distance, near.b_to_a.distance, 1e-8);
    EXPECT_GT(fast.b_to_a.distance, 0.1);
    EXPECT_LE(fast.a_to_b.lower, fast.a_to_b.distance);
    EXPECT_GE(fast.a_to_b.upper, fast.a_to_b.distance);
}

// ---------------------------------------------------------------- the domain mesh's kept geometry

// The domain mesh keeps what its geometry queries need (face boxes between edits, each curved
// arc's area against its chord, bulge and turning points): after every insertion of random
// sources, these must agree with the boundary sampled densely (an independent polyline), and the
// kept boxes with freshly computed ones.
TEST(DomainCaches, KeptGeometryMatchesTheSampledBoundary) {
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> U(-1, 1);
    int curved_faces = 0;
    for (int trial = 0; trial < 12; ++trial) {
        std::array<Vec3, 3> tc{Vec3{0, 0, 0}, Vec3{1, 0.1 * U(rng), 0.05 * U(rng)}, Vec3{0.3 * U(rng), 0.9, 0.1 * U(rng)}};
        TargetFrame frame = TargetFrame::make(tc);
        ASSERT_FALSE(frame.degenerate);
        DomainMesh dm(frame.ccw_corners());
        for (int s = 0; s < 14; ++s) {
            Vec3 c{0.4 + 0.5 * U(rng), 0.4 + 0.5 * U(rng), 0.25 * U(rng)};
            std::array<Vec3, 3> sc;
            for (Vec3& p : sc) p = c + Vec3{0.35 * U(rng), 0.35 * U(rng), 0.2 * U(rng)};
            dm.insert(project_source(frame, sc, (uint32_t)s));
            ASSERT_EQ(dm.validate(), "") << "trial " << trial << " source " << s;
            for (size_t f = 1; f < dm.faces().size(); ++f) {
                if (!dm.faces()[f].alive) continue;
                const Box2 kept = dm.cached_face_box((int)f), fresh = dm.face_box((int)f);
                ASSERT_TRUE(kept.lo == fresh.lo && kept.hi == fresh.hi) << "face " << f;
                Box2 sampled;
                std::vector<Vec2> poly;  // the outer loop as a dense polyline
                bool curved = false;
                for (size_t l = 0; l < dm.faces()[f].loops.size(); ++l) {
                    const int start = dm.faces()[f].loops[l];
                    std::vector<Vec2> pts = dm.sample_loop(start, 2000);
                    for (Vec2 p : pts) sampled.add(p);
                    // The loop's area against the shoelace area of the polyline.
                    double shoelace = 0;
                    for (size_t i = 0; i < pts.size(); ++i) shoelace += 0.5 * cross(pts[i], pts[(i + 1) % pts.size()]);
                    EXPECT_NEAR(dm.loop_area(start), shoelace, 1e-6) << "face " << f;
                    if (l == 0) poly = pts;
                    int h = start;
                    do {
                        curved |= !dm.edges()[h >> 1].curve.straight();
                        h = dm.half_edges()[h].next;
                    } while (h != start);
                }
                curved_faces += curved;
                const double tol = 1e-6;
                EXPECT_LE(fresh.lo.x, sampled.lo.x + 1e-12);
                EXPECT_LE(fresh.lo.y, sampled.lo.y + 1e-12);
                EXPECT_GE(fresh.hi.x, sampled.hi.x - 1e-12);
                EXPECT_GE(fresh.hi.y, sampled.hi.y - 1e-12);
                EXPECT_GE(fresh.lo.x, sampled.lo.x - tol);
                EXPECT_GE(fresh.lo.y, sampled.lo.y - tol);
                EXPECT_LE(fresh.hi.x, sampled.hi.x + tol);
                EXPECT_LE(fresh.hi.y, sampled.hi.y + tol);
                // Inside tests against the polyline's crossing parity, away from the boundary
                // (faces with holes are skipped: their polyline would need all loops).
                if (dm.faces()[f].loops.size() != 1) continue;
                for (int k = 0; k < 20; ++k) {
                    Vec2 p{fresh.lo.x + (fresh.hi.x - fresh.lo.x) * (0.5 + 0.5 * U(rng)),
                           fresh.lo.y + (fresh.hi.y - fresh.lo.y) * (0.5 + 0.5 * U(rng))};
                    if (dm.near_boundary((int)f, p, 1e-4)) continue;
                    bool in = false;
                    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
                        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
                            p.x < poly[j].x + (p.y - poly[j].y) / (poly[i].y - poly[j].y) * (poly[i].x - poly[j].x))
                            in = !in;
                    EXPECT_EQ(dm.point_in_face((int)f, p), in) << "face " << f << " at " << p.x << ", " << p.y;
                }
            }
            dm.update_maxima();
        }
    }
    EXPECT_GT(curved_faces, 20);  // conic arcs were exercised
}

// Meshes far apart (README, "One grid per mesh"): a small target far from a fine mesh looks at the
// sources near its search radius, not at all of them, and its answer is still right. With one grid
// over both meshes the fine mesh fell into one voxel and every target scanned every source.
TEST(SolverFarApart, ATargetFarAwayLooksOnlyNearItsSearchRadius) {
    const TriangleMesh fine = height_field(100, [](double x, double y) { return 0.1 * std::sin(3 * x) * y; });
    TriangleMesh small = height_field(2, [](double x, double) { return 0.05 * x; });
    for (Vec3& p : small.positions) p = p * 0.01 + Vec3(300, 200, 100);
    const VoxelGrid grid(small, fine);
    for (uint32_t t = 0; t < small.num_triangles(); ++t) {
        TargetSolver ts(grid, 0, t);
        ts.record_events();
        ts.run();
        size_t looked_at = 0;
        for (const Event& e : ts.events())
            looked_at += e.kind == EventKind::SourceChosen || e.kind == EventKind::SourceCulled;
        // Every source the search looks at lies in a voxel within the search radius of the target:
        // its box is within the radius plus two voxel diagonals of the target's box.
        auto c = small.corners(t);
        Box3 tb;
        for (const Vec3& v : c) tb.add(v);
        const double reach = std::sqrt(ts.max_sq()) + 2 * std::sqrt(3.0) * grid.of(1).voxel_size;
        size_t near = 0;
        for (uint32_t s = 0; s < fine.num_triangles(); ++s) {
            const Box3 sb = fine.triangle_bounds(s);
            double d2 = 0;
            for (int i = 0; i < 3; ++i) {
                const double g = std::max({0.0, sb.lo[i] - tb.hi[i], tb.lo[i] - sb.hi[i]});
                d2 += g * g;
            }
            near += d2 <= reach * reach;
        }
        EXPECT_LE(looked_at, near) << "target " << t;
        EXPECT_LT(near, fine.num_triangles() / 10) << "target " << t << ": the configuration should need few sources";
        // The answer: at least every corner's distance (brute force), at most the largest corner
        // distance plus the target's size (1-Lipschitz).
        double corners = 0, size = 0;
        for (int k = 0; k < 3; ++k) {
            corners = std::max(corners, brute_distance(c[k], fine));
            size = std::max(size, norm(c[k] - c[(k + 1) % 3]));
        }
        EXPECT_GE(std::sqrt(ts.max_sq()), corners * (1 - 1e-12));
        EXPECT_LE(std::sqrt(ts.max_sq()), corners + size);
    }
}

// An open target's bound from its longest edge (confirm_top.cpp, edge_bound) adds the target's
// height: a needle standing on its edge 1 above a plane, its apex 1e-8 higher, is bounded by the
// apex's distance 1 + 1e-8 (by hand: the height above the plane), not by its edge's 1, and by
// no more than the apex's distance plus twice the tolerance; at the origin and 1e6 from it.
// Two boxes stacked (B: separate shells, their shared facet y = -5.5 twice) against their union
// (A, its faces split differently): by hand, the inner facet is min(x - 3.625, 3.875 - x, ...)
// from A, largest, 0.125, along its mid-line x = 3.75 between the two opposite sides, which tie
// there. The confirmation halves the facet, so its sub-triangles' corners lie on that line, where
// d(., T) - d(., U) is 0 exactly: the ridge cut counted only strict sign changes, no piece on the
// line could be cut between the sides, and the upper end stayed 1.2e-4 above the truth
// (generate_pairs6.py "box_stack" 58688). Now corners on the ridge count as its points.
TEST(ConfirmTop, RidgeThroughSubTriangleCornersIsCut) {
    const TriangleMesh A = mesh_of(
        {{3.625, -5.125, 8.0}, {3.625, -5.125, 8.5}, {3.875, -5.125, 8.5}, {3.875, -5.125, 8.0}, {3.625, -5.125, 9.0},
         {3.875, -5.125, 9.0}, {3.625, -5.75, 8.0}, {3.875, -5.75, 8.0}, {3.875, -5.75, 9.0}, {3.625, -5.75, 9.0},
         {3.75, -5.125, 8.0}, {3.75, -5.75, 8.0}, {3.625, -5.4375, 9.0}, {3.875, -5.4375, 9.0}, {3.875, -5.75, 8.5}},
        {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}, {6, 7, 8}, {6, 8, 9}, {0, 10, 11}, {0, 11, 6}, {10, 3, 11}, {3, 7, 11},
         {4, 12, 13}, {4, 13, 5}, {12, 9, 8}, {12, 8, 13}, {0, 6, 9}, {0, 9, 4}, {3, 2, 14}, {3, 14, 7}, {2, 5, 14}, {5, 8, 14}});
    const TriangleMesh B = mesh_of(
        {{3.625, -5.125, 8.0}, {3.625, -5.125, 9.0}, {3.875, -5.125, 8.0}, {3.875, -5.125, 9.0}, {3.625, -5.5, 8.0},
         {3.875, -5.5, 8.0}, {3.625, -5.5, 9.0}, {3.875, -5.5, 9.0}, {3.625, -5.75, 8.0}, {3.875, -5.75, 8.0},
         {3.875, -5.75, 9.0}, {3.625, -5.75, 9.0}},
        {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}, {5, 7, 6}, {0, 2, 4}, {2, 5, 4}, {1, 6, 7}, {1, 7, 3}, {0, 4, 6}, {0, 6, 1},
         {2, 3, 5}, {3, 7, 5}, {4, 6, 7}, {4, 7, 5}, {8, 9, 10}, {8, 10, 11}, {4, 5, 8}, {5, 9, 8}, {6, 11, 10}, {6, 10, 7},
         {4, 8, 11}, {4, 11, 6}, {5, 7, 9}, {7, 10, 9}});
    Box3 box = A.bounds();
    box.add(B.bounds());
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const HausdorffResult r = hausdorff(A, B, opt);
        EXPECT_EQ(r.b_to_a.distance, 0.125);
        EXPECT_LE(r.b_to_a.lower, 0.125);
        EXPECT_GE(r.b_to_a.upper, 0.125);
        EXPECT_LE(r.b_to_a.upper - r.b_to_a.lower, 1e-9 * box.diagonal()) << "upper " << r.b_to_a.upper;
    }
}

TEST(ConfirmTop, LongestEdgeBoundAddsTheHeight) {
    for (double far : {0.0, 1e6}) {
        SCOPED_TRACE("offset " + std::to_string(far));
        const Vec3 off = Vec3{3, -2, 1} * far;
        const double h = 1e-8;
        const TriangleMesh B = make_mesh({off + Vec3{-4, -4, 0}, off + Vec3{4, -4, 0}, off + Vec3{4, 4, 0}, off + Vec3{-4, 4, 0}},
                                         {{0, 1, 2}, {0, 2, 3}});
        const std::array<Vec3, 3> needle{off + Vec3{0, 0, 1}, off + Vec3{1, 0, 1}, off + Vec3{0.5, 0, 1 + h}};
        const MeshGrid g(B);
        const double tol = 1e-10 * 8, truth = 1 + h;
        const double coord = std::max({std::fabs(off.x), std::fabs(off.y), std::fabs(off.z), 4.0});
        const double bound = longest_edge_bound(g, needle, 1.0, tol, coord);
        EXPECT_GE(bound, truth);
        EXPECT_LE(bound, truth + 2 * tol + 1e-15 * coord);
    }
}

// A segment target 2.4e-4 long 1.3e7 from the origin among 13 tiny triangles of B, some of them
// slivers (generate_pairs9.py "sliver_tiny_on_edge" 20192). Its largest distance lies on a ridge
// between two of them, 4.9e-5 away. A world point there is rounded to 7e-12 (an ulp of y), which
// may put it past the ridge: the triangle nearest the rounded point was then taken for every
// segment near the ridge, its distance 2.5e-12 above the other's at the exact points, a hundred
// times the tolerance, and the bound stayed that far above the distance. Oracle: the largest
// brute-force distance (relative to the target's corner: the rounding of the distances, not of
// the coordinates) over samples refined round the best, a lower bound of the truth.
TEST(ConfirmTop, LongestEdgeBoundFarFromTheOriginTakesTheExactNearestTriangle) {
    const TriangleMesh B = make_mesh(
        {{12763136, 42368.000122070312, 0.0007019042932648338}, {12763136, 42368.000122070312,
        0.00070190429326492628}, {12763136, 42368.000122070305, 0.00070190429326484529}, {12763135.999999998,
        42368.000000000247, 0.00070190615952014923}, {12763135.999999998, 42367.999999998385, 0.00070190615952014923},
        {12763135.999999998, 42368.00000000211, 0.000701904296875}, {12763136, 42368.000131706838, 0.000701904296875},
        {12763136, 42368.000131706889, 0.00070190416640455598}, {12763136, 42368.000131706824,
        0.00070190433740742269}, {12763136, 42368.000070053182, 0.000701904296875}, {12763136, 42368.000070053182,
        0.00070190429687563448}, {12763136, 42368.000070053182, 0.00070190429687539313}, {12763136,
        42368.000122070312, 0.000701904296875}, {12763136, 42368.000146996739, 0.00070190429368761171}, {12763136,
        42368.000146996754, 0.0007019042951835634}, {12763136, 42368.000146996754, 0.00070190429708127174}, {12763136,
        42368.000070053182, 0.00070190429687502179}, {12763136, 42368.000244140378, 0.000701904298598161},
        {12763135.999999998, 42368.00024413479, 0.00070190057330786254}, {12763135.999999996, 42368.000244129202,
        0.00070189684801756408}, {12763136, 42368.0000973059, 0.00070190428334136344}, {12763136.000000015,
        42368.000244133174, 0.00070189498364925385}, {12763135.999999985, 42368.000244127586, 0.00070190615952014923},
        {12763135.999999994, 42368.000244135037, 0.00070191919803619385}, {12763136, 42368.000122070312,
        0.00070190429754543788}, {12763136, 42368.000244140625, 0.000701904296875}, {12763135.999999994,
        42368.000244140625, 0.00070190243422985077}, {12763136.000000007, 42368.000070055044, 0.000701904296875},
        {12763135.999999994, 42368.000070051319, 0.00070189684629440308}, {12763135.999999998, 42368.000070056907,
        0.00070190615952014923}},
        {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 12, 12}, {13, 14, 15}, {16, 16, 16}, {17, 18, 19}, {20,
        20, 20}, {21, 22, 23}, {24, 24, 24}, {25, 25, 26}, {27, 28, 29}});
    const MeshGrid g(B);
    const std::array<Vec3, 3> segment{Vec3{12763136, 42368, 0.000701904296875}, Vec3{12763136, 42368.000244140625, 0.000701904296875},
                                      Vec3{12763136, 42368.000070053182, 0.000701904296875}};
    const Vec3 o = segment[0], e = segment[1] - segment[0];
    const TriangleMesh B_o = shifted(B, -1.0 * o);  // B relative to o
    double at = 0, lower = -1;
    const auto sample = [&](double s) {
        if (const double v = brute_distance(s * e, B_o); v > lower) lower = v, at = s;
    };
    for (int k = 0; k <= 1000; ++k) sample(k / 1000.0);
    for (double step = 1e-3 / 8; step > 1e-15; step /= 8) {  // 17 samples round the best, finer each time
        const double from = at;
        for (int k = -8; k <= 8; ++k)
            if (const double s = from + k * step; s >= 0 && s <= 1) sample(s);
    }
    const double tol = 1e-10 * norm(e);
    const double bound = longest_edge_bound(g, segment, lower, tol, 12763136);
    EXPECT_GE(bound, lower);
    EXPECT_LE(bound, lower + 4 * tol) << "above the sampled distance by " << bound - lower;
}

// Needles folded over a triangle at a hub of corners an ulp of the coordinates apart
// (generate_pairs9.py "tiny_coplanar_retri" 9489, B to A, as it was and moved to the origin; the
// hub's corners are multiples of 2^-17 from B's corner there). On B's triangle 0 the distance
// peaks on a ridge between two needles of A running 1.7e3 from the hub, and the corner bound
// cut each piece there between the needle nearest its centre and A's triangle folded under it:
// their bisector passed beside the piece, gave it all back to the needle, and the ridge's cut
// was never tried; the target stayed open and the interval was 9.2e-9 of the diagonal. Oracles:
// the largest brute-force distance over samples of the triangle near the hub, refined round the
// best (a lower bound of the truth, relative to the hub, so exact far from the origin too), at
// most the upper end; at the origin, the brute-force distance of the witness point, at least the
// lower end; the farthest vertex's, at most the distance.
TEST(ConfirmTop, BisectorBesideAPieceGivesWayToTheRidge) {
    const double u = 0x1p-17;
    const Vec3 p0{330.47312927246094, -1437.0382461547852, 786.7590637207031};
    const Vec3 p4{-140.38845825195312, 1095.7558975219727, -326.5758514404297};
    const Vec3 h1 = Vec3{0, -4, 0} * u, h2 = Vec3{1, -1, 4} * u, h3 = Vec3{1, 4, 2} * u, h5 = Vec3{-1, 3, -2} * u,
               h6 = Vec3{-1, -2, -4} * u, h7{0, 0, 0};
    const std::vector<Vec3> a{p0, h1, h2, h3, p4, h5, h6, h7}, b{h7, p0, p4, h6, h1, h2, h3, h5};
    const std::vector<Tri> fa{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {4, 3, 5}, {4, 5, 6}, {4, 6, 1},
                              {4, 1, 7}, {7, 1, 0}, {1, 2, 3}, {1, 3, 5}, {1, 5, 6}, {1, 6, 6}};
    const std::vector<Tri> fb{{0, 1, 2}, {3, 4, 5}, {3, 5, 6}, {3, 6, 7}};
    const TriangleMesh A0 = mesh_of(a, fa), B0 = mesh_of(b, fb);
    // The sampled lower bound, relative to the hub.
    double lower = -1, su = 0, sv = 0;
    const auto sample = [&](double s, double t) {
        if (s < 0 || t < 0) return;
        if (const double d = brute_distance(s * p0 + t * p4, A0); d > lower) lower = d, su = s, sv = t;
    };
    for (int i = 0; i <= 60; ++i)
        for (int j = 0; j <= 60; ++j) sample(i * 2e-9, j * 2e-9);
    for (double step = 2e-9 / 8; step > 1e-17; step /= 8) {
        const double s0 = su, t0 = sv;
        for (int i = -8; i <= 8; ++i)
            for (int j = -8; j <= 8; ++j) sample(s0 + i * step, t0 + j * step);
    }
    double vertices = 0;
    for (const Vec3& p : b) vertices = std::max(vertices, brute_distance(p, A0));
    const Vec3 o{-49157873547.750717, 35546734081.084541, -72692297641.641632};
    for (const Vec3& off : {Vec3{0, 0, 0}, o}) {
        SCOPED_TRACE("offset " + std::to_string(off.x));
        const TriangleMesh A = shifted(A0, off), B = shifted(B0, off);
        Box3 box = A.bounds();
        box.add(B.bounds());
        for (Mode mode : {Mode::Paper, Mode::Fast}) {
            HausdorffOptions opt;
            opt.mode = mode;
            const OneSidedResult r = hausdorff(A, B, opt).b_to_a;
            EXPECT_GE(r.upper, lower);
            EXPECT_GE(r.distance, vertices);
            EXPECT_LE(r.lower, r.distance);
            EXPECT_GE(r.upper, r.distance);
            EXPECT_LE(r.upper - r.lower, 1e-9 * box.diagonal()) << "upper " << r.upper << " lower " << r.lower;
            if (off.x == 0) EXPECT_LE(r.lower, brute_distance(r.from_point, A));
        }
    }
}
