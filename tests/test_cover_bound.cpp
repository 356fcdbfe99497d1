// Tests of the bound over a triangle from the nearly parallel triangles that cover it
// (core/cover_bound.cpp, suite CoverBound). Oracles: heights by hand, brute-force distances.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <hlens/cover_bound.h>
#include <hlens/voxel_grid.h>

#include "test_meshes.h"

using namespace hlens;
using hlens_test::brute_distance;
using hlens_test::mesh_of;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The regular n-gon of radius 1 in z = 0 fanned from its vertex 0: n - 2 long thin triangles that
// all cross the middle (generate_pairs10.py "fan_thin"). `skip`: a triangle left out (a hole).
TriangleMesh rim_fan(int n, int skip = -1) {
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) p.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0});
    std::vector<Tri> t;
    for (int i = 1; i + 1 < n; ++i)
        if (i != skip) t.push_back({0u, uint32_t(i), uint32_t(i + 1)});
    return mesh_of(p, t);
}

double bound_of(const MeshGrid& g, const std::array<Vec3, 3>& q, double goal = 1.0) {
    double slack = 0;
    const double b = cover_bound(g, q[0], {Vec3{}, q[1] - q[0], q[2] - q[0]}, goal, slack);
    EXPECT_GE(slack, 0.0);
    EXPECT_LE(slack, 1e-12);
    return b;
}

// cover_bound over q (relative to o) from the mesh of corners p and triangles t.
double bound_over(const std::vector<Vec3>& p, const std::vector<Tri>& t, const Vec3& o, const std::array<Vec3, 3>& q, double goal,
                  double& slack) {
    const TriangleMesh B = mesh_of(p, t);
    const MeshGrid g(B);
    return cover_bound(g, o, q, goal, slack);
}

// The largest brute-force distance to B over a barycentric grid of q (41 points a side).
double sampled_max(const std::array<Vec3, 3>& q, const TriangleMesh& B) {
    double truth = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; i + j <= 40; ++j)
            truth = std::max(truth, brute_distance(q[0] + (i / 40.0) * (q[1] - q[0]) + (j / 40.0) * (q[2] - q[0]), B));
    return truth;
}

}  // namespace

// A triangle over the middle of the fan crosses dozens of its sources. Seen along its own normal n,
// each point's line meets the plane z = 0 within the disc, at a distance h / |n_z| (h its height):
// largest at the highest corner. The bound is that, plus a strip of rounding.
TEST(CoverBound, ATriangleOverAFanIsBoundedByItsHeightAlongItsNormal) {
    const TriangleMesh B = rim_fan(200);
    const MeshGrid g(B);
    const std::array<Vec3, 3> q{Vec3{-0.3, -0.2, 0.001}, Vec3{0.4, -0.1, 0.002}, Vec3{0.0, 0.35, 0.003}};
    const Vec3 n = cross(q[1] - q[0], q[2] - q[0]);
    const double expect = 0.003 / (std::fabs(n.z) / norm(n));
    const double b = bound_of(g, q);
    EXPECT_GE(b, expect);
    EXPECT_LE(b, expect + 1e-12);
    // The goal drops every source whose own bound is above it: none is left to cover q.
    EXPECT_EQ(bound_of(g, q, 0.5 * expect), HUGE_VAL);
}

// Where the union does not cover the triangle, there is no bound: past the rim, over a hole. (The
// goal, 0.01, is below q's height over its longest edge, 0.5: else the thin bound, at least that
// height, would be tried, and a bound of 0.504 from a thin triangle on that edge is one. And the
// sources grown by a quarter of the room it leaves, 0.0017, cover neither the 0.02 past the rim
// nor the hole, 0.016 wide where q crosses it: ACrackNarrowerThanTheGoalIsBridgedByItsNeighboursGrown.)
TEST(CoverBound, NoBoundWhereTheSourcesLeaveAGap) {
    const std::array<Vec3, 3> q{Vec3{-0.3, -0.2, 0.001}, Vec3{0.4, -0.1, 0.002}, Vec3{0.0, 0.35, 0.003}};
    const double goal = 0.01;
    {
        const TriangleMesh B = rim_fan(200);
        const MeshGrid g(B);
        ASSERT_LT(bound_of(g, q, goal), goal);
        EXPECT_EQ(bound_of(g, {q[0], q[1], Vec3{0.0, 1.02, 0.003}}, goal), HUGE_VAL);  // a corner past the rim
    }
    // The fan's triangle 100 runs from vertex 0 at (1, 0) to the far side, across the middle.
    const TriangleMesh B = rim_fan(200, 100);
    const MeshGrid g(B);
    EXPECT_EQ(bound_of(g, q, goal), HUGE_VAL);
}

// Two triangulations of one square overlap: no edge but the two diagonals has triangles on both
// sides, and those are inside the union. A triangle inside the square is covered; one that crosses
// its side by 0.1 is not (the goal 0.05 lets the sources grow by 0.01 at most).
TEST(CoverBound, OverlappingTriangulationsCoverTheirSquare) {
    const TriangleMesh B = mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}});
    const MeshGrid g(B);
    const double b = bound_of(g, {Vec3{0.1, 0.1, 0.01}, Vec3{0.9, 0.2, 0.01}, Vec3{0.3, 0.9, 0.01}});
    EXPECT_GE(b, 0.01);
    EXPECT_LE(b, 0.01 + 1e-12);
    EXPECT_EQ(bound_of(g, {Vec3{0.1, 0.1, 0.01}, Vec3{1.1, 0.2, 0.01}, Vec3{0.3, 0.9, 0.01}}, 0.05), HUGE_VAL);
}

// Soundness against brute force: fans whose vertices are lifted at random (the sources not
// coplanar), every third with slivers (rim vertices 1e-9 to 1e-13 from the one before: sources
// whose planes rounding tilts), every third of the others with folds (a rim vertex moved back past
// the one before it, up to a third of the way to the one before that: its two triangles overlap
// their neighbours, and a gap may open), triangles at random over them; wherever a bound is given,
// no point of the triangle (a dense grid of barycentric samples) is farther from the fan than it.
TEST(CoverBound, NeverBelowTheDistanceAnywhereOnTheTriangle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    int bounded = 0, folded = 0;
    for (int trial = 0; trial < 180; ++trial) {
        TriangleMesh B = rim_fan(12 + trial / 2);
        for (Vec3& p : B.positions) p.z = 0.05 * U(rng);
        if (trial % 3 == 0)
            for (size_t i = 2; i + 1 < B.positions.size(); i += 3) {
                const Vec3 step = B.positions[i + 1] - B.positions[i];
                B.positions[i + 1] = B.positions[i] + std::pow(10.0, -9 - 4 * (0.5 + 0.5 * U(rng))) * step / norm(step);
            }
        const bool fold = trial % 3 == 1;
        if (fold)
            for (size_t i = 3; i + 1 < B.positions.size(); i += 4) {
                const Vec3 back = B.positions[i - 1] - B.positions[i];
                B.positions[i] = B.positions[i] + (1 + 0.33 * (0.5 + 0.5 * U(rng))) * Vec3{back.x, back.y, 0};
            }
        const MeshGrid g(B);
        std::array<Vec3, 3> q;
        const double reach = trial % 2 ? 0.6 : 0.9;  // 0.9: often past the rim, where coverage decides
        for (Vec3& c : q) c = {reach * U(rng), reach * U(rng), 0.1 * U(rng)};
        const double b = bound_of(g, q);
        if (!(b < HUGE_VAL)) continue;
        ++bounded;
        folded += fold;
        const double truth = sampled_max(q, B);
        EXPECT_GE(b, truth) << "trial " << trial;
    }
    EXPECT_GE(bounded, 60) << "too few triangles bounded for the test to mean much";
    EXPECT_GE(folded, 15) << "too few over folds";
}

// A needle at height h over the fan, along the edge from vertex 0 to vertex 100 (the x axis) or
// beside it. Its line along the normal meets z = 0 within the disc everywhere, so d <= h; the
// bound is h but for rounding. The union's cover is only certain on the needle shrunk by its
// rounding, whose tip lies that over sin(angle / 2) inside (5e-7 here): the tip is bounded by the
// one source nearest it instead (by convexity), at most h plus the needle's width there.
TEST(CoverBound, ANeedleOverAFanIsBoundedByItsHeightToTheTip) {
    const TriangleMesh B = rim_fan(200);
    const MeshGrid g(B);
    const double h = 0.002;
    for (double y : {0.0, 0.013})
        for (double w : {1e-8, 1e-11}) {
            const std::array<Vec3, 3> q{Vec3{-0.3, y, h}, Vec3{0.3, y + w, h}, Vec3{0.3, y - w, h}};
            const double b = bound_of(g, q);
            EXPECT_GE(b, h) << y << " " << w;
            EXPECT_LE(b, h + 1e-12) << y << " " << w;
        }
}

// A segment (a degenerate target's piece: two corners the same point) and a needle 1e-13 wide,
// whose normal's rounding is 0.03, at height h over the fan: seen along the plane of the fan's
// best-shaped triangle near them, a triangle 1e-4 wide on the segment is covered, and the bound is
// h but for rounding (and, for the needle, its width).
TEST(CoverBound, ASegmentOverAFanIsBoundedByItsHeight) {
    const TriangleMesh B = rim_fan(200);
    const MeshGrid g(B);
    const double h = 0.002;
    for (double w : {0.0, 1e-13}) {
        const std::array<Vec3, 3> q{Vec3{-0.3, 0.013, h}, Vec3{0.3, 0.013 + w, h}, Vec3{0.3, 0.013, h}};
        const double b = bound_of(g, q);
        EXPECT_GE(b, h) << w;
        EXPECT_LE(b, h + 1e-12) << w;
    }
}

// Soundness of the tips' and thin pieces' bounds against brute force: needles (widths 1e-6 to 1e-11,
// 1e-13, or 0: segments) over the lifted
// fans of NeverBelowTheDistanceAnywhereOnTheTriangle: at random, along a spoke (an edge from vertex
// 0: the tip lies on the seam between two sources), or over a flat fan 1e-7 below with the tip past
// the rim by up to 1e-7 (where the union does not reach and only the tip's own bound holds it);
// wherever a bound is given, no point of the needle (the tip and a dense grid of barycentric
// samples) is farther from the fan than it.
TEST(CoverBound, NeedlesAreNeverBoundedBelowTheDistance) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    int bounded[3] = {0, 0, 0};
    for (int trial = 0; trial < 150; ++trial) {
        const int kind = trial % 3;
        TriangleMesh B = rim_fan(12 + trial / 2);
        if (kind < 2)
            for (Vec3& p : B.positions) p.z = 0.01 * U(rng);
        const MeshGrid g(B);
        Vec3 tip{0.5 * U(rng), 0.5 * U(rng), 0.02 + 0.01 * U(rng)}, dir{U(rng), U(rng), 0};
        if (kind == 1) {  // along the spoke from vertex 0 to rim vertex k
            const Vec3 k = B.positions[1 + (trial * 7) % (B.positions.size() - 1)];
            tip = B.positions[0] + (0.3 + 0.2 * U(rng)) * (k - B.positions[0]) + Vec3{0, 0, tip.z};
            dir = k - B.positions[0];
        } else if (kind == 2) {  // past the rim's edge from vertex k to k + 1, pointing inwards
            const size_t k = 1 + trial % (B.positions.size() - 2);
            const Vec3 a = B.positions[k], b = B.positions[k + 1], m = a + (0.5 + 0.4 * U(rng)) * (b - a);
            tip = m + std::pow(10.0, -9 - 2 * U(rng)) * m / norm(m) + Vec3{0, 0, 1e-7};
            dir = -1.0 * m + Vec3{0.3 * U(rng), 0.3 * U(rng), 0};
        }
        dir = dir / norm(dir);
        const Vec3 side{-dir.y, dir.x, 0};
        // Every fifth a segment (two corners the same point) or a needle 1e-13 wide: no normal of
        // its own to be seen along (thin_cover_bound).
        const double len = 0.2 + 0.1 * U(rng), w = trial % 5 == 4 ? (trial % 10 == 4 ? 0.0 : 1e-13) : std::pow(10.0, -8.5 + 2.5 * U(rng));
        const std::array<Vec3, 3> q{tip, tip + len * dir + w * side + Vec3{0, 0, 0.5 * w * U(rng)}, tip + len * dir - w * side};
        const double b = bound_of(g, q);
        if (!(b < HUGE_VAL)) continue;
        ++bounded[kind];
        double truth = 0;
        for (int i = 0; i <= 400; ++i)
            for (int j = 0; i + j <= 400; j += 20)
                truth = std::max(truth, brute_distance(q[0] + (i / 400.0) * (q[1] - q[0]) + (j / 400.0) * (q[2] - q[0]), B));
        EXPECT_GE(b, truth) << "trial " << trial << " kind " << kind;
    }
    for (int kind = 0; kind < 3; ++kind) EXPECT_GE(bounded[kind], 10) << "kind " << kind << ": too few needles bounded for the test to mean much";
}

// A triangle of B folded over its neighbour (generate_pairs9.py "tiny_coplanar_retri" 7793: needles
// from a corner to a hub of rounding-sized triangles, one folded by the hub's rounding). The
// unit square at z = 0: P Q O, the fold O Q X with X inside P Q O (just past the diagonal O Q), then
// O X R and X Q R. Seen from above, O Q has P Q O and the fold on one side, O X has the fold and
// O X R, Q X the fold and X Q R: no source on the other side of any of them, but O X R covers O Q,
// and P Q O covers O X and Q X. A triangle at height h across O Q and O X is covered: d <= h, and
// the bound is h but for rounding.
TEST(CoverBound, ATriangleFoldedOverItsNeighbourIsCoveredByTheOthers) {
    const Vec3 O{0, 0, 0}, P{1, 0, 0}, Q{1, 1, 0}, R{0, 1, 0}, X{0.999, 0.998, 0};
    const TriangleMesh B = mesh_of({O, P, Q, R, X}, {{1, 2, 0}, {0, 2, 4}, {0, 4, 3}, {4, 2, 3}});
    const MeshGrid g(B);
    const double h = 0.002;
    const std::array<Vec3, 3> q{Vec3{0.3, 0.1, h}, Vec3{0.99, 0.995, h}, Vec3{0.1, 0.6, h}};
    const double b = bound_of(g, q);
    EXPECT_GE(b, h);
    EXPECT_LE(b, h + 1e-12);
    const double truth = sampled_max(q, B);  // brute force over the triangle (h everywhere: B covers it)
    EXPECT_NEAR(truth, h, 1e-15);
    // Past the square's side (by 0.01, where the goal 0.01 lets the sources grow by 0.002) the fold
    // covers nothing: no bound.
    EXPECT_EQ(bound_of(g, {q[0], Vec3{1.01, 0.995, h}, q[2]}, 0.01), HUGE_VAL);
}

// A piece 1e-10 across of a target 1 across, over a fan of needles 2 long and 1e-9 wide at their
// rim (generate_pairs9.py "tiny_coplanar_retri" 7793), all in one plane turned at random. The
// piece's corners are known to an ulp of the target's size, so its own normal is off by about 1e-6:
// seen along it, the needles' far corners lie that far off its plane. Seen along the target's
// normal (cover_bound's `whole`), each is within rounding, and the bound is the strip of rounding
// along the piece's sides (2^-46 of the needles' reach, 3e-14). Along the piece's own normal, each
// needle's part over the piece (ANeedleSourceIsBoundedByItsPartOverTheTarget) is within 1e-6 of
// 1e-10 of it: bounded too, and as sound.
TEST(CoverBound, APieceIsSeenAlongItsTargetsNormal) {
    const double a = 0.7, c = std::cos(a), s = std::sin(a);
    const Vec3 axis = Vec3{1, 2, 3} / norm(Vec3{1, 2, 3});
    const auto turn = [&](const Vec3& v) {  // Rodrigues' rotation about axis by a
        return c * v + s * cross(axis, v) + (1 - c) * dot(axis, v) * axis;
    };
    std::vector<Vec3> p{turn(Vec3{-1, 0, 0})};
    std::vector<Tri> t;
    for (int k = 0; k <= 100; ++k) {
        p.push_back(turn(Vec3{1, (k - 50) * 1e-9, 0}));
        if (k > 0) t.push_back({0u, uint32_t(k), uint32_t(k + 1)});
    }
    const TriangleMesh B = mesh_of(p, t);
    const MeshGrid g(B);
    const Vec3 o = turn(Vec3{-0.5, -0.3, 0});
    const std::array<Vec3, 3> whole{Vec3{0, 0, 0}, turn(Vec3{0.5, -0.2, 0}) - o, turn(Vec3{0.0, 0.6, 0}) - o};
    const auto at = [&](double u, double v) { return u * whole[1] + v * whole[2]; };
    // (u, v) of the plane's point (0, 0): -0.5 + 1.0 u + 0.5 v = 0 and -0.3 + 0.1 u + 0.9 v = 0.
    const double u0 = (0.45 - 0.15) / (0.9 - 0.05), v0 = (0.3 - 0.1 * u0) / 0.9;
    const std::array<Vec3, 3> piece{at(u0, v0), at(u0 + 1e-10, v0), at(u0, v0 + 1e-10)};
    const double goal = 1e-12;
    double slack = 0;
    const double b = cover_bound(g, o, piece, goal, slack, &whole);
    EXPECT_LE(b, 1e-13);
    for (const Vec3& x : piece) EXPECT_GE(b + slack, brute_distance(o + x, B) - 1e-15);
    const double own = cover_bound(g, o, piece, goal, slack);
    EXPECT_LE(own, goal);
    for (const Vec3& x : piece) EXPECT_GE(own + slack, brute_distance(o + x, B) - 1e-15);
}

// A strip 0.0112 high and 1e5 long, fanned from one corner (generate_pairs6.py "sliver_strip"
// 63741): the middle triangle, 9 28 29, is 0.015 wide at its top and 8e4 long, so where q crosses
// it, it is 1e-9 thin, below the projected corners' rounding seen from o, 1.9e5 away (its doubled
// area 1.7e-4, where a few ulps of the corners' magnitude times its edges is 4.3e-4). Its
// orientation is still certain from its normal (the edges' cross product, 1.7e-4 against its
// rounding, a few ulps of their product, 6.4e9: 1e-6). Left out, it left a gap between its two
// neighbours, whose edges then bounded their union across q. q lies in the strip's plane: d = 0
// over it, and the bound is the rounding strip along q's sides (2^-46 of 1.9e5 over the sine of
// half its sharpest angle, 0.2), under the goal of 1e-6 of the real pair's tolerance.
TEST(CoverBound, ASliverThinnerThanItsRoundingStillJoinsItsNeighbours) {
    const double H = 1540096.0 - 1540095.9888099348;
    const double x9 = -270812.5409335791, x10 = -355961.57222346356;
    const double x27 = -334159.2176228259, x28 = -350890.86722086696, x29 = -350890.8823553009;
    const std::vector<Vec3> p{{x9, 0, 0}, {x10, 0, 0}, {x27, H, 0}, {x28, H, 0}, {x29, H, 0}};
    const Vec3 o{-163840.0, 0, 0};
    // q around the sliver's middle, where its sides run at y = H / 2 (to 1e-9 over q), below the
    // union's side 9 27, at y = 0.63 H there.
    const double xs = 0.5 * (x9 + 0.5 * (x28 + x29));
    const std::array<Vec3, 3> q{Vec3{xs - 0.01, 0.35 * H, 0} - o, Vec3{xs + 0.01, 0.35 * H, 0} - o, Vec3{xs, 0.6 * H, 0} - o};
    const double goal = 1e-6;
    const std::vector<Tri> fan{{0, 3, 2}, {0, 4, 3}, {0, 1, 4}};
    double slack = 0;
    const double b = bound_over(p, fan, o, q, goal, slack);
    EXPECT_LE(b, 2e-8);
    EXPECT_LE(slack, 5e-8);  // 512 ulps of the corners' magnitude, 1.9e5
    EXPECT_GE(b + slack, sampled_max({o + q[0], o + q[1], o + q[2]}, mesh_of(p, fan)));
    // Without the sliver, its neighbours leave a gap 1e-9 wide across q, bridged only by growing
    // them by a share of the goal (ACrackNarrowerThanTheGoalIsBridgedByItsNeighboursGrown): a
    // looser bound, still above the distance.
    double gap_slack = 0;
    const double gap = bound_over(p, {fan[0], fan[2]}, o, q, goal, gap_slack);
    EXPECT_GT(gap, 2e-8);
    EXPECT_GE(gap + gap_slack, sampled_max({o + q[0], o + q[1], o + q[2]}, mesh_of(p, {fan[0], fan[2]})));
}

// Sources in z = 0 fanned from (0, -0.011): a needle 2e-10 wide at y = 0.0005 between two
// well-shaped triangles (generate_pairs6.py "sliver_strip" 65109). The target is a needle along x,
// 1e-9 wide, one corner 1e-18 above the plane (a corner's rounding): its plane is tilted 1e-9 rad
// about x. q, a piece of it 2e-12 high, is seen along that normal (and its own, the same): the
// needle source's corners, 0.011 away along y, seem 1.1e-11 off q, above the goal of 5e-12, and
// the needle's own plane is no better known, so it was left out and its neighbours' edges bound
// the union across q. Seen along a well-shaped neighbour's normal (the thin bound), every source
// is within rounding of q, and the bound is q's height (a point of q lies within it of q's
// longest edge), 2e-12; the needle's part over q (along_normal_near) is within rounding of q
// too, and gives a bound of rounding size. Either is at most the goal and above the distance.
TEST(CoverBound, APieceThinnerThanTheGoalIsSeenAlongAWellShapedSourcesNormal) {
    const std::vector<Vec3> p{{0, -0.011, 0}, {-1e-10, 0.0005, 0}, {1e-10, 0.0005, 0}, {-0.01, 0.0005, 0}, {0.01, 0.0005, 0}};
    const TriangleMesh B = mesh_of(p, {{0, 1, 3}, {0, 2, 1}, {0, 4, 2}});
    const MeshGrid g(B);
    const Vec3 o{-0.005, 0, 0};
    const std::array<Vec3, 3> whole{Vec3{0, 0, 0}, Vec3{0.01, 0, 0}, Vec3{0.01, 1e-9, 1e-18}};
    const auto at = [&](double x, double y) { return Vec3{x, y, y * 1e-9} - o; };  // on the target's plane
    const std::array<Vec3, 3> q{at(-5e-10, 1e-12), at(5e-10, 1e-12), at(0, 3e-12)};
    const double goal = 5e-12;
    double slack = 0;
    const double b = cover_bound(g, o, q, goal, slack, &whole);
    EXPECT_LE(b, goal);
    EXPECT_LE(slack, 1e-14);  // 512 ulps of the corners' magnitude, 0.015
    EXPECT_GE(b + slack, sampled_max({o + q[0], o + q[1], o + q[2]}, B));
}

// A fan in the plane x = 0 from the origin to points along y = -0.049 (generate_pairs6.py
// "sliver_strip" 65541): its second triangle is a sliver 9.4e-12 wide at its base and 12.8 long.
// Its projection is below its rounding (doubled area 4.6e-13, a few ulps of its corners' magnitude
// times its edges 4.6e-12), and so is a few ulps of its edges' product, 163; but its normal's
// component along x is a difference of two products of 0.63 each, off by a few ulps of those,
// 1e-16: its orientation is certain, and it joins its neighbours. q lies in the fan's plane, so
// d = 0 over it; the bound is the rounding strip along its sides (2^-46 of 12.8 over the sine of
// half its sharpest angle, 0.05).
TEST(CoverBound, ASliverIsOrientedByItsNormalsOwnRounding) {
    const double y = -0.04925754008876261;
    const std::vector<Vec3> p{{0, 0, 0}, {0, y, 0}, {0, y, 12.768302425705942}, {0, y, 12.76830242571532}, {0, y, 12.768339388113969},
                              {0, y, 14.737599864705965}};
    const Vec3 o{0, 0, 0};
    const double zs = 12.768302425705942 * (0.0492 / -y);  // the sliver's sides at y = -0.0492
    const std::array<Vec3, 3> q{Vec3{0, -0.0492, zs - 1e-3}, Vec3{0, -0.0492, zs + 1e-3}, Vec3{0, -0.0491, zs}};
    const double goal = 1e-9;
    const std::vector<Tri> fan{{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}};
    double slack = 0;
    const double b = bound_over(p, fan, o, q, goal, slack);
    EXPECT_LE(b, 1e-11);
    EXPECT_LE(slack, 1e-11);  // 512 ulps of the corners' magnitude, 14.7
    EXPECT_GE(b + slack, sampled_max(q, mesh_of(p, fan)));
    // Without the sliver, its neighbours leave a gap 9e-12 wide across q, bridged only by growing
    // them by a share of the goal: a looser bound, still above the distance.
    double gap_slack = 0;
    const double gap = bound_over(p, {fan[0], fan[2], fan[3]}, o, q, goal, gap_slack);
    EXPECT_GT(gap, 1e-11);
    EXPECT_GE(gap + gap_slack, sampled_max(q, mesh_of(p, {fan[0], fan[2], fan[3]})));
}

// Two triangles in z = 0 meant to share the edge x = 0 from the origin to (0, 1), the second's
// copy of its top corner c = 1e-12 off (generate_pairs11.py "slivers_strip" 20035: two corners of
// B 7e-9 apart where one was meant, 5e7 from the origin; the target stayed open, its interval
// 6.6e-6 of the diagonal). The crack, up to c wide, is a boundary of the union across q, at height
// h: grown by a share of the room the goal leaves, the two triangles cover q's projection, and the
// bound is h plus that growth, at most the goal; the distance over q, h to within c, lies below.
TEST(CoverBound, ACrackNarrowerThanTheGoalIsBridgedByItsNeighboursGrown) {
    const double c = 1e-12, h = 1e-3, goal = 2e-3;
    const std::vector<Vec3> p{{0, 0, 0}, {0, 1, 0}, {c, 1, 0}, {-1, 0.5, 0}, {1, 0.5, 0}};
    const std::vector<Tri> two{{3, 0, 1}, {0, 4, 2}};
    const std::array<Vec3, 3> q{Vec3{-0.1, 0.45, h}, Vec3{0.1, 0.45, h}, Vec3{0, 0.6, h}};
    double slack = 0;
    const double b = bound_over(p, two, {0, 0, 0}, q, goal, slack);
    EXPECT_GE(b, h);
    EXPECT_LE(b, goal);
    EXPECT_GE(b + slack, sampled_max(q, mesh_of(p, two)));
}

// A gap is not a crack because its edges lie near other triangles: a thin triangle T overlapping
// the left one A reaches e = 1e-6 past A's side x = 0, within the growth (a quarter of the goal,
// 2.5e-5) of A, but the right triangle C starts at x = 1e-3. Grown, A and T still end at
// x = e + 2.5e-5 < 1e-3: q, in their plane and across the gap, has points 5e-4 from B, above the
// goal, and gets no bound at all.
TEST(CoverBound, AGapWiderThanTheGoalIsNotBridgedByOverlappingTriangles) {
    const double e = 1e-6, G = 1e-3, goal = 1e-4;
    const std::vector<Vec3> p{{-1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {-0.5, 0, 0}, {e, 0, 0}, {e, 1, 0}, {G, 0, 0}, {G + 1, 0, 0}, {G, 1, 0}};
    const std::vector<Tri> three{{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    const std::array<Vec3, 3> q{Vec3{-0.3, 0.3, 0}, Vec3{G + 0.3, 0.3, 0}, Vec3{G / 2, 0.6, 0}};
    ASSERT_GT(sampled_max(q, mesh_of(p, three)), goal);
    double slack = 0;
    EXPECT_EQ(bound_over(p, three, {0, 0, 0}, q, goal, slack), HUGE_VAL);
    // With C moved to x = 1e-5, inside the growth, the gap is a crack: bounded, above the distance.
    std::vector<Vec3> near = p;
    for (int i = 6; i < 9; ++i) near[i].x -= G - 1e-5;
    const std::array<Vec3, 3> qn{Vec3{-0.3, 0.3, 0}, Vec3{0.3, 0.3, 0}, Vec3{0, 0.6, 0}};
    const double b = bound_over(near, three, {0, 0, 0}, qn, goal, slack);
    EXPECT_LE(b, goal);
    EXPECT_GE(b + slack, sampled_max(qn, mesh_of(near, three)));
}

// A needle source far longer than q (generate_pairs11.py "slivers_strip" 20287): a fan in z = 0
// from the origin, its middle triangle 7e-9 wide at y = 1, between two well-shaped ones. q, 3e-6
// across the needle at y = 2/3 and h = 1e-11 above it, is tilted 1e-8 rad about x (a target
// normal tilted by its corners' rounding): seen along its normal, the needle's far corners seem
// 1e-8 * 2/3 off q, and the needle's own plane is uncertain by 5e-7 rad (a few ulps over its
// doubled area, 7e-9). Left out, it would leave a gap 4.7e-9 wide, above the goal. Its part over q
// (clipped to the prism over q) is within 3e-14 of q's plane: kept, and the bound is about h.
TEST(CoverBound, ANeedleSourceIsBoundedByItsPartOverTheTarget) {
    const double w = 7e-9, h = 1e-11, y = 2.0 / 3.0, goal = 8e-11;
    const std::vector<Vec3> p{{0, 0, 0}, {-0.5, 1, 0}, {0, 1, 0}, {w, 1, 0}, {0.5, 1, 0}};
    const std::vector<Tri> fan{{0, 2, 1}, {0, 3, 2}, {0, 4, 3}};
    const auto at = [&](double x, double dy) { return Vec3{x, y + dy, h + 1e-8 * dy}; };
    const std::array<Vec3, 3> q{at(-1.5e-6, -1e-6), at(1.5e-6, -1e-6), at(0, 2e-6)};
    double slack = 0;
    const double b = bound_over(p, fan, {0, 0, 0}, q, goal, slack);
    EXPECT_GE(b, h * (1 - 1e-3));
    EXPECT_LE(b, goal);
    EXPECT_GE(b + slack, sampled_max(q, mesh_of(p, fan)));
}
