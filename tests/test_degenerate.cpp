// The degenerate stress suite (issue 8): random degenerate pairs (tests/degenerate_pairs.h). On the
// first, middle and last target of A in each, after every insertion: TargetSolver::validate()
// (the domain mesh's invariants; each domain's polynomial against direct distances at several
// points; its label's quadratic equal to the polynomial; the points inside the label's region or a
// tied feature's) and the independent nearest-feature map (label_check.h) with no disagreement.
// Per pair: paper = fast, the result above the farthest vertex distance and above a sampling lower
// bound, both computed here by brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <hlens/cascade.h>
#include <hlens/hausdorff.h>
#include <hlens/label_check.h>
#include <hlens/mesh_io.h>
#include <hlens/point_triangle.h>
#include <hlens/regions.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>

#include "degenerate_pairs.h"

using namespace hlens;
using namespace hlens_test;

namespace {

// Seeds 0 .. kPairs-1 (HLENS_DEGENERATE_PAIRS overrides, for longer runs by hand).
int pair_count() {
    const char* s = std::getenv("HLENS_DEGENERATE_PAIRS");
    return s ? std::atoi(s) : 200;
}

// Known failures, left in the open: none. 77 failed until a short
// chord across a corner or a spike of the face was kept (domain_split.cpp); on 3000 seeds, 308 and
// 2528 (overlapping coplanar, 1e10 from the origin) until a line pair's centre near a corner was
// that corner, 1373, 2003 and 2463 (perpendicular) until a nearly flat parabola kept both arms
// (conic.cpp). Any failing seed listed here is reported, any other fails the test.
const std::vector<int> kKnownFailures = {};
// Seeds beyond CI's first pair_count() that once failed, run as well in the two checks of every
// insertion and of the end (3000 seeds take several minutes; these few, seconds).
const std::vector<int> kRegressionSeeds = {308, 1373, 2003, 2463, 2528,
                                           // thin conics' feet (conic.cpp, feet) and the chords
                                           // they end: each failed one version of that rule
                                           78, 325, 367, 472, 548, 2065, 2245, 2325, 2978};
bool known_failure(int seed) { return std::find(kKnownFailures.begin(), kKnownFailures.end(), seed) != kKnownFailures.end(); }

std::vector<std::array<Vec3, 3>> inserted_corners(const TargetSolver& ts) {
    std::vector<std::array<Vec3, 3>> out;
    for (uint32_t s : ts.inserted_sources()) out.push_back(ts.source_corners(s));
    return out;
}

// The polynomial of the domain at p against d^2 there, evaluated directly: to `rel` relative.
void expect_polynomial_is_d2(const TargetSolver& ts, Vec2 p, double rel) {
    const int f = ts.domain_mesh()->face_at(p);
    ASSERT_GT(f, 0) << p.x << " " << p.y;
    const double d2 = ts.direct_d2(p);
    EXPECT_NEAR(ts.domain_mesh()->faces()[f].poly(p), d2, rel * d2) << p.x << " " << p.y;
}

// Target 0 of A against B in the paper's order, nearest first, and as the debugger builds it
// (watched: every cut made), validate() after every insertion; then `probe(ts)` on the finished
// construction. `to_the_end`: an invalid step does not end the construction, so that the probe,
// an oracle of its own, sees what validate() saw (for a fault that leaves the mesh sound).
template <class Probe>
void expect_constructions_hold(const TriangleMesh& A, const TriangleMesh& B, Probe&& probe, bool to_the_end = false) {
    const VoxelGrid grid(A, B, 1.0, 1);
    for (int order = 0; order < 3; ++order) {
        SCOPED_TRACE(order == 0 ? "the paper's order" : order == 1 ? "nearest first" : "the debugger's");
        TargetSolver ts(grid, 0, 0);
        if (order == 1) ts.nearest_first();
        if (order == 2) ts.on_event([](const Event&) {});
        // Otherwise the first invalid step ends this construction, unprobed: on a corrupt mesh the
        // next step, or the probe, may never finish (generate_pairs4.py 15711's loop edge).
        bool valid = true;
        for (int steps = 0; (valid || to_the_end) && ts.step(); ++steps) {
            const std::string v = ts.validate(true);
            EXPECT_EQ(v, "") << ts.insertions() << " insertions";
            valid = valid && v.empty();
            ASSERT_LT(steps, 10000);
        }
        if (valid || to_the_end) probe(ts);
    }
}

// d^2 at p (frame) by brute force over B, in frame units.
double brute_d2(const TargetFrame& fr, const TriangleMesh& B, Vec2 p) {
    const double d = brute_distance(fr.to_world(p), B) / fr.scale;
    return d * d;
}

// Arcs between two domains (counted in `arcs`) where either domain's quadratic misses d2_at(m), an
// oracle's d^2 at the arc's middle m, by more than the domain mesh's placement of its vertices
// (kOffCurve, or `placement` where a test knows its vertices closer) times the two quadratics'
// gradients, and `floor`.
template <class D2>
int arc_middles_off(const DomainMesh& mesh, int& arcs, double placement, double floor, D2 d2_at) {
    int off = 0;
    for (size_t e = 0; e < mesh.edges().size(); ++e) {
        const DomainMesh::Edge& E = mesh.edges()[e];
        const int F = mesh.half_edges()[2 * e].face, G = mesh.half_edges()[2 * e + 1].face;
        if (!E.alive || F <= 0 || G <= 0) continue;
        const Vec2 m = E.curve(0.5 * (E.z0 + E.z1));
        const double d2 = d2_at(m);
        const double tol = placement * (norm(mesh.faces()[F].poly.gradient(m)) + norm(mesh.faces()[G].poly.gradient(m))) + floor;
        for (int X : {F, G}) off += std::abs(mesh.faces()[X].poly(m) - d2) > tol;
        ++arcs;
    }
    return off;
}
// The same against brute force over B, to 1e-12.
int arc_middles_off_d2(const DomainMesh& mesh, const TargetFrame& fr, const TriangleMesh& B, int& arcs, double placement = 1e-6) {
    return arc_middles_off(mesh, arcs, placement, 1e-12, [&](Vec2 m) { return brute_d2(fr, B, m); });
}

// The domain polynomial at p (frame) and d^2 there by brute force over B (frame units); false
// if p is in no domain.
bool polynomial_and_d2(const DomainMesh& mesh, const TargetFrame& fr, const TriangleMesh& B, Vec2 p, double& poly, double& d2) {
    const int f = mesh.face_at(p);
    if (f <= 0) return false;
    poly = mesh.faces()[f].poly(p);
    d2 = brute_d2(fr, B, p);
    return true;
}
bool polynomial_and_d2(const TargetSolver& ts, const TriangleMesh& B, Vec2 p, double& poly, double& d2) {
    return polynomial_and_d2(*ts.domain_mesh(), ts.frame(), B, p, poly, d2);
}

// fn(p) at each point p of an n x n barycentric grid strictly inside T' (frame).
template <class Fn>
void for_each_grid_point(const TargetFrame& fr, int n, Fn&& fn) {
    const auto& c = fr.corners;
    for (int i = 1; i < n; ++i)
        for (int j = 1; i + j < n; ++j) fn(c[0] + (c[1] - c[0]) * (double(i) / n) + (c[2] - c[0]) * (double(j) / n));
}

// How many points of an n x n barycentric grid strictly inside T' have a domain polynomial off
// d2_at(p), an oracle's d^2 (frame units, in its own precision), by more than tol (1 + d^2); a
// point in no domain counts too.
template <class D2>
int grid_points_off(const DomainMesh& mesh, const TargetFrame& fr, int n, double tol, D2 d2_at) {
    int off = 0;
    for_each_grid_point(fr, n, [&](Vec2 p) {
        const int f = mesh.face_at(p);
        if (f <= 0) { ++off; return; }
        const auto d2 = d2_at(p);
        off += std::abs(mesh.faces()[f].poly(p) - d2) > tol * (1 + d2);
    });
    return off;
}
// The same against brute force over B.
int grid_points_off_d2(const DomainMesh& mesh, const TargetFrame& fr, const TriangleMesh& B, int n, double tol) {
    return grid_points_off(mesh, fr, n, tol, [&](Vec2 p) { return brute_d2(fr, B, p); });
}
int grid_points_off_d2(const TargetSolver& ts, const TriangleMesh& B, int n, double tol) {
    return grid_points_off_d2(*ts.domain_mesh(), ts.frame(), B, n, tol);
}

// How many of the points a + (b - a) i / n (frame), i = from .. to, have a domain polynomial off d^2
// (brute force over B) by more than abs + rel d^2; a point in no domain counts too.
int segment_points_off_d2(const TargetSolver& ts, const TriangleMesh& B, Vec2 a, Vec2 b, int from, int to, int n, double abs,
                          double rel) {
    int off = 0;
    for (int i = from; i <= to; ++i) {
        double poly, d2;
        off += !polynomial_and_d2(ts, B, a + (b - a) * (double(i) / n), poly, d2) || std::abs(poly - d2) > abs + rel * d2;
    }
    return off;
}

// max over the used vertices of A, and over a barycentric grid on every triangle of A, of the
// distance to B: both lower bounds of h(A, B).
void brute_lower_bounds(const TriangleMesh& A, const TriangleMesh& B, double& vertex, double& sampled) {
    vertex = sampled = 0;
    const int n = 6;
    for (size_t t = 0; t < A.num_triangles(); ++t) {
        const auto c = A.corners(t);
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double u = double(i) / n, v = double(j) / n;
                const double d = brute_distance(c[0] + (c[1] - c[0]) * u + (c[2] - c[0]) * v, B);
                sampled = std::max(sampled, d);
                if ((i == 0 || i == n || j == 0) && (i + j == 0 || i == n || j == n)) vertex = std::max(vertex, d);
            }
    }
}

}  // namespace

// The overlay's referee on zero-area sources (degenerate seed 1635: a collinear source's distance
// came out 0.61 where it is 0.0076, so the overlay named a farther source nearest). Hand values:
// a segment from (0,0,0) to (0,2,0) given as a, b and its middle c; a triangle shrunk to a point.
TEST(LabelCheck, NearestFeatureOfZeroAreaTriangles) {
    const Vec3 a{0, 0, 0}, b{0, 2, 0}, c{0, 1, 0};
    NearestFeature f = nearest_feature({1, 0.5, 0}, a, b, c);
    EXPECT_DOUBLE_EQ(f.d2, 1.0);  // beside the segment, nearest inside it
    EXPECT_TRUE(f.region == Region::ab || f.region == Region::ca) << region_name(f.region);
    f = nearest_feature({1, 3, 0}, a, b, c);
    EXPECT_DOUBLE_EQ(f.d2, 2.0);  // past the end b
    EXPECT_EQ(f.region, Region::b);
    f = nearest_feature({0.3, 1.2, 0.4}, c, a, b);  // the same segment, corners in another order
    EXPECT_NEAR(f.d2, 0.25, 1e-15);
    {   // seed 1635's source in its target's frame: c between a and b, rounding making it a sliver
        const Vec3 a1{0.5, 0.50000000000000011, 0.037821132479253644}, b1{0.50000000000000033, -1.5000000000000004, 0.088224657903178128},
                   c1{0.50000000000000011, -0.5, 0.06302289519121565};
        const Vec3 q{0.427734375, 0.072265625, 0};
        const double t = std::clamp(dot(q - a1, b1 - a1) / norm2(b1 - a1), 0.0, 1.0);
        EXPECT_NEAR(nearest_feature(q, a1, b1, c1).d2, norm2(q - (a1 + (b1 - a1) * t)), 1e-15);  // 0.0076
    }
    f = nearest_feature({0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1});
    EXPECT_DOUBLE_EQ(f.d2, 3.0);
    // A proper triangle: above its inside, the height.
    f = nearest_feature({0.2, 0.2, 0.5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_DOUBLE_EQ(f.d2, 0.25);
    EXPECT_EQ(f.region, Region::abc);
}

// A sliver's face distance to 1e-12 relative (independent pair 9225, "fan": Ericson's
// barycentric test gave a sliver of height 5e-6 of its length a face distance 3e-9 relative too
// far, so a neighbour's shared edge, truly 5e-12 farther, looked nearer). Hand value: a sliver in
// the plane z = 0 (base 2.2 long along x, apex H above it) and p at height h above an inside
// point, d^2 = h^2, all rotated and moved by a generic rigid motion (placed; its rounding, ~1e-16
// of the coordinates, moves d^2 by ~1e-14 relative). Ericson's test is far off at H = 1e-6.
TEST(LabelCheck, NearestFeatureOfASliverFace) {
    for (double H : {1e-6, 7e-6})
        for (double h : {0.015, 0.003, 0.2}) {
            // The sliver's corners and p (an unused vertex) moved together.
            const TriangleMesh m = placed(mesh_of({{0, H, 0}, {1.3, 0, 0}, {-0.9, 0, 0}, {0.1, 0.4 * H, h}}, {{0, 1, 2}}), 1.1,
                                          1.0, Vec3{0.3, -0.7, 0.2});
            const auto& v = m.positions;
            const NearestFeature f = nearest_feature(v[3], v[0], v[1], v[2]);
            EXPECT_EQ(f.region, Region::abc);
            EXPECT_NEAR(f.d2, h * h, 1e-12 * h * h) << "H = " << H << ", h = " << h;
        }
}

// The tie rule through chains: a ~ b and b ~ c (within same_quadratic's 1e-11 relative) though
// not a ~ c; merging may leave c's label over a's region (degenerate seed 2552), so the overlay and
// validate() count the three as one class. A quadratic 1e-9 off is no tie.
TEST(LabelCheck, TieClassesFollowChains) {
    const Quadratic2 q{1, 0.25, 1, -0.5, -0.5, 0.5};
    auto with_face = [](const Quadratic2& poly) {
        SourceProjection p;
        p.regions.push_back(SourceRegion{Region::abc, {}, poly});
        return p;
    };
    Quadratic2 b = q, c = q, far = q;
    b.f += 0.8e-11;
    c.f += 1.6e-11;
    far.f += 1e-9;
    ASSERT_TRUE(same_quadratic(q, b, 0) && same_quadratic(b, c, 0));
    ASSERT_FALSE(same_quadratic(q, c, 0));
    const std::vector<int> cls = tie_classes({with_face(c), with_face(far), with_face(q), with_face(b)}, 0);
    const int abc = (int)Region::abc;
    EXPECT_EQ(cls[0 * 8 + abc], cls[2 * 8 + abc]);
    EXPECT_EQ(cls[3 * 8 + abc], cls[2 * 8 + abc]);
    EXPECT_NE(cls[1 * 8 + abc], cls[2 * 8 + abc]);
    EXPECT_EQ(cls[0 * 8 + (int)Region::ab], -1);  // no such region
}

// A source standing on an edge e in T''s plane, leaning theta off the vertical: on the side it
// leans to, its face is nearer than e by a factor cos(theta), d^2 (1 - sin^2 theta). A domain mesh
// labelled with e over all of T' (the edge's quadratic as the only region): with theta = 5e-7 the
// face is 2.5e-13 relative nearer, which the quadratics cannot resolve (independent pair 23555:
// such a label came out of a split whose g was noise), so the overlay counts those samples as ties;
// with theta = 1e-3 (1e-6 relative) they are disagreements. On the other side e is nearest.
TEST(LabelCheck, FeaturesEquallyNearToPrecisionAreTies) {
    const std::array<Vec3, 3> target{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
    const TargetFrame fr = TargetFrame::make(target);
    const Vec3 c{0.1, 0.6, 0}, a{0.6, 0.1, 0}, n = Vec3{1, 1, 0} / std::sqrt(2.0);  // e = ca; n: its side toward (1, 1)
    for (double theta : {5e-7, 1e-3}) {
        const Vec3 b = 0.5 * (a + c) + 0.5 * (std::cos(theta) * Vec3{0, 0, 1} + std::sin(theta) * n);
        const std::array<Vec3, 3> src{a, b, c};
        const SourceProjection full = project_source(fr, src, 0);
        SourceProjection edge_only;  // e's quadratic over all of T', labelled e
        edge_only.regions.push_back(SourceRegion{Region::ca, {}, *region_quadratic(full, Region::ca)});
        DomainMesh mesh(fr.ccw_corners());
        mesh.insert(edge_only);
        const LabelCheck L = check_labels(mesh, fr, {src}, {0});
        ASSERT_GT(L.samples, 1000) << theta;
        if (theta < 1e-6) {
            EXPECT_EQ(L.disagree, 0) << L.first;
            EXPECT_GT(L.ties, L.samples / 10);  // the face's side, within e's extent
        } else {
            EXPECT_GT(L.disagree, L.samples / 10);
        }
    }
}

// A zero-area source, a segment with one corner inside it, and a triangle whose edge is a part of
// the segment: one line, so their edges tie. A domain mesh labelled with the triangle's edge over
// all of T': where a part of the segment is nearest, the region test names the zero-area source's
// edge along that part, which its projection (a segment: its two ends and the edge between them)
// does not have; the overlay takes the projection's feature there, and counts a tie (independent
// pair "fan" 24969 was a disagreement by name only).
TEST(LabelCheck, ZeroAreaSourceFeaturesAsItsProjectionNamesThem) {
    const std::array<Vec3, 3> target{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
    const TargetFrame fr = TargetFrame::make(target);
    // The segment reaches past T' both ways (its ends are nowhere nearest); the triangle stands
    // upright on its edge, so over T' that edge (or a corner of it) is its nearest feature.
    const Vec3 a{0.35, 0.35, 0.1}, b{2, 2, 0.1}, c{-1, -1, 0.1};
    // In the order b, a, c its whole extent is the edge "ca", the region test's edges "ab" and "bc"
    // being parts of it: a sample nearest to the part from a to c is named "bc".
    const std::array<Vec3, 3> segment{b, a, c}, tri{a, Vec3{0.6, 0.6, 0.1}, Vec3{0.475, 0.475, 0.6}};
    const SourceProjection full = project_source(fr, tri, 1);
    ASSERT_TRUE(project_source(fr, segment, 0).degenerate);
    SourceProjection edge_only;  // the triangle's edge ab over all of T'
    edge_only.source = 1;
    edge_only.regions.push_back(SourceRegion{Region::ab, {}, *region_quadratic(full, Region::ab)});
    DomainMesh mesh(fr.ccw_corners());
    mesh.insert(edge_only);
    const LabelCheck L = check_labels(mesh, fr, {segment, tri}, {0, 1});
    ASSERT_GT(L.samples, 1000);
    EXPECT_EQ(L.disagree, 0) << L.first;
    EXPECT_GT(L.ties, L.samples / 10);
}

// A sliver source whose corners lie on one line (c 1.5e-12 above the segment from a to b, in T''s
// plane): its three edges have one quadratic, the distance to that line, and the domain over T'
// is named by one of them. Near a, 0.57 from the edge bc it is named by, the nearest feature is
// the edge ca (d^2 1.3186878512e-4 at (0.498, 0.670), by hand in 40 digits; the face's plane is
// 7e-10 relative nearer, its foot 2e5 barycentric units outside). The overlay takes a label for its
// tie class: 20,852 of 21,011 samples disagreed when it took the named edge alone (generate_pairs.py
// "sliver" 2930, that source against that target).
TEST(LabelCheck, ALabelStandsForItsTieClass) {
    const Vec3 a{0.50059317091057143, 0.69305918166196223, 0}, b{0, 0, 0}, c{0.044816095644598708, 0.062046804426500124, 1.481247600861842e-12};
    const TriangleMesh A = mesh_of({{0, 0, 0}, {1, 0, 0}, a}, {{0, 1, 2}}), B = mesh_of({a, b, c}, {{0, 1, 2}});
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.run();
    ASSERT_NE(ts.domain_mesh(), nullptr);
    EXPECT_EQ(ts.validate(true), "");
    const LabelCheck L = check_labels(*ts.domain_mesh(), ts.frame(), {{a, b, c}}, {0});
    ASSERT_GT(L.samples, 10000);
    EXPECT_EQ(L.disagree, 0) << L.first;
    EXPECT_GT(L.ties, L.samples / 2);  // the region test names the face over most of T'
}

// The tie rule makes quadratics one polynomial that differ by up to 1e-11 of their size; where
// d^2 is far below that size, the distances they stand for may differ by more than 1e-9 relative.
// Two edges on parallel lines eps = 8e-12 apart, 0.01 beyond T''s edge, tie (the nearer one's
// segment ends at x = 0.4, the farther one's starts there); a third edge on a line tilted by 4e-11,
// between them for x in (0.4, 0.6), is nearest there, 1.6e-9 relative nearer than the farther
// line along T''s edge. A domain labelled with the nearer line's edge over all of T' carries a
// polynomial within the pair's spread of every distance there: the overlay counts those samples as
// ties (generate_pairs4.py "strip_vs_tri" 190, a strip 7e-12 of T' wide: its cells' diagonals
// tied, a rail between them). Lowered by 3 eps, below both lines, the third edge stays a
// disagreement.
TEST(LabelCheck, DistanceWithinATieClassesSpreadIsATie) {
    const std::array<Vec3, 3> target{Vec3{0, 0.29, 0}, Vec3{1, 0.29, 0}, Vec3{0.5, 0, 0}};
    const TargetFrame fr = TargetFrame::make(target);
    const double eps = 8e-12, tilt = 4e-11;
    const std::array<Vec3, 3> nearer{Vec3{-1, 0.3, 0}, Vec3{0.4, 0.3, 0}, Vec3{-0.3, 1, 0}};
    const std::array<Vec3, 3> farther{Vec3{0.4, 0.3 + eps, 0}, Vec3{2, 0.3 + eps, 0}, Vec3{1.2, 1, 0}};
    for (double drop : {0.0, 3 * eps}) {
        const double y0 = 0.3 + eps / 2 - drop;
        const std::array<Vec3, 3> between{Vec3{0.4, y0 - 0.1 * tilt, 0}, Vec3{0.6, y0 + 0.1 * tilt, 0}, Vec3{0.5, 1, 0}};
        const SourceProjection a = project_source(fr, nearer, 2), b = project_source(fr, farther, 0);
        ASSERT_TRUE(same_feature_quadratic(*region_quadratic(a, Region::ab), Region::ab, *region_quadratic(b, Region::ab), Region::ab,
                                           std::max(a.delta, b.delta)));
        SourceProjection edge_only;  // the nearer line's quadratic over all of T', labelled its edge
        edge_only.source = 2;
        edge_only.regions.push_back(SourceRegion{Region::ab, {}, *region_quadratic(a, Region::ab)});
        DomainMesh mesh(fr.ccw_corners());
        mesh.insert(edge_only);
        LabelCheckOptions opt;
        opt.resolution = 1024;
        const LabelCheck L = check_labels(mesh, fr, {farther, between, nearer}, {0, 1, 2}, opt);
        ASSERT_GT(L.samples, 100000) << drop;
        if (drop == 0) EXPECT_EQ(L.disagree, 0) << L.first;
        else EXPECT_GT(L.disagree, 100) << drop;
    }
}

// A target 5e-15 across (a point-like triangle) on an edge of an octahedron 61 from the origin
// (generate_pairs5.py "point_like" 56486, side B, target 2): the sources' frame coordinates are
// known to delta = 0.028 of T', and d^2 over T' is at most 0.02, so the tie rule makes the face
// of source 3 one polynomial with its edge ab, which the domain keeps: 0.0116 at a sample where
// the face's d^2 is 0.0013. The neighbouring face (source 7, 0.0099 there, tied with neither)
// beat that quadratic and took the domain; the overlay counted 280 of 8,545 samples as
// disagreements, none of which the domain mesh could resolve (validate() passes: its polynomial is
// within the tie's slack of d^2 by brute force). A label within the spread of the nearest
// feature's class is now a tie, as one within its own class's spread was.
TEST(LabelCheck, DistanceWithinTheNearestClassesSpreadIsATie) {
    const TriangleMesh A = make_mesh({{-1.00440343625859, -61.230100251637054, 6.257462806512688},
                                      {-1.015367032742387, -61.243807751853694, 6.274724769134307},
                                      {-1.0069684472493674, -61.2285602386044, 6.27461170619389},
                                      {-1.0128020217516096, -61.24534776488635, 6.257575869453105},
                                      {-0.9992569664822953, -61.24279255385062, 6.268207805124167},
                                      {-1.0205135025186816, -61.23111544964013, 6.263979770522829}},
                                     {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
    const TriangleMesh B = make_mesh({{-1.00685254091391, -61.234546566520905, 6.257495776704389},
                                      {-1.0068525409139073, -61.2345465665209, 6.257495776704389},
                                      {-1.0068525409139124, -61.234546566520905, 6.257495776704392}},
                                     {{0, 1, 2}});
    const VoxelGrid grid(B, A);
    TargetSolver ts(grid, 0, 0);
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    ASSERT_NE(ts.domain_mesh(), nullptr);
    const LabelCheck L = check_labels(*ts.domain_mesh(), ts.frame(), inserted_corners(ts), ts.inserted_sources());
    ASSERT_GT(L.samples, 5000);
    EXPECT_EQ(L.disagree, 0) << L.first;
    EXPECT_GT(L.ties, 200);
}

// A sliver source 34317 long and 1.7e-4 tall standing on T' at 90 degrees less 3e-9 rad, its long
// edge T''s edge (generate_pairs.py "sliver" 33474). Its face, its edge ca and its edge ab are as
// near over most of T' to 1e-16 relative, and the domain's label is the face: at the sample
// (0.177083333, 0.239583333) the foot on its plane has barycentric coordinates (0.131, 0.714,
// 0.154), exact rationals from the input doubles (Python's fractions). In the frame's rounded
// coordinates the foot's place across the sliver is noise (6e-9 of T' against a height of 5e-9):
// the overlay's closest_point_inside put it outside, so the face's distance was +inf and 24 of 81
// samples disagreed. The overlay now asks the face in world coordinates, in long double.
TEST(LabelCheck, SliverFaceStandingOnTheTargetTiesWithItsEdges) {
    const Vec3 t{-21826.28771505196, -12959.828784949766, -7361.9791501662494}, s1{-44777.437594424438, 12439.498030749723, -4953.8625243227743},
        s2{-44702.821553566915, 12356.923029221472, -4961.691496245141}, t2{-40530.348883805724, 8460.193534801323, 15980.051816119792};
    const TriangleMesh A = mesh_of({t, s1, s2}, {{0, 1, 2}}), B = mesh_of({t, s1, t2}, {{0, 1, 2}});
    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 1, 0);
    ts.run();
    ASSERT_NE(ts.domain_mesh(), nullptr);
    EXPECT_EQ(ts.validate(true), "");
    // The frame's double test is the one that cannot tell at the sample.
    const Vec2 p{0.177083333, 0.239583333};
    const std::array<Vec3, 3> f = source_in_frame(ts.frame(), {t, s1, s2});
    ClosestPoint cp;
    EXPECT_FALSE(closest_point_inside(Vec3(p.x, p.y, 0), f[0], f[1], f[2], cp));
    const int face = ts.domain_mesh()->face_at(p);
    ASSERT_GT(face, 0);
    EXPECT_EQ(ts.domain_mesh()->faces()[face].label.region, Region::abc);
    const LabelCheck L = check_labels(*ts.domain_mesh(), ts.frame(), {{t, s1, s2}}, {0});
    ASSERT_GT(L.samples, 5000);
    EXPECT_EQ(L.disagree, 0) << L.first;
    EXPECT_GT(L.ties, L.samples / 10);
}

// Runs `check` on the first, middle and last target of A of every stress pair; it returns a
// failure ("" if none). A pair fails at its first failing target, which fails the test unless the
// seed is listed. Returns the seeds that failed.
using TargetCheck = std::function<std::string(const DegeneratePair&, const VoxelGrid&, uint32_t, const std::string& where)>;
std::vector<int> check_stress_targets(const TargetCheck& check) {
    std::vector<int> failed;
    std::vector<int> seeds;
    for (int seed = 0; seed < pair_count(); ++seed) seeds.push_back(seed);
    for (int seed : kRegressionSeeds)
        if (seed >= pair_count()) seeds.push_back(seed);
    for (int seed : seeds) {
        const DegeneratePair P = degenerate_pair((unsigned)seed);
        const VoxelGrid grid(P.a, P.b);
        const size_t n = P.a.num_triangles();
        std::string failure;
        for (size_t t : {size_t(0), n / 2, n - 1}) {
            failure = check(P, grid, (uint32_t)t, "seed " + std::to_string(seed) + " (" + P.kind + ") target " + std::to_string(t));
            if (!failure.empty()) break;
        }
        if (failure.empty()) continue;
        failed.push_back(seed);
        if (!known_failure(seed)) ADD_FAILURE() << failure;
        else std::printf("[ info ] known failure: %s\n", failure.c_str());
    }
    for (int seed : kKnownFailures)
        if (seed < pair_count() && std::find(failed.begin(), failed.end(), seed) == failed.end())
            std::printf("[ info ] known failure %d passes now: remove it from kKnownFailures\n", seed);
    return failed;
}

TEST(Degenerate, DomainsAndLabelsHoldAfterEveryInsertion) {
    int targets = 0;
    long samples = 0, ties = 0;
    const std::vector<int> failed = check_stress_targets([&](const DegeneratePair&, const VoxelGrid& grid, uint32_t t,
                                                             const std::string& where) -> std::string {
        TargetSolver ts(grid, 0, t);
        ts.validate_each_insertion(true);  // throws with the first failure
        ts.nearest_first();                // the order the distance runs in (TargetSolver::run)
        try {
            while (ts.step()) {
                const DomainMesh* dm = ts.domain_mesh();
                if (!dm) continue;
                LabelCheckOptions opt;
                opt.resolution = 48;
                const LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources(), opt);
                if (L.disagree) return where + " after " + std::to_string(ts.insertions()) + " insertions: " + L.first;
            }
        } catch (const std::logic_error& e) {
            return where + ": " + e.what();
        }
        const DomainMesh* dm = ts.domain_mesh();
        if (!dm) return "";
        const LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources());
        if (L.disagree) return where + ": " + L.first;
        ++targets;
        samples += L.samples;
        ties += L.ties;
        return "";
    });
    std::printf("[ info ] %d targets passed, %ld samples compared, %ld of them ties; %zu pairs failed\n", targets, samples,
                ties, failed.size());
    EXPECT_GT(targets, 3 * pair_count() / 2);  // most targets have a domain mesh (slivers do not)
    EXPECT_GT(ties, 0);                        // coplanar and shared features were exercised
}

// What the debugger shows: the paper's insertion, watched (every cut reported, the voxel order), as
// a user opens the first, middle and last target at the end of its construction with the
// overlay on: validate() and the overlay's comparison on the finished domain mesh. (After every
// insertion this order still fails seed 23 midway, healed by later insertions; 77 fails at the
// end, as above.)
TEST(Degenerate, TheDebuggersConstructionHoldsAtTheEnd) {
    int targets = 0;
    const std::vector<int> failed = check_stress_targets([&](const DegeneratePair&, const VoxelGrid& grid, uint32_t t,
                                                             const std::string& where) -> std::string {
        TargetSolver ts(grid, 0, t);
        long events = 0;
        ts.on_event([&](const Event&) { ++events; });  // watched: the paper's insertion
        while (ts.step()) {}
        if (ts.insertions() > 0 && events == 0) return where + ": no event reported";
        const DomainMesh* dm = ts.domain_mesh();
        if (!dm) return "";
        const std::string v = ts.validate(true);
        if (!v.empty()) return where + ": " + v;
        const LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources());
        if (L.disagree) return where + ": " + L.first;
        ++targets;
        return "";
    });
    std::printf("[ info ] %d targets passed; %zu pairs failed\n", targets, failed.size());
    EXPECT_GT(targets, 3 * pair_count() / 2);
}

TEST(Degenerate, PaperEqualsFastAndTheResultHoldsItsLowerBounds) {
    for (int seed = 0; seed < pair_count(); seed += 2) {
        const DegeneratePair P = degenerate_pair((unsigned)seed);
        HausdorffOptions paper, fast;
        paper.mode = Mode::Paper;
        fast.mode = Mode::Fast;
        const HausdorffResult rp = hausdorff(P.a, P.b, paper), rf = hausdorff(P.a, P.b, fast);
        for (int dir = 0; dir < 2; ++dir) {
            const OneSidedResult &p = dir ? rp.b_to_a : rp.a_to_b, &f = dir ? rf.b_to_a : rf.a_to_b;
            const std::string what = "seed " + std::to_string(seed) + " (" + P.kind + ") direction " + std::to_string(dir);
            EXPECT_EQ(p.distance, f.distance) << what;
            EXPECT_EQ(p.lower, f.lower) << what;
            EXPECT_EQ(p.upper, f.upper) << what;
            double vertex, sampled;
            brute_lower_bounds(dir ? P.b : P.a, dir ? P.a : P.b, vertex, sampled);
            // The brute force's own rounding: a few ulps of the coordinates' magnitude.
            double coord = 0;
            for (const TriangleMesh* m : {&P.a, &P.b})
                for (const Vec3& q : m->positions) coord = std::max({coord, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
            const double slack = 1e-14 * coord + 1e-12 * P.a.bounds().diagonal();
            EXPECT_GE(p.upper + slack, vertex) << what;
            EXPECT_GE(p.upper + slack, sampled) << what;
            EXPECT_LE(p.lower, p.distance) << what;
            EXPECT_LE(p.distance, p.upper) << what;
        }
    }
}

// ---------------------------------------------------------------- the certified interval

namespace {

// The oracle of the interval test: distances in long double (64-bit mantissa) from points formed
// in long double, so that its own rounding (~1e-19 of the coordinates) is far below the 1e-9 of
// the diagonal the interval is held to, even 1e7 diagonals from the origin.
struct L3 {
    long double x, y, z;
    L3 operator-(const L3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    L3 operator+(const L3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    L3 operator*(long double s) const { return {x * s, y * s, z * s}; }
};
L3 ld(const Vec3& p) { return {p.x, p.y, p.z}; }
long double dotl(const L3& a, const L3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
L3 crossl(const L3& a, const L3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

long double segment_d2(const L3& p, const L3& a, const L3& b) {
    const L3 ab = b - a, w = p - a;
    const long double l2 = dotl(ab, ab);
    const long double t = l2 > 0 ? std::min(1.0L, std::max(0.0L, dotl(w, ab) / l2)) : 0.0L;
    const L3 d = w - ab * t;
    return dotl(d, d);
}

// Does the point a + q of abc's plane (n its normal) lie in the closed triangle abc?
bool projects_inside(const L3& q, const L3& a, const L3& b, const L3& c, const L3& n) {
    return dotl(crossl(b - a, q), n) >= 0 && dotl(crossl(c - b, q - (b - a)), n) >= 0 &&
           dotl(crossl(a - c, q - (c - a)), n) >= 0;
}

// Squared distance from p to the closed triangle abc: the plane where p projects inside, else the
// nearest of the three edges. A triangle whose height is below 1e-12 of its longest edge is its
// edges (off by that height at most): its normal, a small cross product of long edges, would be
// off in direction even in long double.
long double triangle_d2(const L3& p, const L3& a, const L3& b, const L3& c) {
    long double best = std::min({segment_d2(p, a, b), segment_d2(p, b, c), segment_d2(p, c, a)});
    const L3 n = crossl(b - a, c - a);
    const long double nn = dotl(n, n);
    const long double l2 = std::max({dotl(b - a, b - a), dotl(c - b, c - b), dotl(a - c, a - c)});
    if (nn > 1e-24L * l2 * l2) {
        const L3 w = p - a;
        const long double h = dotl(w, n);
        const L3 q = w - n * (h / nn);  // p's projection, relative to a
        if (projects_inside(q, a, b, c, n)) best = std::min(best, h * h / nn);
    }
    return best;
}

long double distance_ld(const L3& p, const TriangleMesh& B) {
    long double best = HUGE_VALL;
    for (size_t t = 0; t < B.num_triangles(); ++t) {
        const auto c = B.corners(t);
        best = std::min(best, triangle_d2(p, ld(c[0]), ld(c[1]), ld(c[2])));
    }
    return std::sqrt(best);
}

// The closest point of the closed triangle abc to p (the plane, else the nearest edge).
L3 closest_on_triangle(const L3& p, const L3& a, const L3& b, const L3& c) {
    auto on_segment = [&](const L3& u, const L3& v) {
        const L3 uv = v - u;
        const long double l2 = dotl(uv, uv);
        const long double t = l2 > 0 ? std::min(1.0L, std::max(0.0L, dotl(p - u, uv) / l2)) : 0.0L;
        return u + uv * t;
    };
    L3 best = on_segment(a, b);
    for (const L3& q : {on_segment(b, c), on_segment(c, a)})
        if (dotl(p - q, p - q) < dotl(p - best, p - best)) best = q;
    const L3 n = crossl(b - a, c - a);
    const long double nn = dotl(n, n);
    const long double l2 = std::max({dotl(b - a, b - a), dotl(c - b, c - b), dotl(a - c, a - c)});
    if (nn > 1e-24L * l2 * l2) {  // as triangle_d2
        const L3 q = (p - a) - n * (dotl(p - a, n) / nn);
        if (projects_inside(q, a, b, c, n)) best = a + q;
    }
    return best;
}

// The largest distance to B near the point a + u (b - a) + v (c - a) of triangle abc: a local
// search in eight directions, from step h down to 1e-13 of the triangle.
long double climb(const L3& a, const L3& b, const L3& c, long double u, long double v, long double h, const TriangleMesh& B) {
    auto at = [&](long double x, long double y) { return distance_ld(a + (b - a) * x + (c - a) * y, B); };
    long double best = at(u, v);
    for (; h > 1e-13L; h *= 0.5L)
        for (int moves = 0; moves < 16; ++moves) {
            bool moved = false;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy) {
                    const long double x = u + dx * h, y = v + dy * h;
                    if ((dx == 0 && dy == 0) || x < 0 || y < 0 || x + y > 1) continue;
                    const long double d = at(x, y);
                    if (d > best) best = d, u = x, v = y, moved = true;
                }
            if (!moved) break;
        }
    return best;
}

// The largest distance to B over A, as far as the oracle finds it: each triangle of A sampled on a
// barycentric grid of n steps, its best sample climbed to its local maximum.
long double climbed_maximum(const TriangleMesh& A, const TriangleMesh& B, int n) {
    long double far = 0;
    for (size_t t = 0; t < A.num_triangles(); ++t) {
        const auto c = A.corners(t);
        long double top = -1, tu = 0, tv = 0;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const long double u = (long double)i / n, v = (long double)j / n;
                const long double d = distance_ld(ld(c[0]) + (ld(c[1]) - ld(c[0])) * u + (ld(c[2]) - ld(c[0])) * v, B);
                if (d > top) top = d, tu = u, tv = v;
            }
        far = std::max(far, climb(ld(c[0]), ld(c[1]), ld(c[2]), tu, tv, 1.0L / n, B));
    }
    return far;
}

}  // namespace

// The certified interval holds the truth on every degenerate pair, by an oracle in extended
// precision: upper is at least every vertex's and every sample's distance (the two highest
// targets' samples climbed to their local maxima), and lower at most the witness's distance (put
// back on its target triangle). Near the origin or 1e7 diagonals away alike, and the interval is
// at most 1e-9 of the diagonal wide.
TEST(Degenerate, CertifiedIntervalHoldsTheTruthInExtendedPrecision) {
    int narrow = 0, wide = 0;
    double widest = 0;
    for (int seed = 0; seed < pair_count(); ++seed) {
        const DegeneratePair P = degenerate_pair((unsigned)seed);
        const HausdorffResult r = hausdorff(P.a, P.b, HausdorffOptions{});
        Box3 box = P.a.bounds();
        box.add(P.b.bounds());
        const double diag = box.diagonal();
        const double coord = coordinate_magnitude(P.a, P.b);
        // The oracle's own rounding, and its slivers taken as their edges (1e-12 of an edge).
        const long double tol = 4 * 0x1p-64L * coord + 1e-12L * diag;
        for (int dir = 0; dir < 2; ++dir) {
            const OneSidedResult& s = dir ? r.b_to_a : r.a_to_b;
            const TriangleMesh &A = dir ? P.b : P.a, &B = dir ? P.a : P.b;
            const std::string what = "seed " + std::to_string(seed) + " (" + P.kind + ") direction " + std::to_string(dir);
            long double far = 0;
            const int n = 8;
            std::vector<std::pair<long double, std::array<long double, 3>>> tops;  // per target: (d, {t, u, v})
            for (size_t t = 0; t < A.num_triangles(); ++t) {
                const auto c = A.corners(t);
                std::pair<long double, std::array<long double, 3>> top{-1, {}};
                for (int i = 0; i <= n; ++i)
                    for (int j = 0; i + j <= n; ++j) {
                        const long double u = (long double)i / n, v = (long double)j / n;
                        const long double d = distance_ld(ld(c[0]) + (ld(c[1]) - ld(c[0])) * u + (ld(c[2]) - ld(c[0])) * v, B);
                        if (d > top.first) top = {d, {(long double)t, u, v}};
                    }
                tops.push_back(top);
            }
            // The two highest targets' samples, climbed to their local maxima.
            std::sort(tops.begin(), tops.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
            for (size_t k = 0; k < tops.size(); ++k) {
                const auto c = A.corners((size_t)tops[k].second[0]);
                far = std::max(far, k < 2 ? climb(ld(c[0]), ld(c[1]), ld(c[2]), tops[k].second[1], tops[k].second[2], 1.0L / n, B)
                                          : tops[k].first);
            }
            EXPECT_GE((long double)s.upper + tol, far) << what << ": upper " << s.upper << " below a sample at " << (double)far;
            // lower: the witness, put back on its target (from_point is rounded to the coordinates),
            // is at least that far from B, less the rounding of from_point (4 ulps of the
            // coordinates: the check is that much weaker than the interval's own claim).
            const auto wc = A.corners(s.target);
            const L3 x = closest_on_triangle(ld(s.from_point), ld(wc[0]), ld(wc[1]), ld(wc[2]));
            EXPECT_LE((long double)s.lower, distance_ld(x, B) + tol + 4 * 0x1p-52L * coord)
                << what << ": lower " << s.lower << " above the witness's distance " << (double)distance_ld(x, B);
            EXPECT_LE(s.lower, s.distance) << what;
            EXPECT_LE(s.distance, s.upper) << what;
            const double width = (s.upper - s.lower) / diag;
            widest = std::max(widest, width);
            (width <= 1e-9 ? narrow : wide)++;
            EXPECT_LE(width, 1e-9) << what << ": the interval is " << width << " of the diagonal wide (coordinates "
                                   << coord / diag << " diagonals from the origin)";
        }
    }
    std::printf("[ info ] %d intervals within 1e-9 of the diagonal, %d wider (the widest %.3g of it)\n", narrow, wide, widest);
}

// Degenerate pair "mirror" 11642 of an independent generator: three triangles within 1e-4 of a
// plane against their mirror images, 3.5e-10 apart over a mesh 1.4e-4 across. The difference of
// an edge's quadratic and the nearly parallel mirror's is a thin ellipse of the target's size
// (conic.cpp); taken as parallel lines, the edge's sliver 3.5e-6 wide was lost, and the result
// came out 3.10e-10 with an interval below the truth. The oracle: the long-double samples above,
// climbed to their local maxima (3.5132e-10 here).
TEST(Degenerate, MirroredNearlyFlatTrianglesKeepTheirMaximum) {
    const std::vector<Vec3> pa = {{-8.7356544500505118e-05, 3.303978726262699e-05, -2.0918147625084617e-07},
                                  {-0.00010645863780371901, 7.4867424910677244e-06, -1.7915758474779267e-05},
                                  {-4.635716120604335e-05, 5.0768821908317412e-05, 1.7796565865136273e-05},
                                  {-0.00015481481164470774, 4.9432862726328342e-05, -5.2850685850746646e-06},
                                  {-0.00013073470627412995, 6.4842954290457569e-05, 7.9828230999344434e-06},
                                  {-8.033909642823976e-05, 1.2283606450351048e-05, -9.9458468084072044e-06},
                                  {-0.00011628849971831231, -1.3525346293357271e-05, -3.1264055981031996e-05},
                                  {-4.759568303527e-05, 4.0771227751496237e-06, -7.616391835396905e-06},
                                  {-0.00012543267905242649, 4.4712279207092533e-05, -1.7707393555936555e-06}};
    const std::vector<Vec3> pb = {{-8.7356544473704277e-05, 3.3039787332664905e-05, -2.091816062383736e-07},
                                  {-4.635716110025706e-05, 5.0768822184765873e-05, 1.7796565352059151e-05},
                                  {-0.00010645863786688299, 7.4867423260030055e-06, -1.7915758168425851e-05},
                                  {-0.00015481481302630305, 4.9432859115842516e-05, -5.2850618841594961e-06},
                                  {-8.0339093862956772e-05, 1.2283613154136069e-05, -9.9458592503601306e-06},
                                  {-0.00013073470124104009, 6.4842967443295803e-05, 7.9827986888004965e-06},
                                  {-0.00011628854915573873, -1.3525475486853406e-05, -3.126381620314646e-05},
                                  {-0.00012543274481773337, 4.4712107344385694e-05, -1.7704203853847763e-06},
                                  {-4.7595646902995738e-05, 4.0772171986496679e-06, -7.6165670815808278e-06}};
    const std::vector<Tri> faces = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    const TriangleMesh A = make_mesh(pa, faces), B = make_mesh(pb, faces);
    Box3 box = A.bounds();
    box.add(B.bounds());
    const double diag = box.diagonal();
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const HausdorffResult r = hausdorff(A, B, opt);
        for (int dir = 0; dir < 2; ++dir) {
            const OneSidedResult& s = dir ? r.b_to_a : r.a_to_b;
            const TriangleMesh &from = dir ? B : A, &to = dir ? A : B;
            const long double far = climbed_maximum(from, to, 24);
            const long double tol = 1e-12L * diag;
            SCOPED_TRACE(mode_name(mode));
            SCOPED_TRACE(dir);
            EXPECT_GT(far, 3.5e-10L);  // the oracle found the top (the old answer was 3.10e-10)
            EXPECT_GE((long double)s.upper + tol, far);
            EXPECT_GE((long double)s.distance + 1e-9L * diag, far);
            EXPECT_LE(s.upper - s.lower, 1e-9 * diag);
        }
    }
    // Every target's domain mesh, in the debugger's order, holds after every insertion (d^2
    // continuous across each arc included): in B's target 2 a sliver 6e-7 wide, where g stayed
    // below the split's old zero tolerance (1e-13), was cut along one side only, d^2 off by 0.03.
    const VoxelGrid grid(A, B);
    for (int side = 0; side < 2; ++side)
        for (uint32_t t = 0; t < 3; ++t) {
            SCOPED_TRACE(side);
            SCOPED_TRACE(t);
            TargetSolver ts(grid, side, t);
            ts.on_event([](const Event&) {});
            ts.validate_each_insertion(true);
            EXPECT_NO_THROW(while (ts.step()) {});
        }
}

// Every target of both meshes, in the paper's order and nearest first: the thorough validate()
// after every insertion.
static void validate_every_insertion(const TriangleMesh& A, const TriangleMesh& B) {
    const VoxelGrid grid(A, B);
    for (int side = 0; side < 2; ++side)
        for (uint32_t t = 0; t < grid.mesh(side).num_triangles(); ++t)
            for (bool nearest : {false, true}) {
                SCOPED_TRACE(side);
                SCOPED_TRACE(t);
                SCOPED_TRACE(nearest);
                TargetSolver ts(grid, side, t);
                ts.nearest_first(nearest);
                ts.validate_each_insertion(true);
                EXPECT_NO_THROW(while (ts.step()) {});
            }
}

// Independent pair "perpendicular" 803: a strip of B standing on end, its bottom edge 0.004 (1.2e-6 of
// the target's size) under the plane of A and its plane tilted from the vertical by 2e-6. Over
// most of A's target 0 the nearest point of B is inside that face, not on its bottom edge; the two
// quadratics differ by 4e-12 of their size, and d^2 is 5e-6 there. The tie rule's old relative
// allowance, 1e-11, made them one polynomial: the face's domain merged with the edge's and took
// its quadratic, 2.8e-7 relative above d^2. validate() after every insertion checks the domains'
// polynomials against direct distances, both orders, every target.
TEST(Degenerate, SourceStandingJustUnderTheTargetKeepsItsFacesQuadratic) {
    const std::vector<Vec3> pa = {{-41937.202529802409, -64185.613806275302, -29345.36813588511},
                                  {-38828.419358279207, -64185.613806275302, -29345.36813588511},
                                  {-41937.202529802409, -63149.352749100901, -29345.36813588511},
                                  {-38828.419358279207, -63149.352749100901, -29345.36813588511},
                                  {-41937.202529802409, -62113.0916919265, -29345.36813588511},
                                  {-38828.419358279207, -62113.0916919265, -29345.36813588511},
                                  {-41937.202529802409, -61076.830634752099, -29345.36813588511},
                                  {-38828.419358279207, -61076.830634752099, -29345.36813588511}};
    const std::vector<Vec3> pb = {{-40030.505776661623, -64905.597902194742, -29345.372092765047},
                                  {-40030.505776661623, -63313.933749045427, -29345.372092765047},
                                  {-40030.505776661623, -61722.269595896112, -29345.372092765047},
                                  {-40030.502940332604, -64905.597902194742, -27979.536192117856},
                                  {-40030.502940332604, -63313.933749045427, -27979.536192117856},
                                  {-40030.502940332604, -61722.269595896112, -27979.536192117856}};
    const TriangleMesh A = make_mesh(pa, {{0, 1, 3}, {0, 3, 2}, {2, 3, 5}, {2, 5, 4}, {4, 5, 7}, {4, 7, 6}});
    const TriangleMesh B = make_mesh(pb, {{0, 1, 3}, {1, 4, 3}, {1, 2, 5}, {1, 5, 4}});
    validate_every_insertion(A, B);
}

// generate_pairs.py "nearcoinc_far" 13239: a cube and its copy 2.4e6 from the origin, moved by
// 2.8e-6 of the target's size (A's top face above B's target 0). Beyond A's corner, outside both
// vertical faces, the nearest feature is their vertical edge; the corner's quadratic lies h^2 =
// 7.6e-12 above it everywhere, within the tie allowance of 1e-11 that edges and corners had
// between them, so the corner's domain kept its quadratic where the edge is nearer: 9.6e-12
// where d^2 is 2e-12. A corner and an edge now tie only to 1e-13, as a face and an edge do.
TEST(Degenerate, CornerAboveAVerticalEdgeDoesNotTieWithIt) {
    const std::vector<Vec3> pa = {{-2374861.4795741886, 2374861.4797022929, -2374861.4798181583},
                                  {-2374862.9032908403, 2374865.7183102369, -2374853.6337251649},
                                  {-2374861.3999953917, 2374869.4308781996, -2374865.7607538714},
                                  {-2374862.8237120439, 2374873.6694861436, -2374857.914660878},
                                  {-2374852.5621395921, 2374862.0854630242, -2374860.1889441027},
                                  {-2374853.9858562443, 2374866.3240709677, -2374852.3428511093},
                                  {-2374852.4825607957, 2374870.0366389309, -2374864.4698798163},
                                  {-2374853.9062774475, 2374874.2752468749, -2374856.6237868229}};
    const std::vector<Vec3> pb = {{-2374861.4795657424, 2374861.4795657424, -2374861.4795657424},
                                  {-2374862.9032823942, 2374865.7181736864, -2374853.633472749},
                                  {-2374861.399986946, 2374869.4307416491, -2374865.7605014555},
                                  {-2374862.8237035978, 2374873.6693495931, -2374857.9144084621},
                                  {-2374852.5621311464, 2374862.0853264737, -2374860.1886916873},
                                  {-2374853.9858477982, 2374866.3239344177, -2374852.3425986939},
                                  {-2374852.4825523496, 2374870.0365023804, -2374864.4696274004},
                                  {-2374853.9062690018, 2374874.2751103244, -2374856.623534407}};
    const std::vector<Tri> cube = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 1}, {4, 5, 1},
                                   {2, 3, 6}, {3, 7, 6}, {0, 2, 4}, {2, 6, 4}, {1, 5, 3}, {5, 7, 3}};
    validate_every_insertion(make_mesh(pa, cube), make_mesh(pb, cube));
}

// A target 2e-10 long lying on the long edge of a coplanar source 7e-3 long (a third, blind
// generator's "mixed_scale" 246): in the target's frame the source's corners are 2.5e7 units away.
// The edge's quadratic must vanish on the edge's own line: a point of that line near the target,
// found in long double from the input coordinates, has d^2 = 0 there up to the rounding of its
// frame coordinates (2.5e-9 units, so ~1e-17). Projecting r once onto the plane normal to the edge
// left it off by 1e-16 of |r| along the edge, and the quadratic was 6.9e-10 on the line; validate()
// saw d^2 jump by that across the region line. Then the same with the target 1.4e-11 long against
// a source of size 3 ("mixed_scale" 78: 2e11 units away, coordinates rounded to 2e-5 units in the
// frame): the continuity check allows for that rounding (DomainMesh::delta()), every insertion,
// both orders.
TEST(Degenerate, TinyTargetOnALongCoplanarEdge) {
    const TriangleMesh A = make_mesh({{-2.5864882926926294, -8.56517091668887, -43.252309927800795},
                                      {-2.586488292691468, -8.5651709166883, -43.252309927800795},
                                      {-2.58648829263236, -8.565170916889791, -43.252309927800795}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-2.5817236234679517, -8.567553251372713, -43.252309927800795},
                                      {-2.5888706272337227, -8.567553251372713, -43.252309927800795},
                                      {-2.5817236234679517, -8.560406247606942, -43.252309927800795}},
                                     {{0, 1, 2}});
    const TargetFrame frame = TargetFrame::make(A.corners(0));
    const SourceProjection src = project_source(frame, B.corners(0), 0);
    const auto sc = B.corners(0);
    int edges = 0;
    for (const SourceRegion& r : src.regions) {
        if (r.kind != Region::ab && r.kind != Region::bc && r.kind != Region::ca) continue;
        const int i = r.kind == Region::ab ? 0 : r.kind == Region::bc ? 1 : 2;
        const Vec3 p0 = sc[i], p1 = sc[(i + 1) % 3];
        // The foot of the frame's origin on the edge's line, in long double.
        long double u[3] = {(long double)p1.x - p0.x, (long double)p1.y - p0.y, (long double)p1.z - p0.z};
        long double w[3] = {(long double)frame.origin.x - p0.x, (long double)frame.origin.y - p0.y, (long double)frame.origin.z - p0.z};
        const long double t = (w[0] * u[0] + w[1] * u[1] + w[2] * u[2]) / (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        // Its frame coordinates from the offset to the origin, never rounded to world coordinates.
        const long double f[3] = {t * u[0] - w[0], t * u[1] - w[1], t * u[2] - w[2]};
        const Vec2 q{(double)((f[0] * frame.e1.x + f[1] * frame.e1.y + f[2] * frame.e1.z) / frame.scale),
                     (double)((f[0] * frame.e2.x + f[1] * frame.e2.y + f[2] * frame.e2.z) / frame.scale)};
        if (norm(q) > 10) continue;  // only the edge passing by the target
        ++edges;
        EXPECT_LE(std::fabs(r.poly(q)), 1e-14) << region_name(r.kind) << " at (" << q.x << ", " << q.y << ")";
    }
    EXPECT_EQ(edges, 1);  // the hypotenuse
    validate_every_insertion(A, B);
    const TriangleMesh A2 = make_mesh({{1.0000000000071472, 1.5573758420233564e-12, 0.0},
                                       {1.0000000000043996, 5.843819770074282e-12, 0.0},
                                       {1.0000000000027482, 6.77893731734303e-12, 0.0},
                                       {0.9999999999947047, 5.0464472103201595e-12, 0.0},
                                       {0.9999999999934314, 3.218765707403769e-12, 0.0},
                                       {0.9999999999957544, -5.956712413722837e-12, 0.0},
                                       {0.9999999999975909, -6.906790752026716e-12, 0.0},
                                       {1.0000000000010165, -7.243892674938265e-12, 0.0}},
                                      {{0, 1, 7}, {1, 6, 7}, {1, 2, 6}, {2, 5, 6}, {2, 3, 5}, {3, 4, 5}});
    const TriangleMesh B2 = make_mesh({{-1, -1, 0}, {-1, 2, 0}, {2, -1, 0}}, {{0, 2, 1}});
    validate_every_insertion(A2, B2);
}

// A grid of eight coplanar triangles 4.2e-7 across (1e-7 of the target's size) at the middle of a
// large target (a third generator's "mixed_scale" 862): every region line of every source passes
// within 1e-7 of one point, below the domain mesh's resolution. In the paper's insertion a sliver
// 1e-7 wide and 0.24 long, from that cluster to T''s edge (a source's edge region, as far as the
// cuts could tell), was left to the last region, the face region of a source 5e-8 across, whose
// quadratic is 0: leftover_region looked at a point stepped in from a short arc at the cluster,
// inside that region to 1e-7, not at the sliver's middle (DomainMesh::long_arc_point). d^2 jumped
// by 0.014 across its edges. Every target, both orders, every insertion.
TEST(Degenerate, SourcesBelowTheResolutionLeaveNoSliverToTheirFaceRegion) {
    const double h = 2.1247848137551703e-07;
    std::vector<Vec3> pb;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) pb.push_back({i * h, j * h, 0});
    const std::vector<Tri> grid = {{0, 3, 4}, {0, 4, 1}, {1, 4, 5}, {1, 5, 2}, {3, 6, 7}, {3, 7, 4}, {4, 7, 8}, {4, 8, 5}};
    validate_every_insertion(make_mesh({{-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}}, {{1, 2, 0}}), make_mesh(pb, grid));
}

// Independent pair "sliver" 1682: a needle of B lying in the plane of A's target 2, its tip among
// four nearly concurrent region lines (the needle's edges and their perpendiculars at the tip, 3e-6
// apart in angle). Cutting there left a cycle of no area (two vertices 7e-7 apart, a third on the
// first) outside the face it was given to, the far source's domain, where d^2 is 0.07 and near the
// needle ~0: validate() saw d^2 jump across its arcs. Every target, both orders, every insertion.
TEST(Degenerate, NeedleTipInTheTargetsPlaneLeavesNoOrphanLoop) {
    const std::vector<Vec3> pa = {{0, 0, 0},
                                  {0, -0.0033073253983759458, 0},
                                  {0, -0.0066146507967518916, 0},
                                  {0, 0, -0.0066146507967518916},
                                  {0, -0.0033073253983759458, -0.0066146507967518916},
                                  {0, -0.0066146507967518916, -0.0066146507967518916},
                                  {8.7663352248324995e-05, -0.0045977211672926744, -0.005863053570357101},
                                  {-0.00026654688855382464, -0.0043056917264710027, -0.0019810319213811114},
                                  {-0.00036738106990451914, -0.0042225587504905104, -0.00087592416893327669}};
    const std::vector<Vec3> pb = {{0, -0.0038503291818440212, -0.00053221458471414932},
                                  {0, -0.0029045010330511446, -0.00086465872144181691},
                                  {0, -0.003236318838321844, -0.00074803173138813758},
                                  {-0.00016779522687527932, -0.00014389475492063199, -6.1115047599498955e-05},
                                  {0, -0.0028089782027646477, -0.0037244183981377057},
                                  {-4.7528622226192049e-05, -0.0020540834018718812, -0.0026867740963472421},
                                  {0, -0.0057282642642098956, -0.0011941632293180869},
                                  {-7.73962342149124e-05, -0.0036380115750568216, -0.0065851249199033292},
                                  {-6.3864308474734956e-05, -0.0040034704950529442, -0.0056425713964007931},
                                  {0.00019246749963915558, -0.0043012817870835534, -0.0059994810814565733},
                                  {0, -0.0063331170654544258, -0.0061635675713407395},
                                  {0.00027756115910692561, -0.0034029675283361927, -0.0059269352234189209},
                                  {0, -0.0057282642642098956, -0.0011941632293180869},
                                  {-7.73962342149124e-05, -0.0036380115750568216, -0.0065851249199033292},
                                  {-6.3864308474734956e-05, -0.0040034704950529442, -0.0056425713964007931}};
    const TriangleMesh A = make_mesh(pa, {{0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 5, 4}, {6, 7, 8}});
    const TriangleMesh B = make_mesh(pb, {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}});
    validate_every_insertion(A, B);
}

// Degenerate pair "mirror" 16298 of an independent generator: four triangles, each with an edge in
// the plane z = 0, against their mirror images. On target 3, two sources' edge quadratics differ by
// a line pair whose centre lies at a corner of a domain; the crossing on the arc beside it was
// polished onto the flat g = 0 and moved 3.4e-8 past the corner, the boundary went out of order,
// the lines' chords crossed and the face stayed whole (d^2 off by 0.125 there). Now a polished
// crossing within kCluster of an arc's end is that end. Every target, both constructions:
// validate() after every insertion and the overlay's comparison at the end.
TEST(Degenerate, MirrorWithAnEdgeInTheMirrorPlane) {
    const std::vector<Vec3> pa = {{1.3862829539819598e-05, -1.1359268909766227e-05, 0},
                                  {9.6587979033841501e-06, -1.4197764367387693e-05, 0},
                                  {1.4700103617639368e-05, -1.3137017092803443e-05, 3.9977381135170005e-06},
                                  {2.9519868153914635e-06, -7.3743884759364287e-06, 0},
                                  {3.5063173767466216e-06, -3.1860506102316288e-06, 0},
                                  {1.7548484308425671e-05, -1.8845086168945805e-05, 6.8921653337960621e-06},
                                  {1.9095538966301469e-05, -1.2200580048547409e-05, 0},
                                  {5.962926315879033e-07, -1.2656351998437214e-05, 0},
                                  {1.4207544581571134e-05, -6.5867897661226247e-06, -9.5376517513071242e-06},
                                  {3.1412369153057258e-06, -4.3271543078411099e-06, 0},
                                  {8.7984712273343218e-06, -1.29703107003393e-05, 0},
                                  {1.5319422131834903e-05, -4.8912631370349686e-06, 6.3872197781163967e-06}};
    std::vector<Vec3> pb = pa;
    for (Vec3& p : pb) p.z = -p.z;
    const std::vector<Tri> fa = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}}, fb = {{0, 2, 1}, {3, 5, 4}, {6, 8, 7}, {9, 11, 10}};
    const TriangleMesh A = make_mesh(pa, fa), B = make_mesh(pb, fb);
    const VoxelGrid grid(A, B);
    for (uint32_t t = 0; t < A.num_triangles(); ++t)
        for (bool watched : {false, true}) {
            SCOPED_TRACE(t);
            SCOPED_TRACE(watched ? "the debugger's construction" : "nearest first");
            TargetSolver ts(grid, 0, t);
            if (watched) ts.on_event([](const Event&) {});
            else ts.nearest_first();
            ts.validate_each_insertion(true);
            EXPECT_NO_THROW(while (ts.step()) {});
            ASSERT_NE(ts.domain_mesh(), nullptr);
            const LabelCheck L = check_labels(*ts.domain_mesh(), ts.frame(), inserted_corners(ts), ts.inserted_sources());
            EXPECT_EQ(L.disagree, 0) << L.first;
        }
}

// Degenerate pair "near_coinc_far" 5830 of an independent generator: a strip of nine triangles
// 1.3e5 from the origin against a copy 0.25 off it. The tie rule's allowance (DomainMesh::delta(),
// the largest rounding of the inserted sources) grows when a source farther from the frame's
// origin is inserted, and two neighbouring domains whose quadratics differ by less than the new
// allowance are one domain. Target 0 of B, nearest first: source 3 raised the allowance but won
// no piece of the target, and the insertion returned "unchanged" without merging, so validate()
// found two neighbours with the same polynomial after it.
TEST(Degenerate, LargerTieAllowanceMergesEvenWhenNothingIsCut) {
    const std::vector<Vec3> pa = {{10738, 125856, 22855},
                                  {10746.890963773625, 125885.83613934834, 22840.605393580849},
                                  {10755.781927547252, 125915.67227869666, 22826.210787161701},
                                  {10764.672891320877, 125945.50841804499, 22811.816180742549},
                                  {10773.563855094504, 125975.34455739333, 22797.421574323398},
                                  {10728.31653391633, 125894.78291149622, 22929.405438703594},
                                  {10737.207497689955, 125924.61905084456, 22915.010832284443},
                                  {10746.098461463582, 125954.45519019289, 22900.616225865291},
                                  {10754.989425237207, 125984.29132954123, 22886.221619446143},
                                  {10763.880389010832, 126014.12746888955, 22871.827013026992}};
    const std::vector<Vec3> pb = {{10738.041233350394, 125856.01696571559, 22854.833215094794},
                                  {10746.932197124019, 125885.85310506393, 22840.438608675642},
                                  {10755.823160897646, 125915.68924441225, 22826.044002256494},
                                  {10764.714124671271, 125945.52538376059, 22811.649395837343},
                                  {10773.605088444898, 125975.36152310892, 22797.254789418192},
                                  {10728.357767266723, 125894.79987721182, 22929.238653798388},
                                  {10737.248731040349, 125924.63601656015, 22914.844047379236},
                                  {10746.139694813975, 125954.47215590849, 22900.449440960085},
                                  {10755.030658587601, 125984.30829525682, 22886.054834540937},
                                  {10763.921622361226, 126014.14443460514, 22871.660228121786}};
    const std::vector<Tri> fa = {{2, 3, 8}, {3, 4, 9}, {1, 7, 6}, {1, 7, 2}, {1, 2, 7}, {0, 6, 5}, {0, 1, 6}, {2, 8, 7}, {3, 9, 8}};
    std::vector<Tri> fb = fa;
    fb.push_back({2, 8, 3});
    const TriangleMesh A = make_mesh(pa, fa), B = make_mesh(pb, fb);
    const VoxelGrid grid(A, B, 1.0, 1);
    for (int side = 0; side < 2; ++side)
        for (uint32_t t = 0; t < grid.mesh(side).num_triangles(); ++t) {
            SCOPED_TRACE(side);
            SCOPED_TRACE(t);
            TargetSolver ts(grid, side, t);
            ts.validate_each_insertion(true).nearest_first();
            EXPECT_NO_THROW(while (ts.step()) {});
        }
}

// ---------------------------------------------------------------- paper = fast, interval included

namespace {

struct DumpedPair {
    const char* name;
    std::vector<Vec3> pa;
    std::vector<Tri> fa;
    std::vector<Vec3> pb;
    std::vector<Tri> fb;
};

// Pairs of the independent generator (seeds 2, 12, 18, 11608) on which paper and fast mode
// disagreed. 2, 12, 18: a sliver or needle target (handled as its edges, its slack its height):
// fast mode's upper end took the solved pieces' values plus their slack, paper mode's the
// confirmation of the top, so fast's was looser (by up to 1.3e-7 on seed 18). 11608: a
// T-junction, two targets of A round vertex 5 tied at its distance (3.5e-15 apart); the true top
// lies 6e-6 from that vertex in target 2, 2.5e-9 farther. Fast mode's lower bound L had reached it
// (a centroid's distance), so target 1 was not solved whole: the witness was target 2, whose polish
// found the top, while paper mode's witness, target 1, cannot reach it by its own local search.
std::vector<DumpedPair> dumped_pairs() {
    std::vector<DumpedPair> out;
    out.push_back({"seed 2 (sliver)",
                   {{0, 0, 0},
                    {8.9211156374179132e-06, 3.8397716184857592e-05, 1.544866118679108e-05},
                    {1.7842231274835826e-05, 7.6795432369715185e-05, 3.089732237358216e-05},
                    {7.1864543972111674e-05, -3.0056412982999691e-05, 3.3205835900472136e-05},
                    {8.0785659609529587e-05, 8.341303201857898e-06, 4.8654497087263216e-05},
                    {8.97067752469475e-05, 4.6739019386715487e-05, 6.4103158274054296e-05},
                    {2.5893108512618041e-05, 4.5039153938467618e-05, 2.6984767568891077e-05},
                    {8.4394809615068541e-05, 4.3783995919228831e-05, 6.0256925826418026e-05},
                    {5.863899568635827e-05, 4.4336588677811247e-05, 4.5608607898241606e-05},
                    {5.9636865959961435e-05, 5.3584495154844895e-05, 4.7694496938294545e-05},
                    {6.0840194704956043e-05, 3.7035906889593038e-05, 4.3417602807407683e-05},
                    {6.1320029695327702e-05, 3.0437052076462598e-05, 4.1712164073747877e-05},
                    {4.9873115062469815e-05, 4.740163516887451e-05, 4.2102903689617513e-05},
                    {6.8520952402543022e-05, 3.3299351789664471e-05, 4.8318440057180691e-05},
                    {6.8073113744569939e-05, 3.3638026325991265e-05, 4.8169170336599039e-05},
                    {5.0610132459706898e-05, 6.0745657058063552e-05, 4.12029774996393e-05},
                    {3.9662534894870388e-05, 2.6734097524764728e-05, 2.997398649411256e-05},
                    {4.5560381914805524e-05, 4.505729344690302e-05, 3.6023429831419241e-05},
                    {4.1894476836748102e-05, 4.7288134674904882e-06, 2.5340019343542841e-05},
                    {4.4162480347965046e-05, 7.3658144070069782e-07, 2.5569670461907769e-05},
                    {4.0933605887558714e-05, 6.4201775936859437e-06, 2.5242724481787062e-05},
                    {5.5672139639602234e-05, 3.0086294847494615e-05, 3.6349713269291321e-05},
                    {7.9886466608277313e-05, 9.6138648546572833e-06, 4.8480039439029723e-05},
                    {7.7863676341579838e-05, 1.1324068592926466e-05, 4.746670913840482e-05}},
                   {{0, 1, 4}, {0, 4, 3}, {1, 2, 4}, {2, 5, 4}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17},
                    {18, 19, 20}, {21, 22, 23}},
                   {{5.8463019521040843e-05, 7.8865679372007918e-06, 3.9189215390919104e-05},
                    {3.7309507268589477e-05, 1.0066764513702169e-05, 2.7197502162160874e-05},
                    {6.291593873521691e-05, 7.4276257480449212e-06, 4.1713530483663357e-05},
                    {4.0593706764525474e-05, -1.2716177589876268e-05, 1.9902543764214605e-05},
                    {1.2869052948517034e-05, 2.9585889236234833e-06, 8.1887876409192581e-06},
                    {5.3251738670011743e-05, -1.9872805689507798e-05, 2.5250570875224443e-05}},
                   {{0, 1, 2}, {3, 4, 5}}});
    out.push_back({"seed 12 (needle_threshold, 1e5 sizes from the origin)",
                   {{-11.698127645662719, -6.4113227675761113, 16.177768021775798},
                    {-11.698164204570173, -6.4113225635447177, 16.177768021775798},
                    {-11.698147940175259, -6.4113226543128965, 16.177768021775798}},
                   {{0, 1, 2}},
                   {{-11.698128170075487, -6.4113640245553007, 16.177768021775798},
                    {-11.698072881557474, -6.4113791558897013, 16.177768021775798},
                    {-11.698115213714351, -6.4113675704463748, 16.177768021775798}},
                   {{0, 1, 2}}});
    out.push_back({"seed 18 (sliver, 3e6 sizes from the origin)",
                   {{2702807457.8327112, -1257634683.425415, 1255145522.9589636},
                    {2702808422.2711668, -1257634912.9161556, 1255145614.0071325},
                    {2702807491.151403, -1257634926.218899, 1255144558.0556045},
                    {2702808455.5898585, -1257635155.7096395, 1255144649.1037734},
                    {2702808389.1061497, -1257635104.0196257, 1255144683.7559881},
                    {2702807488.0183167, -1257634928.413003, 1255144600.5991266},
                    {2702808346.2142353, -1257635095.6607244, 1255144679.7977092},
                    {2702807628.849813, -1257634742.9645388, 1255145461.4294844},
                    {2702808402.8563242, -1257635006.3186886, 1255145208.1535201},
                    {2702808021.2972555, -1257634876.4939876, 1255145333.0100162},
                    {2702808251.9216781, -1257635077.5455029, 1255144752.2945688},
                    {2702807505.538723, -1257634729.6493287, 1255145227.1633456},
                    {2702807809.3718467, -1257634871.2688291, 1255145033.8565931}},
                   {{0, 1, 3}, {0, 3, 2}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}},
                   {{2702807510.1068249, -1257634789.1191938, 1255145277.5470624},
                    {2702808208.2422743, -1257634914.8082001, 1255145575.8063715},
                    {2702808419.8664913, -1257634952.9080236, 1255145666.217041},
                    {2702807577.1484118, -1257634815.6645195, 1255144923.8291874},
                    {2702807742.2750478, -1257634940.8971887, 1255144767.5589092},
                    {2702807733.2714186, -1257634934.0688021, 1255144776.0796399},
                    {2702808037.7357554, -1257635080.5015161, 1255144657.1516445},
                    {2702808382.3164797, -1257634934.1526923, 1255145342.9248998},
                    {2702808107.6846018, -1257635050.7931466, 1255144796.3615446},
                    {2702807927.0634594, -1257635038.1869576, 1255144674.8610561},
                    {2702807696.1387529, -1257634755.4353287, 1255145482.3760924},
                    {2702807704.4348464, -1257634765.5933318, 1255145453.3656836}},
                   {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}}});
    out.push_back({"seed 11608 (t_junction)",
                   {{0, 0, 0},
                    {-19.431286078124042, -75.4986126158269, 128.11530948978222},
                    {-148.64923739953048, 13.44151810094038, -14.624558896164991},
                    {-168.08052347765454, -62.057094514886522, 113.49075059361724},
                    {-54.082686685362191, -51.64821050055766, 89.837838662503145}},
                   {{0, 1, 2}, {1, 3, 4}, {4, 3, 2}},
                   {{0, 0, 0},
                    {-19.431286078124042, -75.4986126158269, 128.11530948978222},
                    {-148.64923739953048, 13.44151810094038, -14.624558896164991},
                    {-168.08052347765454, -62.057094514886522, 113.49075059361724},
                    {-54.083325616761478, -51.668195815492034, 89.825964368828963}},
                   {{0, 1, 4}, {0, 4, 2}, {1, 3, 4}, {4, 3, 2}}});
    return out;
}

}  // namespace

// Paper and fast mode give the same distance, interval and witness target, bit for bit, on pairs
// where they differed; the interval holds an independent long-double sampling lower bound (every
// target's best sample climbed to its local maximum), lower is at most the witness's distance,
// and the interval is at most 1e-9 of the diagonal wide (plus a sliver witness's slack).
TEST(Degenerate, PaperEqualsFastOnSliversAndTiedTargets) {
    for (const DumpedPair& P : dumped_pairs()) {
        const TriangleMesh A = make_mesh(P.pa, P.fa), B = make_mesh(P.pb, P.fb);
        Box3 box = A.bounds();
        box.add(B.bounds());
        const double diag = box.diagonal();
        const double coord = coordinate_magnitude(A, B);
        const long double tol = 4 * 0x1p-64L * coord + 1e-12L * diag;
        HausdorffOptions paper_opt, fast_opt;
        paper_opt.mode = Mode::Paper;
        fast_opt.mode = Mode::Fast;
        const HausdorffResult paper = hausdorff(A, B, paper_opt), fast = hausdorff(A, B, fast_opt);
        for (int dir = 0; dir < 2; ++dir) {
            const std::string what = std::string(P.name) + (dir ? " B->A" : " A->B");
            const OneSidedResult &p = dir ? paper.b_to_a : paper.a_to_b, &f = dir ? fast.b_to_a : fast.a_to_b;
            EXPECT_EQ(p.distance, f.distance) << what;
            EXPECT_EQ(p.lower, f.lower) << what;
            EXPECT_EQ(p.upper, f.upper) << what;
            EXPECT_EQ(p.target, f.target) << what;
            const TriangleMesh &from = dir ? B : A, &to = dir ? A : B;
            const long double far = climbed_maximum(from, to, 16);
            for (const OneSidedResult* s : {&p, &f}) {
                const std::string m = what + " (" + (s == &p ? "paper" : "fast") + ")";
                EXPECT_GE((long double)s->upper + tol, far) << m << ": upper " << s->upper << " below a sample at " << (double)far;
                const auto wc = from.corners(s->target);
                const L3 x = closest_on_triangle(ld(s->from_point), ld(wc[0]), ld(wc[1]), ld(wc[2]));
                EXPECT_LE((long double)s->lower, distance_ld(x, to) + tol + 4 * 0x1p-52L * coord)
                    << m << ": lower " << s->lower << " above the witness's distance " << (double)distance_ld(x, to);
                EXPECT_LE(s->lower, s->distance) << m;
                EXPECT_LE(s->distance, s->upper) << m;
                // The width: 1e-9 of the diagonal, and lower below the witness by its target's slack
                // when that is a sliver (its true maximum may lie off it by its height).
                const TargetFrame wf = TargetFrame::make(wc);
                double slack = 0;
                if (wf.degenerate)
                    for (const Vec2& q : wf.corners) slack = std::max(slack, std::fabs(q.y) * wf.scale);
                EXPECT_LE(s->upper - s->distance, 1e-9 * diag) << m;
                EXPECT_LE(s->upper - s->lower, 1e-9 * diag + slack) << m;
            }
            // 11608 A->B: the tied targets are all polished, so the top 6e-6 from vertex 5 (2.5e-9
            // above the vertex, 1e-11 of the diagonal) is the result in both modes.
            if (std::string(P.name).rfind("seed 11608", 0) == 0 && dir == 0) {
                EXPECT_LE(far - (long double)p.distance, 1e-13L * diag) << what;
            }
        }
    }
}

// Generate_pairs3.py "rot_tiny_far" 3051: a strip of four triangles 700 from the origin against a
// copy turned by 2e-6 about one corner. In the paper's insertion of B's triangle 2 into A's
// target 3 the region of a corner is a sliver along T''s edge, 2.25e-12 wide at most and 8.4e-7
// long, too thin for a chord across it (DomainMesh::kTinyChord): it stays with the edge region
// beside it. Once triangle 3 takes the rest of that domain, a face 2.25e-12 wide remains whose tip
// lies 4.2e-7 beyond the edge region. validate() holds such a face only to its polynomial; the
// test checks that the face is there, that each probe of it lies within kTinyChord of its
// boundary, and that d^2 there is the face's polynomial to the rim allowance.
TEST(Degenerate, FaceThinnerThanATinyChordIsHeldToItsPolynomial) {
    const double x = -518.0485605789409;
    const TriangleMesh A = make_mesh({{x, -45.38512635526228, -706.1413390681194}, {x, -44.88512635526228, -706.1413390681194},
                                      {x, -44.38512635526228, -706.1413390681194}, {x, -45.38512635526228, -707.1413390681194},
                                      {x, -44.88512635526228, -707.1413390681194}, {x, -44.38512635526228, -707.1413390681194}},
                                     {{0, 3, 1}, {3, 4, 1}, {1, 4, 2}, {4, 5, 2}});
    const TriangleMesh B = make_mesh({{-518.0485605789409, -45.38512635526228, -706.1413390681194},
                                      {-518.0485607507644, -44.885126355263466, -706.1413401434219},
                                      {-518.048560922588, -44.38512635526465, -706.1413412187244},
                                      {-518.04856039356, -45.38512850586722, -707.1413390681171},
                                      {-518.0485605653836, -44.88512850586841, -707.1413401434195},
                                      {-518.0485607372073, -44.385128505869595, -707.141341218722}},
                                     {{0, 3, 1}, {3, 4, 1}, {1, 4, 2}, {4, 5, 2}});
    const VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 3);
    ts.on_event([](const Event&) {});  // watched: the paper's insertion
    int slivers = 0;
    while (ts.step()) {
        EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
        const DomainMesh& m = *ts.domain_mesh();
        for (size_t f = 1; f < m.faces().size(); ++f) {
            if (!m.faces()[f].alive || m.faces()[f].infinite) continue;
            const Box2 b = m.face_box((int)f);
            if (!(m.face_area((int)f) <= DomainMesh::kTinyChord * norm(b.hi - b.lo))) continue;
            ++slivers;
            Vec2 p;
            ASSERT_TRUE(m.interior_point((int)f, p));
            EXPECT_TRUE(m.near_boundary((int)f, p, DomainMesh::kTinyChord)) << "face " << f;
            // d^2 is about 5e-12 here (frame units): its gradient, 2 d, times twice the vertex
            // tolerance is the rim allowance validate() gives the polynomial.
            const double d2 = ts.direct_d2(p);
            EXPECT_NEAR(m.faces()[f].poly(p), d2, 4 * std::sqrt(d2) * 2 * DomainMesh::kVertexTolerance) << "face " << f;
        }
    }
    EXPECT_GT(slivers, 0);
}

// Generate_pairs3.py "rot_tiny_far" 6887: a tetrahedron 1.2e7 from the origin against a copy turned
// by 2e-6. Over A's face 2, two faces of the copy meet on an edge that pierces T''s plane 1.2e-6
// outside T''s edge, near a corner; the difference of their planes' quadratics is a line pair whose
// centre is that point, and its lines cross T''s edge 1.4e-6 apart. In the paper's insertion the
// split took the two crossings for one touching point at the centre (split_at_touching_point), so
// neither line's chord had an end there and a piece 2e-6 long near the corner kept the farther
// plane: 2.0e-12 where d^2 is 2.2e-13 (frame units). Now crossings on the lines stay crossings.
TEST(Degenerate, LinePairCentreJustOutsideTheTargetKeepsBothCrossings) {
    const std::vector<Tri> tetra = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    const TriangleMesh A = make_mesh({{-11361719.651319886, 2615948.73976005, -4524476.0993976975},
                                      {-11361719.651319886, 2615946.73976005, -4524478.0993976975},
                                      {-11361721.651319886, 2615946.73976005, -4524476.0993976975},
                                      {-11361721.651319886, 2615948.73976005, -4524478.0993976975}},
                                     tetra);
    const TriangleMesh B = make_mesh({{-11361719.651313774, 2615948.7397551904, -4524476.099398949},
                                      {-11361719.651325997, 2615946.7397574075, -4524478.099401166},
                                      {-11361721.651321277, 2615946.7397626927, -4524476.099396446},
                                      {-11361721.651318494, 2615948.7397649097, -4524478.099394229}},
                                     tetra);
    const VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 2);
    ts.on_event([](const Event&) {});  // watched: the paper's insertion
    ts.validate_each_insertion(true);
    EXPECT_NO_THROW(while (ts.step()) {});
    // 1e-6 inside T''s edge, 3e-6 from its corner, and more than 1e-7 from the domain's boundary.
    // The polynomial agrees with d^2 to 8e-17 (4e-4 relative), far within the rounding of
    // quadratics from corners 1.2e7 from the origin (TargetSolver::rounding_sq, 5.7e-14 here);
    // before, it was 9 times d^2.
    expect_polynomial_is_d2(ts, {0.499999013, 0.866021901}, 1e-3);
}

// Generate_pairs.py "tjunction" 38792: over A's target 0 a corner of B's triangle 1 is nearer than
// triangle 0's face on an ellipse 0.06 across lying wholly inside that face's domain. The split
// inserts the ellipse as a closed chord: its inner side a new piece, its outer side a hole of the
// domain. The hole was given to the outer loop enclosing a point on it, the smallest such, and the
// ellipse's own inner loop, on which that point lies too, counted as enclosing it: the domain kept
// its outer loop alone, the ellipse became a piece of no area, and the corner's domain was lost
// (d^2 0.0227 where it is 0.0219, nearest first and in the paper's order). Both orders, every
// insertion; and at that point the polynomial is d^2.
TEST(Degenerate, ClosedChordInsideAFaceIsAHoleOfIt) {
    const TriangleMesh A = make_mesh({{-0.0015622893001202046, -0.0023385332563889095, 0.0046115970846689483},
                                      {0.0014637826359506782, -0.0016090808231238258, 0.004458214684548505},
                                      {-0.00076291191620679794, -0.00050378781124775637, 0.0061441237106872552},
                                      {0.00023979530175257334, -0.0041420501014721731, 0.0023659052406149518}},
                                     {{0, 1, 2}, {0, 1, 3}});
    const TriangleMesh B = make_mesh({{0.0017642094868197309, -0.00057511302892776072, 0.0053641266190710048},
                                      {0.0013250279060435892, -0.0016425284666352967, 0.0044652477405864414},
                                      {0.0036818124819957606, -0.0029395823048578929, 0.0025590015281293011},
                                      {0.0031869631493827645, -0.0030635497523956714, 0.0043754552024143026},
                                      {0.0028882327887862908, -0.001481087512533963, 0.0021244582948203037},
                                      {-4.9253332084763088e-05, -0.0019738070397563676, 0.0045349058846087271},
                                      {-0.00073819346977193798, -0.0021398801108620108, 0.0045698261687560273},
                                      {0.0007380121016651634, -0.0022492235448674258, 0.0040493597112593177},
                                      {0.00033392134236506061, -0.0018814405314419951, 0.0045154839235733938},
                                      {6.6329342931463996e-05, -0.001030866175982048, 0.004946002223131957},
                                      {-0.0013782834679294282, 0.0014033758747002789, 0.0050814132053651657},
                                      {-0.00092995936582491805, -0.0012873782107105099, 0.0054405058908278299}},
                                     {{6, 0, 10}, {1, 2, 9}, {8, 11, 4}, {5, 7, 3}});
    validate_every_insertion(A, B);
    const VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, 0);
    ts.run();
    const Vec2 p{0.555517248, 0.393583492};  // inside the ellipse, 0.03 from it
    expect_polynomial_is_d2(ts, p, 1e-7);
}

// Generate_pairs.py "sliver" 37698, the paper's order: a strip of needles 2e-8 wide and 2e4 long
// (1e-13 of T' across), under a target 4.6e4 across. Where a needle's corner is nearer than its
// neighbour's edge, g is a parabola 1e12 times longer than wide, lying along a region line: its tip
// is where rounding puts it, and a chord ended at a vertex 2e-5 from the tip (kFlatTip) started
// its arc at the tip. The lens between that arc and the region line, 4e-10 wide, left a gap of 2e-5
// between its line and its arc, and the ray test, blind to the gap, counted a point 7e-6 outside
// the corner's region as inside the lens: validate() held the corner's quadratic there, 18% above
// d^2 (the edge's). The loop is closed by straight connectors from a vertex to its arc's end.
TEST(Degenerate, ArcStartingAtAFlatTipIsJoinedToItsVertex) {
    const TriangleMesh A = make_mesh({{6002.4901253876633, -165.45065957926636, 17424.678027266717},
                                      {2353.8443716082593, -1899.4604081437196, 16748.061181990928},
                                      {-1294.8013821711461, -3633.470156708172, 16071.44433671514},
                                      {-4943.4471359505505, -5367.4799052726248, 15394.82749143935},
                                      {-8592.0928897299564, -7101.4896538370785, 14718.210646163559},
                                      {6002.4901253862026, -165.45065958345549, 17424.678027285336},
                                      {2353.8443716067977, -1899.4604081479088, 16748.061182009544},
                                      {-1294.8013821726076, -3633.4701567123616, 16071.444336733757},
                                      {-4943.4471359520121, -5367.4799052768149, 15394.827491457965},
                                      {-8592.092889731417, -7101.4896538412677, 14718.210646182179},
                                      {-427.67077866460386, 2652.7005376999682, 14306.205587334141},
                                      {4031.1413443020792, 16818.008945456964, 11800.121318497615},
                                      {-941.40647467992653, 1738.7396539674926, 10327.494864908991}},
                                     {{0, 1, 5}, {1, 6, 5}, {1, 2, 6}, {2, 7, 6}, {2, 3, 8}, {2, 8, 7},
                                      {3, 4, 8}, {4, 9, 8}, {10, 11, 12}});
    const TriangleMesh B = make_mesh({{-3990.2578466429586, -20.828886543856697, -10876.356764780643},
                                      {-15126.370766191339, -11021.839179125574, 17910.907530139411},
                                      {11970.773539928876, 62.486659631571456, 32629.070294341931},
                                      {23106.886459477257, 11063.496952213289, 3841.8059994218765}},
                                     {{0, 1, 2}, {0, 2, 3}});
    const VoxelGrid grid(A, B, 1.0, 1);
    TargetSolver ts(grid, 1, 0);
    ts.on_event([](const Event&) {});  // the paper's insertion
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    const Vec2 p{0.393265209, 0.087352548};  // 7.2e-6 outside the corner's region, in its edge's
    expect_polynomial_is_d2(ts, p, 1e-3);
    const int f = ts.domain_mesh()->face_at(p);
    ASSERT_GT(f, 0);
    EXPECT_NE(ts.domain_mesh()->faces()[f].label.region, Region::b);
}

// Generate_pairs3.py "sliver" 11734, the paper's order: needles along the diagonal of a grid, in
// its plane. One needle's corner region is a wedge 5e-7 wide per unit of length; the next needle's
// region line crosses it where it is 3e-12 wide, less than a chord the splits insert (kTinyChord),
// so the wedge's tip beyond the line, 5.4e-6 long, stays with the rest of the wedge, in the edge
// region above the line, d^2 7e-12 by its polynomial beside 0 across its side. validate() took
// that for a jump of d^2; it now allows it across a sliver thinner than kTinyChord. Just beside
// the tip, d^2 is that of the needle, 0.
TEST(Degenerate, WedgeTipThinnerThanATinyChordIsNoJump) {
    const TriangleMesh A = make_mesh({{-1.5, -1.5, 0}, {-1.5, 0, 0}, {-1.5, 1.5, 0}, {0, -1.5, 0}, {0, 0, 0},
                                      {0, 1.5, 0}, {1.5, -1.5, 0}, {1.5, 0, 0}, {1.5, 1.5, 0}},
                                     {{0, 3, 4}, {0, 4, 1}, {1, 4, 5}, {1, 5, 2}, {3, 6, 7}, {3, 7, 4}, {4, 7, 8}, {4, 8, 5}});
    const TriangleMesh B = make_mesh({{0, 0, 0},
                                      {1, 1, 0},
                                      {0.38210877907368773, 0.38210877906375, 0},
                                      {0.7017347063417019, 0.7017347063417236, 0},
                                      {0.029043409911972455, 0.029043385798283756, 0},
                                      {0.41381438612549937, 0.41381464655259814, 0},
                                      {0.020503854359354236, 0.02052434414555545, 0},
                                      {0.6318550271430906, 0.6318800980632672, 0},
                                      {0.8926045735172259, 0.8926045733801282, 0},
                                      {0.8941192965616946, 0.8941192965620128, 0},
                                      {0.9612102026235669, 0.9612102025758433, 0},
                                      {0.048774945938697946, 0.048774986367953375, 0}},
                                     {{5, 0, 1}, {7, 0, 1}, {1, 8, 0}, {3, 0, 1}, {9, 0, 1}, {0, 1, 6},
                                      {4, 0, 1}, {2, 0, 1}, {0, 1, 10}, {1, 11, 0}});
    const VoxelGrid grid(A, B, 1.0, 1);
    TargetSolver ts(grid, 0, 7);
    ts.on_event([](const Event&) {});  // the paper's insertion
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    const DomainMesh& dm = *ts.domain_mesh();
    for (double y : {1e-6, 3e-6, 5e-6})
        for (double x : {0.2758763432, 0.2758763452}) {  // 1e-9 either side of the tip
            const Vec2 p{x, y};
            const int f = dm.face_at(p);
            ASSERT_GT(f, 0);
            EXPECT_NEAR(dm.faces()[f].poly(p), ts.direct_d2(p), 1e-14) << x << " " << y;
        }
}

// Generate_pairs3.py "sliver" 12014 in a hand case: a target 2e-13 across over the middle of a
// source 9e-13 high, so every point of the target lies over the source's face. The distance is the
// height of its top corner, 2e-13. The search takes a triangle that thin as its edges (4.9e-13
// from that corner), and the lower end, from the witness's distance by the same evaluation, was
// above the truth: it now takes each triangle's distance from below (triangle_distance_lower).
TEST(Degenerate, LowerEndHoldsOverASourceTakenAsItsEdges) {
    const TriangleMesh A = make_mesh({{0.5 - 1e-13, 3e-13, 1e-13}, {0.5 + 1e-13, 3e-13, 1e-13}, {0.5, 4.5e-13, 2e-13}}, {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0, 0, 0}, {1, 0, 0}, {0.5, 9e-13, 0}}, {{0, 1, 2}});
    const VoxelGrid grid(A, B);
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = one_sided(grid, 0, opt);
        EXPECT_LE(r.lower, 2e-13) << mode_name(mode);
        EXPECT_GE(r.upper, 2e-13) << mode_name(mode);
        EXPECT_LE(r.lower, r.distance) << mode_name(mode);
    }
}

// Generate_pairs.py "zeroarea" 42181, nearest first: a cube against a copy moved by 4e-8 (T' 5.5e-3
// across, 1.7e4 from the origin). A source region's line passes 7.7e-10 from a vertex where the
// face's boundary, a curved arc, runs along it: two chords end there. The first chord's tangent
// came out 2.9e-5 rad beyond the boundary arc's, so the wedge between them read as a whole turn
// less 2.9e-5, and it took the second chord: one piece where there were three, and a strip 1.4e-5
// wide where the copy's face is nearer kept the cube's other face, d^2 70% above (to the end of
// the construction). Such nearly full wedges now wait for the secants (find_wedge).
TEST(Degenerate, NearlyFullWedgeWaitsForTheSecants) {
    const TriangleMesh A = make_mesh({{17080.375659006972, 21.567161957182378, -2488.6408128371991},
                                      {17080.382617014784, 21.567161957182378, -2488.6408128371991},
                                      {17080.375170725722, 21.568993011869878, -2488.6444749465741},
                                      {17080.375170725722, 21.565086761869878, -2488.6405686965741},
                                      {17080.375170725722, 21.568993011869878, -2488.6405686965741},
                                      {17080.371264475722, 21.568993011869878, -2488.6444749465741},
                                      {17080.379443186659, 21.567161957182378, -2488.6408128371991},
                                      {17080.371264475722, 21.565086761869878, -2488.6444749465741},
                                      {17080.371264475722, 21.565086761869878, -2488.6405686965741},
                                      {17080.375170725722, 21.565086761869878, -2488.6444749465741},
                                      {17080.371264475722, 21.568993011869878, -2488.6405686965741}},
                                     {{7, 3, 8}, {7, 8, 5}, {7, 9, 3}, {8, 3, 10}, {9, 2, 3}, {8, 10, 5}, {5, 10, 2},
                                      {10, 4, 2}, {5, 2, 9}, {1, 6, 0}, {7, 5, 9}, {3, 4, 10}, {2, 4, 3}});
    const TriangleMesh B = make_mesh({{17080.371264510537, 21.565086776406286, -2488.6444749609909},
                                      {17080.371264494577, 21.565086743254689, -2488.6405686897247},
                                      {17080.37126445994, 21.568993065063438, -2488.6444749562779},
                                      {17080.371264513527, 21.568992971417124, -2488.6405687207171},
                                      {17080.375170678417, 21.56508676210942, -2488.6444748829726},
                                      {17080.375170713578, 21.565086745830339, -2488.6405687049505},
                                      {17080.375170753934, 21.56899300410824, -2488.6444749570742},
                                      {17080.37517070126, 21.568992956846429, -2488.6405686851222},
                                      {17080.373217624256, 21.567039873681466, -2488.6425218233994}},
                                     {{0, 2, 1}, {3, 2, 1}, {6, 5, 4}, {6, 5, 7}, {0, 5, 4}, {0, 5, 1}, {2, 3, 6},
                                      {7, 6, 3}, {0, 4, 2}, {2, 6, 4}, {1, 5, 3}, {7, 3, 5}, {6, 1, 8}});
    const VoxelGrid grid(A, B, 1.0, 1);
    TargetSolver ts(grid, 0, 6);
    ts.nearest_first();
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    const Vec2 p{0.500006956, 0.499985077};  // in the strip
    expect_polynomial_is_d2(ts, p, 1e-3);
}

// Generate_pairs3.py "coinc_retri_far" 13964, nearest first: a hexagonal prism against a copy
// moved by 5e-9 (T' 3.7e-4 across). Two sources' edges parallel to T''s edge differ by a linear g
// plus rounding in its quadratic part, 2e-15 of it, which made an ellipse 1e10 across: its points,
// an ulp of 1e10 off, missed a face 1e-5 across, and no chord was found. A strip 2e-6 wide where
// the second edge is nearer kept the first (d^2 5.3e-11 where it is 2.3e-11). A quadratic part
// that moves g by less than a thousandth of the zero tolerance on the face is now dropped.
TEST(Degenerate, QuadraticPartBelowRoundingLeavesTheLine) {
    const TriangleMesh A = make_mesh({{3.2459069342159674, 0.00022446692227889807, 0.0002591920760037772},
                                      {3.2456477421399637, 0.0002244669222788981, 0.0},
                                      {3.2459069342159674, 0.00022446692227889807, 0.0},
                                      {3.2460365302539693, 0.0, 0.0},
                                      {3.2460365302539693, 0.0, 0.0002591920760037772},
                                      {3.2455181461019618, 3.174187462423833e-20, 0.0002591920760037772},
                                      {3.2456477421399637, -0.000224466922278898, 0.0},
                                      {3.2456477421399637, -0.000224466922278898, 0.0002591920760037772},
                                      {3.2459069342159674, -0.00022446692227889807, 0.0002591920760037772},
                                      {3.2455181461019618, 3.174187462423833e-20, 0.0},
                                      {3.2456477421399637, 0.0002244669222788981, 0.0002591920760037772},
                                      {3.2459069342159674, -0.00022446692227889807, 0.0}},
                                     {{7, 5, 9}, {1, 10, 2}, {0, 3, 2}, {3, 11, 6}, {11, 4, 8}, {7, 9, 6}, {2, 10, 0},
                                      {4, 5, 7}, {11, 3, 4}, {5, 1, 9}, {3, 9, 1}, {11, 8, 6}, {5, 10, 1}, {0, 10, 4},
                                      {3, 0, 4}, {10, 5, 4}, {6, 8, 7}, {3, 1, 2}, {8, 4, 7}, {3, 6, 9}});
    const TriangleMesh B = make_mesh({{3.245647740264008, 0.00022446433222161134, -5.252231648106225e-09},
                                      {3.2459069323400116, 0.00022446433222161132, -5.252231648106225e-09},
                                      {3.2459069323400116, 0.00022446433222161132, 0.00025918682377212913},
                                      {3.245518144226006, -2.590057286707758e-09, -5.252231648106225e-09},
                                      {3.2459069323400116, -0.0002244695123361848, 0.00025918682377212913},
                                      {3.245647740264008, -0.00022446951233618474, 0.00025918682377212913},
                                      {3.245647740264008, -0.00022446951233618474, -5.252231648106225e-09},
                                      {3.2460365283780135, -2.5900572867394995e-09, 0.00025918682377212913},
                                      {3.245647740264008, 0.00022446433222161134, 0.00025918682377212913},
                                      {3.2459069323400116, -0.0002244695123361848, -5.252231648106225e-09},
                                      {3.245518144226006, -2.590057286707758e-09, 0.00025918682377212913},
                                      {3.2460365283780135, -2.5900572867394995e-09, -5.252231648106225e-09}},
                                     {{2, 7, 11}, {11, 9, 6}, {9, 11, 7}, {0, 10, 8}, {3, 11, 6}, {0, 1, 11}, {11, 1, 2},
                                      {3, 0, 11}, {4, 5, 6}, {2, 1, 8}, {4, 6, 9}, {10, 7, 8}, {8, 1, 0}, {0, 3, 10},
                                      {5, 10, 3}, {7, 4, 9}, {7, 5, 4}, {5, 3, 6}, {5, 7, 10}, {7, 2, 8}});
    const VoxelGrid grid(A, B, 1.0, 1);
    TargetSolver ts(grid, 1, 0);
    ts.nearest_first();
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
}

// Generate_pairs3.py "sliver" 14674: needles in one plane against a copy jittered by 3e-6. Fast
// mode cut a needle target into pieces; the piece at its far corner is 1.8e-7 tall for its length,
// and the nearest source's region line crossed it 4.3e-5 before the corner, where it was 7.7e-12
// wide: no chord (kTinyChord), so the tip kept the source edge's polynomial, 8.6e-11 (frame units)
// where d^2 is 1.9e-9. The piece's maximum, from that polynomial, was below L, it stopped early,
// and the target holding paper mode's witness (that corner) was left to the confirmation: fast
// mode's distance came out 1.9e-17 below paper mode's. A corner's candidate is now held to d^2
// there. The corner's distance, 2.716004291271859e-06, is exact rational arithmetic on the inputs.
TEST(Degenerate, CornerOfAThinPieceIsHeldToItsDistance) {
    const TriangleMesh A = make_mesh(
        {{0.932623493553276, -0.40884791214729277, 0}, {0.013636429420541774, -0.8031355938680103, 0}, {3.253252020977896, 0.5868083660268099, 0},
         {0.9088345546458734, 0.9341973626464439, 0}, {1.8576341684791804, 0.6183187581323558, 0}, {1.0812086212365704, 0.8768107113858713, 0},
         {-0.016109316400517937, -0.4527482771182241, 0}, {0.42362205524627095, 0.4453810681264537, 0}, {0.42362205521944674, 0.4453810681395871, 0},
         {0.7642713373940555, 0.026658595103773663, 0}, {-0.06686042347935328, -0.5294169357977998, 0}, {2.6799699786370725, 1.3083725051305335, 0},
         {-0.7843953175733009, 0.9938174030700186, 0}, {-1.0688346138745786, 1.9525114557894638, 0}, {-1.05125435455571, 1.89325724996151, 0},
         {-0.9835874236347761, 0.10431586759463096, 0}, {-0.13167915800232322, 0.6280069090943936, 0}, {-0.13167894322363805, 0.6280072547585518, 0},
         {-0.2811766024751421, -0.21728645350307163, 0}, {-0.8575447795580936, -1.0344765932172484, 0}, {-0.8575447795325128, -1.0344765932352904, 0}},
        {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}});
    const TriangleMesh B = make_mesh(
        {{0.4236229414988239, 0.4453817311251068, 0}, {-0.7843937754368747, 0.9938164072760267, 0}, {0.7642731918993251, 0.02665682855620675, 0},
         {0.9326233528852366, -0.40884623774293943, 0}, {-0.8575438510363179, -1.034475578416756, 0}, {0.4236225080536916, 0.4453791652819478, 0},
         {-0.8575466330370093, -1.0344781583030893, 0}, {-1.0688329943789066, 1.9525134141838387, 0}, {-0.28117510591348677, -0.21728536560804051, 0},
         {-0.13167900139341382, 0.6280053211592797, 0}, {2.679969628689901, 1.3083715131024223, 0}, {-0.9835854666306936, 0.10431775089342066, 0},
         {0.01363448300490351, -0.8031370199232937, 0}, {1.0812068986069898, 0.876810334034666, 0}, {-0.016111028347153125, -0.4527501520162352, 0},
         {-1.0512536116266857, 1.893257904808888, 0}, {-0.1316805277941275, 0.6280056779782485, 0}, {3.2532499688630008, 0.5868074958876383, 0},
         {0.9088356948378441, 0.9341967916017351, 0}, {-0.06685979548639988, -0.529416817393104, 0}, {1.857633681685374, 0.618319118909403, 0}},
        {{9, 11, 16}, {5, 0, 14}, {20, 13, 18}, {15, 1, 7}, {6, 8, 4}, {10, 2, 19}, {3, 12, 17}});
    const VoxelGrid grid(A, B, 1.0, 1);
    const double corner = 2.716004291271859e-06;  // d(A's corner 15, B)
    // The piece as fast mode cut it, stopped below L (the corner's squared distance less the tie margin).
    const std::array<Vec3, 3> piece = {Vec3{-0.98358742363477614, 0.10431586759463096, 0},
                                       Vec3{-0.93034315703274784, 0.13704655768836613, 0},
                                       Vec3{-0.93034314360907999, 0.13704657929237601, 0}};
    TargetSolver ts(grid, 0, 5, piece);
    ts.stop_below(0.99999 * corner * corner);
    ts.run();
    EXPECT_FALSE(ts.stopped_early());
    EXPECT_GE(std::sqrt(ts.upper_sq()), corner * (1 - 1e-12));
    HausdorffOptions paper, fast;
    paper.mode = Mode::Paper;
    fast.mode = Mode::Fast;
    const OneSidedResult p = one_sided(grid, 0, paper), f = one_sided(grid, 0, fast);
    EXPECT_EQ(p.distance, f.distance);
    EXPECT_NEAR(p.distance, corner, 1e-15);
    EXPECT_LE(p.lower, corner);
    EXPECT_GE(p.upper, corner);
}

// h(A, B) in both modes: the certified interval reaches `at_least` (a lower bound of the truth)
// from above and `at_most` (an upper bound) from below, lower <= distance, and it is no wider than
// 1e-9 of the diagonal (issue 8's goal).
// `allowance`: width allowed beyond the goal (a sliver target's height, which its bound may add).
static void expect_narrow_interval_holding(const TriangleMesh& A, const TriangleMesh& B, double at_least, double at_most,
                                           double allowance = 0) {
    const VoxelGrid grid(A, B);
    Box3 box = A.bounds();
    box.add(B.bounds());
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = one_sided(grid, 0, opt);
        EXPECT_GE(r.upper, at_least) << mode_name(mode);
        EXPECT_LE(r.lower, at_most) << mode_name(mode);
        EXPECT_LE(r.lower, r.distance) << mode_name(mode);
        EXPECT_LE(r.upper - r.lower, allowance + 1e-9 * box.diagonal()) << mode_name(mode);
    }
}

// A sliver target's witness lies on its edges in the frame; the lower end took it to lie off the
// sliver by up to its height and subtracted that (generate_pairs4.py "thin_shell_far" 187: the
// lower end 0 where the distance was 4.2e-4, a rim sliver 8e-4 high, coordinates 4e9). Now the
// witness is taken to the nearest point of the target itself. Here a sliver 1024 long and 1e-5
// high (1e-8 of its length: handled as its edges) lies flat 1e-3 above a square, 2^20 from the
// origin: every point of it is exactly 1e-3 from the square, so that is the distance, and the
// interval must be narrower than 1e-9 of the diagonal (it was 1e-5 wide).
TEST(Degenerate, SliverWitnessIsTakenOntoTheSliver) {
    const double X = 1048576, Z = 1048576, d = 0x1p-10;  // 2^-10 = 9.8e-4, exact
    const TriangleMesh A = make_mesh({{X, X, Z + d}, {X + 1024, X, Z + d}, {X + 512, X + 1e-5, Z + d}}, {{0, 1, 2}});
    const TriangleMesh B =
        make_mesh({{X - 64, X - 64, Z}, {X + 1088, X - 64, Z}, {X + 1088, X + 64, Z}, {X - 64, X + 64, Z}}, {{0, 1, 2}, {0, 2, 3}});
    expect_narrow_interval_holding(A, B, d, d);
}

// A sliver 5e4 long and 3e-8 wide (generate_pairs8.py "mixed_scale_sim" 702: a similarity of a
// 1e6 square with 1e-6 triangles on it and a sliver along its diagonal) against a target 4e-8
// across on its diagonal. The sliver's normal, rounded over its area, is off by some 1e-7, and its
// plane's quadratic was taken through its first corner, 1.2e4 (3e11 frame units) from the target:
// 2696 at a point whose foot lies inside the sliver 1e-12 from it (d^2 1.1e-24, exact rational
// arithmetic from the input doubles, 5e-10 in frame units), and validate() saw d^2 jump by 0.5
// across an arc. The plane is now taken through the sliver's point nearest the target.
// Oracle: d^2 in long double on a grid over the target, each point's height over a source's plane
// taken from its foot on the nearest edge's line (brute_distance in double, and distance_ld, which
// takes a source this thin as its edges, are off by up to 0.05 of T' in d^2 here).
long double sliver_d2_ld(const L3& p, const L3& a, const L3& b, const L3& c) {
    long double best = std::min({segment_d2(p, a, b), segment_d2(p, b, c), segment_d2(p, c, a)});
    const L3 n = crossl(b - a, c - a);
    const long double nn = dotl(n, n);
    if (!(nn > 0) || !projects_inside((p - a) - n * (dotl(p - a, n) / nn), a, b, c, n)) return best;
    L3 from = p - a;
    long double nearest = HUGE_VALL;
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const L3 e = v - u, w = p - u, r = w - e * (dotl(w, e) / dotl(e, e));  // p less its foot on the line
        if (dotl(r, r) < nearest) nearest = dotl(r, r), from = r;
    }
    const long double h = dotl(from, n);
    return std::min(best, h * h / nn);
}

// sliver_d2_ld over B at p (frame), the point taken in long double from the frame (no world
// point's rounding), in frame units.
long double brute_d2_ld(const TargetFrame& f, const TriangleMesh& B, Vec2 p) {
    const L3 w = ld(f.origin) + ld(f.e1) * ((long double)p.x * f.scale) + ld(f.e2) * ((long double)p.y * f.scale);
    long double d2 = HUGE_VALL;
    for (size_t t = 0; t < B.num_triangles(); ++t) {
        const auto s = B.corners(t);
        d2 = std::min(d2, sliver_d2_ld(w, ld(s[0]), ld(s[1]), ld(s[2])));
    }
    return d2 / ((long double)f.scale * f.scale);
}

// grid_points_off against brute_d2_ld over B.
int grid_points_off_d2_ld(const TargetSolver& ts, const TriangleMesh& B, int n, double tol) {
    return grid_points_off(*ts.domain_mesh(), ts.frame(), n, tol, [&](Vec2 p) { return brute_d2_ld(ts.frame(), B, p); });
}

// The probe of the constructions checked in long double: d^2 on a 24 x 24 grid over T' against
// sliver_d2_ld over B to `tol`, and the overlay's nearest-feature map.
void expect_d2_ld_and_labels(const TargetSolver& ts, const TriangleMesh& B, double tol) {
    EXPECT_EQ(grid_points_off_d2_ld(ts, B, 24, tol), 0);
    const LabelCheck L = check_labels(*ts.domain_mesh(), ts.frame(), inserted_corners(ts), ts.inserted_sources());
    EXPECT_EQ(L.disagree, 0) << L.first;
}

TEST(Degenerate, SliverPlaneIsTakenThroughItsPointNearestTheTarget) {
    const TriangleMesh target = make_mesh({{-3659.7953959393876, 6688.814004763557, -9620.8646633590561},
                                           {-3659.7953959234778, 6688.8140047837396, -9620.8646633824046},
                                           {-3659.7953959699362, 6688.8140047701318, -9620.8646633741919}},
                                          {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0, 0, 0},
                                      {15910.327942029378, 20181.163449643533, -23348.342181082178},
                                      {-14639.181583740045, 26755.256018944317, -38483.458653519301},
                                      {-30549.509525769423, 6574.0925693007875, -15135.116472437128},
                                      {15910.327942033755, 20181.163449616055, -23348.342181102948},
                                      {15910.327942049664, 20181.163449636235, -23348.342181126292},
                                      {8455.8486541903076, 16898.346553000025, -20575.743952811205},
                                      {8455.8486542062183, 16898.346553020208, -20575.743952834553},
                                      {8455.8486541859311, 16898.346553027506, -20575.743952790435},
                                      {15910.327942025, 20181.163449671007, -23348.342181061409},
                                      {15910.327942040909, 20181.16344969119, -23348.342181084754},
                                      {15910.327942020625, 20181.163449698488, -23348.34218104064},
                                      {-4.3762893552703873e-09, 2.7478444728879513e-08, 2.0768874374166526e-08},
                                      {-14639.181583744423, 26755.256018971795, -38483.458653498536},
                                      {-7319.5907919049487, 13377.628009506212, -19241.729326754019}},
                                     {{0, 1, 2}, {0, 2, 3}, {4, 5, 1}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}});
    const TargetFrame fr = TargetFrame::make(target.corners(0));
    const SourceProjection sliver = project_source(fr, B.corners(5), 5);
    EXPECT_LT((*region_quadratic(sliver, Region::abc))({0.509765625, 0.474609375}), 1e-6);
    expect_constructions_hold(target, B, [&](const TargetSolver& ts) { expect_d2_ld_and_labels(ts, B, 1e-3); });
}

// Two slivers of a fan (67 long, 5e-6 rad at their common apex, the origin), sharing a spoke,
// against a target 1.3e-9 across at the apex (generate_pairs9.py "sliver_fan_tiny" 2287, side B,
// target 7, and A's first two triangles). Each sliver stands within 5e-6 rad of perpendicular to
// T', so its side planes along the spokes are within 7e-6 of T''s plane, and their lines on T'
// are their offsets over 7e-6. Taken through the spokes' far ends, 5e10 frame units away, whose
// frame coordinates are rounded by 1e-5, the face region's line was 0.3 of T' off: the face region
// held points whose foot lies outside the sliver, and d^2 jumped by 0.0115 across a region line
// after the second insertion. A plane along an edge is now taken through the edge's end near T'.
// Oracle: d^2 in long double on a grid over T' (brute_distance in double cannot place a foot on
// a sliver 5e-15 wide there) after every insertion, in three orders, to 1e-5 (the sources' frame
// coordinates are known to 7e-4 there, and the tie rule makes the shared spoke's quadratic one
// with the second sliver's plane, 4e-7 apart on T').
TEST(Degenerate, SidePlaneOfASliverIsTakenThroughItsEndNearTheTarget) {
    const TriangleMesh target = make_mesh({{7.6099605375838521e-10, 2.611947839363066e-10, 1.0004218622279919e-10},
                                           {-5.0597872008531451e-10, -5.0422573776981817e-11, -2.0948452776017841e-11},
                                           {1.6889122724633073e-10, 2.8982589804812518e-10, 1.0793111788573306e-10}},
                                          {{0, 1, 2}});
    const TriangleMesh fan = make_mesh({{0, 0, 0},
                                        {-65.317855855817001, -14.825735264471474, -5.7792954120781115},
                                        {-65.317854492075355, -14.825609627696776, -5.7796331235295488},
                                        {-65.317856032017247, -14.825734585704129, -5.7792951619097801}},
                                       {{0, 1, 2}, {0, 2, 3}});
    expect_constructions_hold(target, fan, [&](const TargetSolver& ts) { expect_d2_ld_and_labels(ts, fan, 1e-5); });
}

// Segments (zero-area triangles) crossing at one point of a target 3e-4 across, and a sliver
// lying in T''s plane through it (generate_pairs9.py "zeroarea_cross_tiny" 1266, side A, target
// 1). Two segments standing across T' at that point, 1e-11 apart, and a third lying along T' 1e-11
// off it leave a lens 9e-6 long there between two domains' arcs. The sliver's edge line crosses
// the lens, both crossings at one point; taken in the order of their parameters (rounding), the
// chords on either side left the face across the lens, became bridges of one loop, and the face
// stayed whole across the line: a wedge where the segment in T''s plane is nearer kept the sliver,
// d^2 0.0465 where the truth is 0.0417 (frame units). Oracle: d^2 in long double on a grid over
// T' after every insertion, in three orders; and the overlay's nearest-feature map.
TEST(Degenerate, ChordsLeaveCoincidentCrossingsIntoTheFace) {
    const TriangleMesh target = make_mesh({{-2.4594415271025743e-05, 6.4953677125102136e-05, 4.6922855175292589e-05},
                                           {-9.3945670332446936e-05, -1.1373884950349302e-05, -0.0002216327906112796},
                                           {-0.00025081006315349661, 0.00018604756847860396, -8.3155499383793282e-05}},
                                          {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-0.00017315333619608399, 7.5185740915814276e-06, -7.1627478578829856e-05},
                                      {0.00014187252193982144, 0.00039142412319875851, -0.00026209084835570207},
                                      {-0.00024999945195530152, -8.6129770965258433e-05, -2.516662534393232e-05},
                                      {-0.00011911816439045368, 7.3368413938536218e-05, -0.00010429692663996914},
                                      {-0.00014926821681058154, 3.6626120786950325e-05, -8.6068325924882694e-05},
                                      {-0.00014517841654946881, 0.00027391129472662836, 0.00026866055989450884},
                                      {-0.00011815399698919159, 4.0263582863419243e-05, -0.00015759075685726841},
                                      {7.4106519704263048e-05, -0.00013552677876151316, -0.00019392247280951093},
                                      {-0.00014017875355309446, 8.9815292220831889e-05, -9.4141242298344453e-05},
                                      {-3.303611692529906e-05, -2.2855743270442654e-05, -0.00014403185755559436},
                                      {-0.00023931293079047442, 0.00013622220482741618, -0.00016456926215398671},
                                      {-8.6607200088500462e-05, 5.0693029584641537e-05, -8.4390438854322453e-05}},
                                     {{0, 1, 1}, {2, 3, 4}, {5, 6, 6}, {7, 8, 9}, {10, 11, 11}});
    expect_constructions_hold(target, B, [&](const TargetSolver& ts) { expect_d2_ld_and_labels(ts, B, 1e-4); }, true);
}

// A fin 2.5e-7 of T' across standing 1e-3 rad off perpendicular to T' among other tiny fins
// (generate_pairs9.py "tiny_fins" 2316, side A, target 0). Its face region on T' is a wedge from
// its foot to the corner where its top is carried along its normal onto T', 5.9e-4 away; there the
// edge region ca's lines, 0.003 rad apart, cross 1.4e-5 further on (the tolerance over the angle),
// and the face's domain runs on to that crossing in a sliver 5e-8 wide. A point of it was 3.4e-8
// outside the face region's line but 6.9e-6 beyond its bevel, and validate() failed it though d^2
// holds to 4e-9 there. validate() now holds points to the region's lines, not its bevels. The
// oracles: d^2 in long double on a grid over T' and the overlay's nearest-feature map, after
// every insertion in three orders.
TEST(Degenerate, RegionCheckHoldsATipToItsLinesNotItsBevel) {
    const TriangleMesh target = make_mesh({{-5078.3405750056982, -4900.8371513487355, -1212.7468487591689},
                                           {2587.0907110939943, 5699.5201491244452, 9608.0962860007803},
                                           {-7226.3715405856328, -7530.1614960978577, 7683.7492136174187}},
                                          {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-6152.3560577986636, -6215.499323727714, 3235.5011824153962},
                                      {-6152.3560577926683, -6215.4993237188792, 3235.5011824428539},
                                      {-6152.3560578559336, -6215.4993236766622, 3235.5011824314201},
                                      {-5078.3405751312503, -4900.8371515217523, -1212.7468489151711},
                                      {-5078.3405748801461, -4900.8371511757186, -1212.7468486031667},
                                      {-5078.3405750739239, -4900.8371514460168, -1212.7468488458185},
                                      {440.28932559741395, 2743.7823422356701, 7033.0958038678054},
                                      {440.28674547292587, 2743.7788639295727, 7033.095297924554},
                                      {440.29242232494829, 2743.779199400873, 7033.0958019721547},
                                      {-3558.3972045992814, -2618.7695120357685, 7232.9566126961872},
                                      {-3558.3971039151265, -2618.769372801853, 7232.9567548261475},
                                      {-3558.3975507111018, -2618.7692139933474, 7232.9566316124447},
                                      {-3558.397468935389, -2618.7691009075029, 7232.956747050458},
                                      {4767.0447391657508, 8714.1309040320521, 12685.410489906964},
                                      {4767.0447390286699, 8714.1309038646541, 12685.410490488655},
                                      {4767.0447385404741, 8714.1309042468874, 12685.410490437933},
                                      {4767.044738531019, 8714.1309042353423, 12685.410490478054},
                                      {-5840.8022829560705, -5834.1380034409704, 1945.139465109525},
                                      {-5840.8022839526166, -5834.1380048066603, 1945.1394641367904},
                                      {-5840.8022818961217, -5834.1380052967334, 1945.1394646508279},
                                      {-4849.3598131998433, -4498.7334304307105, 2098.4850809229511},
                                      {-4849.3580916405726, -4498.7313231344133, 2098.4779507439553},
                                      {-4849.3576117375769, -4498.7345361306816, 2098.4839985342437},
                                      {-7226.3715415485294, -7530.1614972765028, 7683.7492176054438},
                                      {-7226.3715396227362, -7530.1614949192126, 7683.7492096293936},
                                      {-7226.3715334798198, -7530.1615008782837, 7683.7492126860243}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {10, 12, 11}, {13, 14, 15}, {14, 16, 15},
                                      {17, 18, 19}, {20, 21, 22}, {23, 24, 25}});
    expect_constructions_hold(target, B, [&](const TargetSolver& ts) { expect_d2_ld_and_labels(ts, B, 1e-6); }, true);
}

// A sliver source 1.6e-8 across standing on T''s edge, among tiny triangles at the ends of that edge
// (generate_pairs9.py "shared_edge_tiny" 2146, side B, target 2, the paper's order). Its region
// lines meet T' within 1.5e-7 of that edge for 0.17 of T', so no cut takes in the sliver of the
// old domain between them and the edge, and its far end lies in a corner region the fast
// insertion passes over as nowhere nearer; so it was no crack either, and it kept the old source,
// d^2 up to 0.0013 where this one gives 0 (a jump of 6.3e-4 across the vertex region's line). Such
// a sliver is now split where the source is nearer, and its pieces are cracks. Oracle: d^2 in long
// double on a grid over T' and the overlay, after every insertion in three orders.
TEST(Degenerate, SliverAlongRegionLinesGoesWhereTheSourceIsNearer) {
    const TriangleMesh target = make_mesh({{0.00016205047802867088, -0.00012097683318640473, -5.3531543285930969e-06},
                                           {0.00011693186920190611, 3.8128890061500216e-05, -1.0598549590873815e-05},
                                           {9.9930135177006728e-05, -0.00011059577016191618, -4.1347811350778547e-06}},
                                          {{0, 1, 2}});
    const TriangleMesh A = make_mesh({
                                      {0.00011693186920189845, 3.8128890061506423e-05, -1.0598549590873978e-05},
                                      {0.00011693186920189372, 3.8128890061490309e-05, -1.0598549590871281e-05},
                                      {0.00011693186920190293, 3.8128890061495499e-05, -1.0598549590872894e-05},
                                      {0.00011693186918019212, 3.8128890034835246e-05, -1.0598549616448432e-05},
                                      {0.00011693186921543839, 3.8128890030219363e-05, -1.0598549585630119e-05},
                                      {0.0001169318691807085, 3.8128890063266056e-05, -1.0598549609633953e-05},
                                      {0.00011693186898696899, 3.8128890008391067e-05, -1.0598549353009215e-05},
                                      {0.00011693186585750905, 3.8128898037161898e-05, -1.0598550387271865e-05},
                                      {0.00011693187519372947, 3.8128893579278902e-05, -1.0598542955103499e-05},
                                      {0.00013789066876812388, -3.5779970323884851e-05, -8.161923314222786e-06},
                                      {0.00013789066876813283, -3.5779970323880921e-05, -8.1619233142346309e-06},
                                      {0.00013789066876814177, -3.577997032387699e-05, -8.1619233142464758e-06},
                                      {0.00013949117361528851, -4.1423971562452255e-05, -7.9758519597334561e-06},
                                      {0.0001394911756335556, -4.1423970930412153e-05, -7.9758501487162012e-06},
                                      {0.00013949117387228188, -4.1423971481972259e-05, -7.975851729129961e-06},
                                      {0.0001361905961536802, -2.9784854625703093e-05, -8.3595702064521683e-06},
                                      {0.00013619059615345707, -2.9784854626117963e-05, -8.359570206290324e-06},
                                      {0.00013619059615357495, -2.9784854626100128e-05, -8.3595702065277372e-06},
                                      {0.00014155360076280758, -4.8696890059101199e-05, -7.7360784941039441e-06},
                                      {0.0001415536007883349, -4.8696890088807587e-05, -7.7360784776698651e-06},
                                      {0.00014155360076768917, -4.869689005356365e-05, -7.7360784884564909e-06},
                                      {0.0001255097476260956, 7.8799620451944917e-06, -9.6013033544318318e-06},
                                      {0.00012550974762609568, 7.8799620451946272e-06, -9.6013033544318047e-06},
                                      {0.00012550974762609571, 7.8799620451945459e-06, -9.6013033544318589e-06},
                                      {0.00013949117361546673, -4.1423971562401941e-05, -7.9758519597401917e-06},
                                      {0.00013949117373688805, -4.1423971965012889e-05, -7.9758517546140602e-06},
                                      {0.00013949117364061442, -4.1423971589037116e-05, -7.9758514932923291e-06},
                                      {0.00014651895615311412, -6.6206659960801309e-05, -7.1588166365078968e-06},
                                      {0.00014651895615311379, -6.6206659960801499e-05, -7.1588166365080865e-06},
                                      {0.00011693186920281091, 3.8128890061713912e-05, -1.0598549591852569e-05},
                                      {0.00011693186920279242, 3.8128890061718289e-05, -1.059854959186772e-05},
                                      {0.00011693186920279315, 3.8128890061717503e-05, -1.0598549591865308e-05}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}, {21, 22, 23}, {24, 25, 26}, {27, 27, 28}, {29, 30, 31}});
    expect_constructions_hold(target, A, [&](const TargetSolver& ts) { expect_d2_ld_and_labels(ts, A, 1e-6); }, true);
}

// A target 2.4e-7 across, a few ulps of its coordinates (3.5e8), lying in the plane of a sliver
// whose apex is 1.6e-7 off its long edge (generate_pairs8.py "mixed_scale_sim" 1746: a similarity
// of a square 1e6 across with 1e-6 triangles, scaled to 2e5 far from the origin). At the sample
// (0.5918, 0.4551) the domain is labelled with the sliver's face, and its foot does lie inside
// the face (exact rational arithmetic from the input doubles; the long double oracle below).
// The overlay took the face's distance at the sample rounded to a world point, 6e-8 (a quarter of
// T') off, found its foot outside, and counted 2,111 of 19,296 samples as disagreements. It now
// takes the point in long double relative to the frame's origin.
TEST(LabelCheck, FaceDistanceIsTakenAtTheSampleNotItsWorldRounding) {
    const TriangleMesh target = make_mesh({{-349950233.2768445, 238102947.73944452, -220916870.61301118},
                                           {-349950233.27684438, 238102947.73944452, -220916870.613011},
                                           {-349950233.27684426, 238102947.73944452, -220916870.61301115}},
                                          {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-349843609.42759413, 238102947.73944473, -221023494.46226156},
                                      {-350056857.12609488, 238102947.73944473, -221023494.46226156},
                                      {-350056857.12609488, 238102947.73944473, -220810246.76376083},
                                      {-349843609.42759413, 238102947.73944473, -220810246.76376083},
                                      {-349843609.42759413, 238102947.73944452, -221023494.46226156},
                                      {-350056857.12609488, 238102947.73944452, -220810246.76376083},
                                      {-349950233.2768445, 238102947.73944452, -220916870.61301097}},
                                     {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}});
    const VoxelGrid grid(target, B);
    TargetSolver ts(grid, 0, 0);
    ts.on_event([](const Event&) {});
    ts.run();
    ASSERT_NE(ts.domain_mesh(), nullptr);
    const TargetFrame& f = ts.frame();
    const Vec2 p{0.591796875, 0.455078125};
    const int face = ts.domain_mesh()->face_at(p);
    ASSERT_GT(face, 0);
    EXPECT_EQ(ts.domain_mesh()->faces()[face].label.source, 2u);
    EXPECT_EQ(ts.domain_mesh()->faces()[face].label.region, Region::abc);
    // The oracle: the sample in long double, the sliver's face (its foot inside) nearer than its edges.
    const L3 w = ld(f.origin) + ld(f.e1) * ((long double)p.x * f.scale) + ld(f.e2) * ((long double)p.y * f.scale);
    const auto s = B.corners(2);
    const L3 a = ld(s[0]), b = ld(s[1]), c = ld(s[2]);
    EXPECT_LT(sliver_d2_ld(w, a, b, c), std::min({segment_d2(w, a, b), segment_d2(w, b, c), segment_d2(w, c, a)}));
    const LabelCheck L = check_labels(*ts.domain_mesh(), f, inserted_corners(ts), ts.inserted_sources());
    ASSERT_GT(L.samples, 10000);
    EXPECT_EQ(L.disagree, 0) << L.first;
}

// Generate_pairs8.py "mixed_scale" 4589, B's target 3 (1.4e-3 across, 2.6e8 from the origin)
// against A in the debugger's order: A's last triangle is a needle 1.4e9 long and 7e-4 wide
// (height 5e-13 of its length: a face to its projection, which keeps a face region down to 2e-14,
// but its edges to the region test, which takes a height below 1e-12 as none), coplanar with the
// target and crossing it. The domain mesh rightly merged the needle's face domain with the
// coplanar face of A's triangle 5 (the same quadratic, 0); the label check found the needle's
// edge, 1.4e-5 away, nearest where d is 0, and counted 792 of 12,705 samples as disagreements.
// Oracle: the sample taken in long double from the frame lies over the needle's face (its foot
// inside: nearer than its edges), as exact rational arithmetic on the input doubles also says
// (the three orientations 2.0e4, 7.8e5 and 2.5e5 in world units squared, all positive).
TEST(LabelCheck, NeedleThinnerThanTheRegionTestsFaceKeepsItsFace) {
    const TriangleMesh A = make_mesh(
        {{0, 0, 0}, {1024000000, 0, 0}, {1024000000, 0, 1024000000}, {0, 0, 1024000000}, {512000000, 0, 512000000},
         {512000000.00102401, 0, 512000000}, {512000000, 0.001024, 512000000}, {512000000, -2.4473224058916978e-07, 512000000},
         {512000000.00102401, -2.4473224058916978e-07, 512000000}, {512000000, -2.4473224058916978e-07, 512000000.00102401},
         {256000000, 0.001024, 256000000}, {256000000.00102401, 0.001024, 256000000},
         {256000000.00055328, 0.0020479999999999999, 256000000.00086167}, {256000000, 0.001024, 256000000},
         {256000000.00055328, 0.001024, 256000000.00086167}, {255999999.99957386, 0.001024, 256000000.00093111},
         {256000000, 0.001024, 256000000}, {255999999.99957386, 0.001024, 256000000.00093111},
         {255999999.99898624, 0.0020479999999999999, 256000000.00014451}, {0, 0.001024, 0},
         {1024000000, 0.001024, 1024000000}, {512000000, 0.001024, 512000000.00102401}},
        {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}, {13, 14, 15}, {16, 17, 18}, {19, 20, 21}});
    const TriangleMesh B = make_mesh({{0, 0, 0}, {1024000000, 0, 0}, {1024000000, 0, 1024000000}, {0, 0, 1024000000},
                                      {363002359.85767359, 0, 961992215.60058808}, {363002359.85869759, 0, 961992215.60058808},
                                      {363002359.85767359, 0, 961992215.60161209}, {256000000, 0.001024, 256000000},
                                      {256000000.00102401, 0.001024, 256000000}, {256000000, 0.001024, 256000000.00102401}},
                                     {{0, 1, 3}, {1, 2, 3}, {4, 5, 6}, {7, 8, 9}});
    const VoxelGrid grid(A, B);
    TargetSolver ts(grid, 1, 3);
    ts.on_event([](const Event&) {});
    ts.run();
    ASSERT_NE(ts.domain_mesh(), nullptr);
    const TargetFrame& f = ts.frame();
    const Vec2 p{0.509765625, 0.326171875};
    const L3 w = ld(f.origin) + ld(f.e1) * ((long double)p.x * f.scale) + ld(f.e2) * ((long double)p.y * f.scale);
    const auto n = A.corners(7);
    const L3 a = ld(n[0]), b = ld(n[1]), c = ld(n[2]);
    EXPECT_LT(sliver_d2_ld(w, a, b, c), std::min({segment_d2(w, a, b), segment_d2(w, b, c), segment_d2(w, c, a)}));
    const LabelCheck L = check_labels(*ts.domain_mesh(), f, inserted_corners(ts), ts.inserted_sources());
    ASSERT_GT(L.samples, 10000);
    EXPECT_EQ(L.disagree, 0) << L.first;
    // The map names the needle's face at the sample.
    const auto& ids = ts.inserted_sources();
    const int slot = (int)(std::find(ids.begin(), ids.end(), 7u) - ids.begin());
    ASSERT_LT(slot, (int)ids.size());
    bool seen = false;
    for (int y = 0; y < L.height; ++y)
        for (int x = 0; x < L.width; ++x)
            if (L.sample_point(x, y) == p) {
                seen = true;
                EXPECT_EQ(L.nearest[y * L.width + x], feature_index(slot, Region::abc));
            }
    EXPECT_TRUE(seen);
}

// Generate_pairs7.py "prism_axis_needle" 14492: a needle (1.5 long, 1e-8 high: handled as its
// edges) on the axis of a closed heptagonal prism 1.5 high, from one cap's centre to the other's.
// Its distance peaks at the middle of the axis, where the caps' fourteen triangles tie (d = 0.75,
// by hand: d(p) = min(z, 1.5 - z, the sides' distance >= cos(pi/7) - 1e-8) on the needle). The
// subdivision of the top spent its budget among the ties and the target stayed open, bounded by
// what its subdivision had: 7e-4 above the truth (21.4 of 21952 in 14492). An open target is now
// also bounded by its longest edge plus its height (ConfirmTop's edge bound): the interval is
// within the needle's height and 1e-9 of the diagonal, at the origin and 2^20 from it.
TEST(Degenerate, OpenNeedleIsBoundedByItsLongestEdgeAndHeight) {
    const int n = 7, rings = 4;
    const double H = 1.5, w = 1e-8;
    for (const double X : {0.0, 1048576.0}) {
        std::vector<Vec3> p;
        std::vector<Tri> t;
        for (int j = 0; j <= rings; ++j)
            for (int i = 0; i < n; ++i)
                p.push_back({X + std::cos(2 * M_PI * i / n), X + std::sin(2 * M_PI * i / n), X + H * j / rings});
        for (int j = 0; j < rings; ++j)
            for (int i = 0; i < n; ++i) {
                const uint32_t a = j * n + i, b = j * n + (i + 1) % n, c = (j + 1) * n + (i + 1) % n, d = (j + 1) * n + i;
                t.push_back({a, b, c});
                t.push_back({a, c, d});
            }
        const uint32_t bottom = p.size(), top = bottom + 1;
        p.push_back({X, X, X});
        p.push_back({X, X, X + H});
        for (int i = 0; i < n; ++i) {
            t.push_back({bottom, (uint32_t)((i + 1) % n), (uint32_t)i});
            t.push_back({top, (uint32_t)(rings * n + i), (uint32_t)(rings * n + (i + 1) % n)});
        }
        const TriangleMesh needle = make_mesh({{X, X, X}, {X, X, X + H}, {X + w, X, X + H / 2}}, {{0, 1, 2}});
        SCOPED_TRACE("at " + std::to_string(X));
        expect_narrow_interval_holding(needle, make_mesh(p, t), H / 2, H / 2, w);
    }
}

// Generate_pairs4.py "lod_surface" 1258, nearest first (target 6 and the four sources inserted
// first): a coarse triangle of a sphere under a fine one's edges, which meet over its edge's
// midpoint. After the fourth insertion g, the difference of the two edges' quadratics, is a
// hyperbola whose centre lies 1.2e4 from T'; its branch crosses a face 2e-5 across, but its
// points, taken from the centre, are differences of terms 5e7 long, and no chord was found: a
// sliver 1.35e-5 long kept the farther edge where the nearer is 7.3e-10 nearer (d^2 5.6e-6), a
// jump of d^2 across the face's edge. A conic straight across a face to 1e-3 of kOnCurve is now its
// tangent line there.
TEST(Degenerate, ConicStraightAcrossAFaceIsItsTangentLine) {
    const TriangleMesh A = make_mesh({{1.284816372491102, 1.4799309231902382, 2.7386545374533626},
                                      {-3.1460654167790256, 7.205428848160677, 10.565253889821411},
                                      {-9.116070913097294, 7.79503574130131, 6.754124645077435}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{1.284816372491102, 1.4799309231902382, 2.7386545374533626},
                                      {-0.9410749884557601, 4.317000938842512, 6.664351813987569},
                                      {-3.9307215677395, 4.600393536461976, 4.764296262757372},
                                      {-3.1460654167790256, 7.205428848160677, 10.565253889821411},
                                      {-6.135712900450866, 7.488819223512421, 8.665199411485178},
                                      {-6.911080484774028, 4.906607831983145, 2.853222569243593}},
                                     {{0, 1, 2}, {1, 3, 4}, {1, 4, 2}, {2, 4, 5}});
    const VoxelGrid grid(A, B, 1.0, 1);
    TargetSolver ts(grid, 0, 0);
    ts.nearest_first();
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    // A point of the sliver, 6e-6 along T''s edge from where the two edges' regions meet.
    const Vec2 p{0.65385854, 0.23074059};
    expect_polynomial_is_d2(ts, p, 1e-9);
}

// Generate_pairs3.py "perpendicular" 23943 (target 0 and two of B's eight triangles), each construction:
// two fins standing on T', one (the second) 1.5e-12 above it and leaning 2.6e-9 rad. Beyond its
// corner b, the region of its edge bc is a needle between two region lines 7.7e-7 rad apart, up to
// 7.7e-8 wide, running from the fin's foot towards the first fin, which is nearer past the conic
// where their quadratics are equal. That conic, a hyperbola whose centre lies far off T', crossed
// the needle between curve parameters 5.4e-13 apart, and the chord was dropped as having no
// length (the test was on the parameter, not the plane): the whole needle, 0.09 of T' long, kept
// the first fin's edge, d^2 0.0178 where the truth is 0.0020, and validate() found d^2 jumping
// across the needle's edge. The oracle: d by brute force on a segment across the needle.
TEST(Degenerate, ChordShortInItsParameterButNotInThePlaneIsKept) {
    const TriangleMesh A = make_mesh({{-1, -1, 0}, {1, -1, 0}, {1, 0, 0}}, {{0, 1, 2}});
    const double yb = -0.9289040238841911;  // the leaning fin's corner b
    const TriangleMesh B = make_mesh({{0.29089267834138743, -0.9306153477984784, 6.270501466390105e-14},
                                      {0.29234998239413235, -0.9306153477984784, 6.270501466390105e-14},
                                      {0.29070149225864506, -0.9306153477984784, 0.44873765934625626},
                                      {-0.10697018726355867, -0.9308707578133095, 1.5161137319600407e-12},
                                      {-0.10697018726355867, yb, 1.5161137319600407e-12},
                                      {-0.1069701868384782, -0.9293933867139367, 0.1656916850777681}},
                                     {{0, 1, 2}, {3, 4, 5}});
    // Across the needle halfway along it (world x between the fin's foot and the conic), 3e-7
    // either side of the line through b: each point's polynomial is d^2, up to the gradient (0.09)
    // times the resolution (2e-7) where a boundary is that near.
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        for (int k = -30; k <= 30; ++k) {
            double poly, d2;
            ASSERT_TRUE(polynomial_and_d2(ts, B, ts.frame().to_frame(Vec3{-0.007, yb + k * 1e-8, 0}), poly, d2)) << k;
            EXPECT_NEAR(poly, d2, 1e-4 * d2) << k << " e-8 from b's line";
        }
    });
}

// Generate_pairs4.py "thin_shell" 14160 (target 5 and two of B's triangles), each construction: a plate
// 1.3e-5 thick, one side A, the other B; a triangle of B lies 6.1e-6 under the target (d^2
// 3.7e-11 over it), another's edge runs along the target's edge. The set where that edge is
// nearer is a thin ellipse along T''s edge, 6e-6 wide at the middle, its tip at T''s corner; the
// boundary meets its near side 5e-8 from the far side, where two chords of the far side end. The
// chord towards the tip ended there with the curve's tangent 3.1e-3 rad across T''s edge, the
// wedge chosen by it was the wrong one, and the lens stayed in one piece with the rest of the
// face: d^2 up to 3 times the truth over it. A curved arc whose curve ends off its vertex now
// decides a wedge by its tangent only with a margin, else by secants. The oracle: d by brute
// force on a segment across the lens.
TEST(Degenerate, TangentOfAChordEndingOffItsVertexDecidesNoCloseWedge) {
    const TriangleMesh A = make_mesh({{-0.556562717917214, -0.4956821757316062, 0.30833165738044166},
                                      {-0.09391721214353826, -0.05320656533361441, 0.5648684396656971},
                                      {-0.09124267805875094, 0.05998879250947858, 0.3647947955459698}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-0.5565660127799874, -0.49567956034966615, 0.30833307200005117},
                                      {-0.093920503156805, -0.05320395502628446, 0.5648698725018177},
                                      {-0.09124597253041314, 0.05999142088622869, 0.3647961867986981},
                                      {-0.09391392113027155, -0.05320917564094438, 0.5648670068295762}},
                                     {{0, 1, 2}, {0, 1, 3}});
    // Across the lens halfway along T''s edge (frame y 0.15 there), into T' by 1.2e-5: the
    // polynomial is d^2 to the gradient (1e-5) times the resolution (2e-7) where a boundary is
    // that near.
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        int inside = 0;
        for (int k = 0; k <= 60; ++k) {
            double poly, d2;
            if (!polynomial_and_d2(ts, B, Vec2{0.55, 0.150002 - k * 2e-7}, poly, d2)) continue;
            ++inside;
            EXPECT_NEAR(poly, d2, 3e-12) << k;
        }
        EXPECT_GE(inside, 55);
    });
}

// Generate_pairs3.py "parallel_edge" 28995 (the target and three of B's eight triangles), the
// paper's order: a triangle of B lies 7.4e-6 under the target, parallel to it (d^2 5.5e-11), and
// another's plane meets the target along its edge. Where the second is nearer is a strip along
// T''s edge bounded by a line of the first's conic; that line crosses a conic boundary arc at
// 2.1e-3 rad at a vertex where its chord was cut in two, and again within kCluster (one vertex).
// The second half of the chord left the vertex just outside the face by tangents, in no wedge,
// and went into the first one found: the strip became a slit of the face, which went whole to
// the parallel triangle, d^2 up to 1.9 times the truth. Such a direction now goes into the wedge
// it is nearest to. The oracle: d by brute force across the strip.
TEST(Degenerate, ChordLeavingItsVertexInNoWedgeGoesOnInside) {
    const TriangleMesh A = make_mesh({{0, 0, 0},
                                      {-0.5877539711661561, 0.2029097692536516, 0.7831812656849257},
                                      {0.5282912241559062, 0.8294203671477581, 0.18157708291613267}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.3602572815541058, -0.5006254371403407, -0.6721236623197747},
                                      {-1.0115377624978161, -0.02704188091254365, 1.1557911312276998},
                                      {-0.7694208729214611, 1.041401469417754, 1.4212915134773194},
                                      {-0.4595350031316163, -0.42741091493815914, -0.8307823879032806},
                                      {-1.186733848347661, -0.04573952906404406, 1.1827091121966464},
                                      {-0.03526150361064459, 0.1236641701621871, 0.1445445185000088},
                                      {0.6778787725563898, 0.49772529223635914, -0.2628669589803767},
                                      {-0.225959013825997, 0.8097563897272095, 0.9414955059951378},
                                      {-0.319876972342681, -0.7067321701415019, -0.2889594005928427}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    // Across the strip 1.8e-5 along T''s edge (x = y) from where the line meets it: the
    // polynomial is d^2 to the gradient (1.5e-6) times the resolution (2e-7).
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        for (int k = 0; k <= 60; ++k) {
            double poly, d2;
            ASSERT_TRUE(polynomial_and_d2(ts, B, Vec2{0.27003 + k * 1e-6, 0.270018}, poly, d2)) << k;
            EXPECT_NEAR(poly, d2, 1e-12) << k;
        }
    });
}

// Generate_pairs3.py "sliver" 26294, nearest first (target 3 of B and three of A's slivers, which
// lie within 1e-5 of its plane): a region line of the last sliver passes through the tip of a
// spike of a domain, where the spike's two sides are 1.6e-8 apart. The chord from one side of the
// tip and the chord to the other were left in different loops of the face and bridged them, so
// the face stayed whole across the line, and the source nearer on one side of it got none of it:
// d^2 4.3 times the truth over 0.0037 of T'. A short chord whose middle lies outside the face now
// pinches the face there, as one shorter than kTinyChord does. The oracle: d by brute force on a
// grid over that part of T' (d^2 below 2e-11 of T''s size squared).
TEST(Degenerate, ShortChordAcrossTheGapAtASpikesTipPinchesTheFace) {
    const TriangleMesh A = make_mesh({{-1.5494508541672527, -0.31495979950420927, -0.0015411737864600705},
                                      {-1.0729980783071147, -1.0735490996189114, 0.4429079528035869},
                                      {1.5494508541672527, 0.31495979950420927, 0.0015411737864600705}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{1.1818926614226872, -0.15078243169244676, 0.20412024767561862},
                                      {-0.30098497099216737, 0.7185502188030948, -0.404982569521034},
                                      {-2.016273161109507, 0.6833881149258144, -0.5691395604262065},
                                      {-0.34476532698585066, -1.1291013673992418, 0.5492916971058195},
                                      {1.2335286777735308, 0.39622676449101857, -0.07428023399722705},
                                      {-0.2444021734913488, -0.019853581722774995, -0.01565922988119636},
                                      {1.1339894620202, 0.027567110243997717, 0.10645494032898156},
                                      {1.6396632336582941, 0.2295918502868834, 0.05545440908949906},
                                      {-1.3283125334631027, -0.5045825538743178, 0.12042450048587251}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        double worst = 0;
        int near = 0;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 8; ++j) {
                double poly, d2;
                const Vec2 p{0.17 + i * 0.0045, 0.0005 + j * 0.005};
                if (!polynomial_and_d2(ts, B, p, poly, d2) || d2 > 2e-11) continue;
                ++near;
                worst = std::max(worst, std::fabs(poly - d2) / d2);
            }
        EXPECT_GE(near, 100);
        EXPECT_LT(worst, 1e-6);
    });
}

// Generate_pairs4.py "thin_shell" 16336, the debugger's construction (target 0 and three of B's
// triangles): a plate 6e-3 across whose two sides nearly coincide, d^2 below 1e-10 of T''s size
// squared. The last insertion's conic crossed the base of a spike of a domain, 1.1e-3 long and
// 1.9e-8 across there; the chord was dropped as leaving the face, and the spike, where the old
// source is nearer (d^2 from 0), went with the rest of the face to the new one (3.6e-11). A short
// chord that leaves the face between its ends now pinches the face there. The oracle: d by
// brute force along the spike's middle.
TEST(Degenerate, ShortChordLeavingTheFaceAcrossASpikesBasePinchesTheFace) {
    const TriangleMesh A = make_mesh({{0.00022604914561927126, 0.0038035291523214826, 0.003214920556803328},
                                      {-0.0032574942929462706, -0.0023214192953841836, 0.002975472556740796},
                                      {0.003264368962426826, 0.002317321366361434, -0.0029711190901028357}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-0.0032574942929462706, -0.0023214192953841836, 0.002975472556740796},
                                      {-0.001750857019589281, -0.0030570585575561845, -0.00012547737506872942},
                                      {0.0017473965251850138, 0.003059121327336233, 0.00012328597561564513},
                                      {0.003264368962426826, 0.002317321366361434, -0.0029711190901028357},
                                      {-0.003257539606426599, -0.002321392309671173, 0.0029754439501632726},
                                      {0.0017473512350267772, 0.0030591483323447965, 0.00012325735031978345},
                                      {-0.0017509022860082045, -0.003057031534680609, -0.0001255060210457116}},
                                     {{0, 1, 2}, {2, 1, 3}, {4, 5, 6}});
    // The spike: from its apex to the middle of its base (frame), below the resolution across.
    const Vec2 apex{0.675647541724, 0.175647554706}, base{0.676416951043, 0.176416972727};
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        for (int k = 1; k < 20; ++k) {
            double poly, d2;
            ASSERT_TRUE(polynomial_and_d2(ts, B, apex + (k / 20.0) * (base - apex), poly, d2)) << k;
            EXPECT_NEAR(poly, d2, 1e-13) << k;
        }
    });
}

// Generate_pairs3.py "hinge_rot" 30869, nearest first (target 3 of B and two of A's triangles, 3.5e5
// from the origin): the target and a source share an edge, the source's third corner 0.1 off the
// target's plane; a second source shares its other edge. The two sources' planes differ by a line
// pair centred 4.2e-6 from T''s corner, 1e-11 inside T''s edge; one line runs along the edge (its
// chord dropped as the boundary), and the other's chord ended at the centre, a new vertex in the
// face, dangling: the wedge between that line and T''s edge, where the second source is nearer,
// kept the first, d^2 1.7 times the truth. A centre within kCluster of a straight arc of the face
// is now a vertex on that arc. The oracle: d by brute force along the wedge.
TEST(Degenerate, LinePairCentreBesideAnArcIsOnIt) {
    const TriangleMesh A = make_mesh({{94484.87116323694, -269612.413381426, 338253.64107140177},
                                      {86831.33051941836, -256266.35557319171, 289592.339976514},
                                      {110680.98869799986, -224250.02494809893, 321384.8634014359}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{94484.87116323694, -269612.413381426, 338253.64107140177},
                                      {86831.33051941836, -256266.35557319171, 289592.339976514},
                                      {110681.09208257622, -224250.07278628316, 321384.83402060973},
                                      {60712.953326837625, -233098.29637419645, 326817.16466962127}},
                                     {{0, 1, 2}, {1, 3, 2}});
    // Along the wedge from T''s corner (1, 0) to its third corner, 1e-6 t inside the edge at t of
    // the way (the wedge is about 3e-6 t wide): d^2 there is below 5e-12 of T''s size squared.
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        const auto& c = ts.frame().corners;
        const Vec2 corner{1, 0}, apex = *std::max_element(c.begin(), c.end(), [](Vec2 p, Vec2 q) { return p.y < q.y; });
        const Vec2 along = apex - corner, inward = Vec2{-along.y, along.x} / norm(along);
        for (int k = 1; k < 20; ++k) {
            const double t = k / 20.0;
            double poly, d2;
            ASSERT_TRUE(polynomial_and_d2(ts, B, corner + t * (apex - corner) + (1e-6 * t) * inward, poly, d2)) << k;
            EXPECT_NEAR(poly, d2, 1e-13) << k;
        }
    });
}

// Generate_pairs4.py "subdiv_far" 3329 (one target and the five triangles of B around it): a
// triangle 8.6e3 from the origin against its 1-to-4 subdivision beside an unsplit neighbour, the
// midpoints rounded in world coordinates. Along the T-junction's seam d peaks at 4.8e-13 on the
// ridge between two triangles of B that are not neighbours; no sub-triangle's centre falls there,
// and each sub-triangle across it was bounded by the ridge's true value, above the largest
// distance measured, until the budget ran out: the target stayed open, and the interval was 8.6e-10
// wide (1e-13 of the coordinates) where the goal is 1.3e-12. A corner measured farther now raises
// the result, as a centre does. The oracle: d in long double on a grid hugging the seam, a lower
// bound of the truth that the upper end must hold.
TEST(Degenerate, RidgeOfASeamRaisesTheConfirmation) {
    const TriangleMesh A = make_mesh({{-8646.174942020623, 2642.060653428126, -3107.1548233252684},
                                      {-8646.174890840473, 2642.0596224230935, -3107.1542585354946},
                                      {-8646.174640845615, 2642.0596389693173, -3107.154395190438}},
                                     {{0, 2, 1}});
    const TriangleMesh B = make_mesh({{-8646.175192015482, 2642.060636881902, -3107.1546866703247},
                                      {-8646.174942020623, 2642.060653428126, -3107.1548233252684},
                                      {-8646.174890840473, 2642.0596224230935, -3107.1542585354946},
                                      {-8646.174640845615, 2642.0596389693173, -3107.154395190438},
                                      {-8646.174791433119, 2642.0601461987217, -3107.1546092578533},
                                      {-8646.174765843043, 2642.059630696205, -3107.1543268629666},
                                      {-8646.174916430547, 2642.0601379256095, -3107.1545409303817}},
                                     {{0, 1, 2}, {1, 4, 6}, {4, 3, 5}, {6, 5, 2}, {4, 5, 6}});
    const auto c = A.corners(0);
    long double sampled = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 400; ++j) {
            const long double u = i * 2.5e-10L, v = j / 400.0L;  // along the edge c0-c2, at most 1e-8 into A
            if (u + v > 1) continue;
            const L3 p = ld(c[0]) + (ld(c[1]) - ld(c[0])) * u + (ld(c[2]) - ld(c[0])) * v;
            sampled = std::max(sampled, distance_ld(p, B));
        }
    ASSERT_GT(sampled, 1e-13L);  // the seam's ridge: the points inside are nearer
    expect_narrow_interval_holding(A, B, (double)sampled, HUGE_VAL);
}

// Generate_pairs4.py "nested_scales" 3014, nearest first: a target 1e-5 across against a plane
// through it (heights 3e-9 of T'), a copy of it 1e-9 of its size off (nearer over half of it) and a
// copy 1e-9 of its size. The copy's and the plane's quadratics differ by a line pair whose lines
// cross at 27 degrees, 1.6e-6 outside the tiny copy's domain (a hole in the plane's). A vertex of
// the hole on one line lies within kOffCurve of the other: taken for the centre, it broke the
// other line's chord there, and the copy kept none of the two quadrants where it is nearer (d^2
// 1.14e-18 where the plane's polynomial gave 2.2e-18; 574 of 10,477 of the overlay's samples).
// The centre's vertex now lies within kOffCurve of the centre.
TEST(Degenerate, LinePairCentreIsNoFartherVertex) {
    const TriangleMesh A = make_mesh({{-1.2323533871695138e-11, -2.0825893254907406e-12, 5.13428501250513e-12},
                                      {0.0005301178452331184, -0.0012833491807933155, 0.002093544836145144},
                                      {0.001012422654849264, -0.0011067459027076809, 0.0006394479878222693},
                                      {0.0005121716462644768, -0.0007935862586917006, 0.0009074390254916991},
                                      {0.0005142424191886519, -0.0007985993418701678, 0.0009156169347016063},
                                      {0.0005161264223057199, -0.0007979094850217171, 0.0009099368689083926},
                                      {0.0005141801587553421, -0.0007966983559253299, 0.000910997602913105},
                                      {0.0005141801627050277, -0.0007966983654870264, 0.0009109976185112296},
                                      {0.0005141801662984787, -0.0007966983641712295, 0.0009109976076773639}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    const TriangleMesh B = make_mesh({{0.0005121716463261803, -0.0007935862588851751, 0.0009074390252876733},
                                      {0.0005142424190980369, -0.0007985993416315398, 0.0009156169348010297},
                                      {0.0005161264223346316, -0.0007979094850668713, 0.0009099368690129954}},
                                     {{0, 1, 2}});
    const VoxelGrid grid(B, A, 1.0, 1);
    TargetSolver ts(grid, 0, 0);
    ts.nearest_first();
    while (ts.step()) EXPECT_EQ(ts.validate(true), "") << ts.insertions() << " insertions";
    const DomainMesh& dm = *ts.domain_mesh();
    const LabelCheck L = check_labels(dm, ts.frame(), inserted_corners(ts), ts.inserted_sources());
    EXPECT_EQ(L.disagree, 0) << L.first;
    expect_polynomial_is_d2(ts, {0.509765625, 0.361328125}, 1e-7);  // where the copy is nearer: 1.14e-18 against 2.2e-18
}

// Generate_pairs4.py "cap_sliver" 9260: **a certified interval below the truth**. A is a square
// split along its diagonal, one half bent at a point of the diagonal 1.6e-12 out of the plane, the
// gap closed by a cap 1.6e-12 high; B is the flat square, 2x refined. Two targets of B across the
// crease stayed open (their subdivision's budget spent along it), and their domain meshes' maximum
// 1.429e-12 plus 1e-13 of the coordinates stood for them: the upper end 1.457e-12, where d
// reaches 1.548e-12 at a point of B (its value here in long double; exact rational arithmetic
// agrees). An open target is now bounded by what its subdivision had (largest bound first), and
// the crease closes: a cut piece tries each corner's nearest triangle, not only its centre's (the
// cap, nearest on its line only).
TEST(Degenerate, OpenTargetIsBoundedByItsSubdivision) {
    const Vec3 c1{0.04258823997176417, -0.028017222151032535, -0.0597899686968171},
        c2{-0.016323506650103552, -0.07340703164985665, 0.02277090496050203}, split{-0.005795026962536389, 0.003812333121190666, 0.008135684429226296};
    const TriangleMesh A = make_mesh({c1, c2, -1.0 * c1, -1.0 * c2, split}, {{0, 1, 2}, {0, 4, 3}, {4, 2, 3}, {0, 2, 4}});
    const TriangleMesh B = make_mesh({c1,
                                      {0.01313236666083031, -0.0507121269004446, -0.018509531868157538},
                                      c2,
                                      {0.02945587331093386, 0.02269490474941206, -0.04128043682865957},
                                      {0, 0, 0},
                                      {-0.02945587331093386, -0.02269490474941206, 0.04128043682865957},
                                      -1.0 * c2,
                                      {-0.01313236666083031, 0.0507121269004446, 0.018509531868157538},
                                      -1.0 * c1},
                                     {{0, 1, 3}, {1, 4, 3}, {1, 2, 4}, {2, 5, 4}, {3, 4, 6}, {4, 7, 6}, {4, 5, 7}, {5, 8, 7}});
    const auto t = B.corners(6);
    const L3 p = ld(t[0]) + (ld(t[1]) - ld(t[0])) * (1.0L / 12) + (ld(t[2]) - ld(t[0])) * (2.0L / 12);
    const long double at_p = distance_ld(p, A);
    ASSERT_GT(at_p, 1.5e-12L);
    const VoxelGrid grid(B, A);
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = one_sided(grid, 0, opt);
        EXPECT_GE((long double)r.upper, at_p) << mode_name(mode);
        EXPECT_LE(r.lower, r.distance) << mode_name(mode);
        // And the crease now closes (each corner's nearest triangle tried for a cut piece): the
        // interval is within the 1e-9 of the diagonal it was 1.8e-4 of.
        EXPECT_LE(r.upper - r.lower, 1e-9 * B.bounds().diagonal()) << mode_name(mode);
    }
}

// Generate_pairs3.py "sliver" 30802 (the tetrahedron's face 0 against eight slivers lying in z = 0,
// to the end): two sources' planes cross the target along a line pair whose centre is a vertex
// 1e-9 off one line; that line's chord ends on its curve 1.3e-7 from the vertex and is joined to
// it by a connector pointing 90 degrees off the line. The other line's chord, leaving the centre
// between the two, went into the wedge on the connector's far side, and a wedge where source 4 is
// nearer kept source 5 (d^2 up to 7% high over 0.028 of T'). The connector now leads into its
// chord's direction (DomainMesh::past_connector). The oracle: d by brute force over the slivers at
// every point of a grid on the target.
TEST(Degenerate, ConnectorAtALinePairsCentreOrdersItsWedgeByItsChord) {
    const TriangleMesh B = make_mesh({{1.0, 1.0, 1.0},
                                      {1.0, -1.0, -1.0},
                                      {-1.0, 1.0, -1.0},
                                      {-1.0, -1.0, 1.0}},
                                     {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
    const TriangleMesh A = make_mesh({{0.8064650178942536, 0.9983044755093133, 0.0},
                                      {0.4535241092674549, -0.3478846750573076, 0.0},
                                      {-0.5045752197874263, 2.291224362646563, 4.826492058432683e-07},
                                      {-0.6162820922652092, 0.1895815422027225, 0.0},
                                      {0.3602504633263285, -1.3354514514206555, 0.0},
                                      {0.5407359107449768, 0.14807115866208997, 1.0488251062550197e-11},
                                      {-0.038412594720744986, 0.6289344419598906, 0.0},
                                      {0.6102327806058152, -1.7255922417776217, 0.0},
                                      {-0.6301394488963856, -1.1605316099566112, 2.4375409136618404e-10},
                                      {0.7813181169308145, -0.5455473103243011, 0.0},
                                      {0.24300609751240176, 1.672714759453175, 0.0},
                                      {-0.030923430328354984, 0.41426396057505566, 3.274232560806168e-13},
                                      {0.2951644165070313, -0.3372973307519507, 0.0},
                                      {-1.0673027193160494, 1.3718530633274753, 0.0},
                                      {-1.5946372061098788, 1.1630836639352622, 1.5488158989527376e-07},
                                      {-0.48381394498813934, 0.17026176910876556, 0.0},
                                      {-0.5958839979494828, 1.524732420609408, 0.0},
                                      {-0.7818829998721271, -1.3671949560450938, 0.0003373352982260098},
                                      {-0.88395914072753, 0.11914880232675507, 0.0},
                                      {-0.33546778625678786, 0.25428879996393794, 0.0},
                                      {-1.1453171778420823, 0.09156858741603913, 3.0565663686190474e-13},
                                      {0.355283481624737, 0.4214541385778201, 0.0},
                                      {-0.014283438654749125, -0.8528403278704556, 0.0},
                                      {0.8454225352447047, 1.3473335481576751, 8.178728675201172e-13}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}, {21, 22, 23}});
    expect_constructions_hold(B, A, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, A, 60, 1e-9), 0); });
}

// Generate_pairs4.py "f32_export" 15711 (target 21 of A, the paper's order, against all of B): a
// chord between the two feet of one vertex at a thin conic's hairpin is an edge from that vertex
// back to itself, whose inner side is a cycle of itself alone. When the merging removed it,
// remove_edge's general splice linked a live half-edge to it: validate() now reports that ("next
// or prev is a removed edge's", after the 7th insertion), and the next split walked a face's loop
// forever (the construction never ended; paper mode and the statistics ran it too). A loop edge
// now splices only its outer side. The construction must end with every step valid, and the
// domains' polynomials must be d^2 by brute force over B at every point of a grid on the target.
TEST(Degenerate, LoopEdgeAtAHairpinIsRemovedCleanly) {
    const TriangleMesh A = make_mesh({{-790.9123046479806, 2307.7299788460673, -4264.199158591687},
                                      {-710.2753829169918, 2350.5738956190967, -4277.602772916986},
                                      {-665.9897113085838, 2305.791098770425, -4154.3233518488505}},
                                     {{0, 2, 1}});
    const TriangleMesh B = make_mesh({{-673.8279418945312, 2437.984130859375, -4414.39892578125},
                                      {-468.3646240234375, 2479.105712890625, -4317.8134765625},
                                      {-665.9896850585938, 2305.791015625, -4154.3232421875},
                                      {-790.9122924804688, 2307.72998046875, -4264.19921875},
                                      {-754.56103515625, 2395.356689453125, -4400.88232421875},
                                      {-835.2941284179688, 2352.729248046875, -4387.365234375},
                                      {-879.6759643554688, 2397.728271484375, -4510.53173828125},
                                      {-710.275390625, 2350.573974609375, -4277.6025390625},
                                      {-549.0015258789062, 2436.26171875, -4304.41015625},
                                      {-960.5052490234375, 2355.317138671875, -4496.90185546875},
                                      {-782.5932006835938, 2174.454833984375, -4004.689208984375},
                                      {-827.0712280273438, 2219.67041015625, -4127.74267578125},
                                      {-746.5304565429688, 2262.730712890625, -4141.03271484375},
                                      {-621.7040405273438, 2261.00830078125, -4031.0439453125},
                                      {-952.1861572265625, 2222.042236328125, -4237.39208984375},
                                      {-585.448974609375, 2348.851318359375, -4167.61376953125},
                                      {-863.0377807617188, 2131.17822265625, -3991.511962890625},
                                      {-702.1486206054688, 2217.731689453125, -4017.86669921875},
                                      {-798.8467407226562, 2440.139404296875, -4524.16162109375},
                                      {-460.8148498535156, 2347.561767578125, -4057.3984375},
                                      {-718.0174560546875, 2482.550537109375, -4537.79150390625},
                                      {-996.7603149414062, 2267.47412109375, -4360.33203125},
                                      {-916.0272216796875, 2310.1015625, -4373.8486328125},
                                      {-380.3702697753906, 2390.83837890625, -4070.575927734375},
                                      {-1041.33447265625, 2312.906005859375, -4483.27197265625},
                                      {-541.2594604492188, 2304.284912109375, -4044.22119140625},
                                      {-637.188232421875, 2524.961669921875, -4551.42138671875},
                                      {-424.367431640625, 2434.971923828125, -4194.19482421875},
                                      {-907.6119995117188, 2176.610107421875, -4114.4521484375},
                                      {-871.5492553710938, 2264.885986328125, -4250.79541015625},
                                      {-593.0948486328125, 2480.61181640625, -4427.91552734375},
                                      {-504.908203125, 2391.91162109375, -4180.904296875},
                                      {-556.3589477539062, 2567.372802734375, -4565.05126953125},
                                      {-629.6384887695312, 2393.417724609375, -4291.00634765625},
                                      {-512.36181640625, 2523.2392578125, -4441.4326171875}},
                                     {{17, 13, 2}, {12, 11, 10}, {23, 27, 19}, {31, 15, 25}, {7, 2, 33},
                                      {34, 30, 8}, {0, 20, 4}, {15, 33, 2}, {26, 30, 32}, {30, 0, 33},
                                      {15, 2, 13}, {18, 4, 20}, {16, 10, 11}, {22, 14, 29}, {31, 25, 19},
                                      {8, 1, 34}, {17, 12, 10}, {28, 16, 11}, {32, 30, 34}, {22, 29, 5},
                                      {27, 1, 31}, {33, 0, 7}, {1, 8, 31}, {29, 3, 5}, {31, 8, 15},
                                      {14, 28, 29}, {11, 3, 29}, {30, 26, 0}, {7, 4, 3}, {17, 2, 12},
                                      {4, 7, 0}, {11, 12, 3}, {18, 6, 5}, {18, 5, 4}, {33, 8, 30}, {5, 6, 22},
                                      {24, 21, 9}, {6, 9, 22}, {28, 11, 29}, {22, 9, 21}, {33, 15, 8},
                                      {22, 21, 14}, {5, 3, 4}, {7, 3, 12}, {13, 25, 15}, {0, 26, 20},
                                      {31, 19, 27}, {7, 12, 2}});
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs4.py "f32_export" 19111 (target 31 of B against all of A, the paper's order): the
// first source's regions that meet T' are four of its seven, the seventh not among them, and the
// cuts left a sliver 8e-8 wide in none of them. The last region takes what is left only if it is
// the last of all seven, so the sliver kept no source (d^2 infinite) until the next source won it
// whole with one region's quadratic, 0.5 where d^2 is 0.125. The last region that may win now
// takes what its cut left, and validate() reports a domain of no source after an insertion (the
// regions of any source tile the plane). The oracle: every domain has a source after each
// insertion, and at the end the polynomials are d^2 by brute force over A on a grid.
TEST(Degenerate, CrackLeftByTheFirstSourcesCutsGoesToItsLastRegion) {
    const TriangleMesh T = make_mesh({{0.22580369881067877, 0.10246267758047356, -0.2814782692344384},
                                      {0.2749960810234293, 0.29177080801906324, -0.1393974176821792},
                                      {0.34481732804809095, 0.2251697410286838, -0.28050554957945006}},
                                     {{0, 2, 1}});
    const TriangleMesh A = make_mesh({{-0.41052186489105225, 0.0007454640581272542, 0.28003638982772827},
                                      {-0.3407006859779358, -0.06585554033517838, 0.13892818987369537},
                                      {-0.27087947726249695, -0.13245657086372375, -0.002179980045184493},
                                      {-0.2010582685470581, -0.19905760884284973, -0.14328813552856445},
                                      {-0.13123707473278046, -0.2656586170196533, -0.28439632058143616},
                                      {-0.291508287191391, 0.1234525740146637, 0.2810090482234955},
                                      {-0.22168710827827454, 0.05685156211256981, 0.13990087807178497},
                                      {-0.1518658697605133, -0.009749488905072212, -0.0012072751997038722},
                                      {-0.08204467594623566, -0.07635051012039185, -0.14231544733047485},
                                      {-0.012223513796925545, -0.14295148849487305, -0.28342366218566895},
                                      {-0.17249472439289093, 0.24615968763828278, 0.2819817364215851},
                                      {-0.1026734933257103, 0.1795586496591568, 0.14087358117103577},
                                      {-0.03285226970911026, 0.11295759677886963, -0.0002345777757000178},
                                      {0.0369688905775547, 0.04635661467909813, -0.14134278893470764},
                                      {0.10679006576538086, -0.020244384184479713, -0.28245100378990173},
                                      {-0.053481120616197586, 0.36886677145957947, 0.2829544246196747},
                                      {0.016340121626853943, 0.3022657036781311, 0.14184628427028656},
                                      {0.0861613005399704, 0.2356647253036499, 0.0007380861788988113},
                                      {0.15598246455192566, 0.1690637320280075, -0.14037013053894043},
                                      {0.2258037030696869, 0.10246267914772034, -0.28147825598716736},
                                      {0.06553250551223755, 0.49157384037971497, 0.28392714262008667},
                                      {0.1353537142276764, 0.4249728322029114, 0.14281895756721497},
                                      {0.20517486333847046, 0.3583718538284302, 0.0017107470193877816},
                                      {0.2749960720539093, 0.2917708158493042, -0.13939741253852844},
                                      {0.3448173403739929, 0.22516974806785583, -0.28050553798675537}},
                                     {{0, 1, 5}, {1, 6, 5}, {1, 2, 6}, {2, 7, 6}, {2, 3, 7}, {3, 8, 7},
                                      {3, 4, 8}, {4, 9, 8}, {5, 6, 10}, {6, 11, 10}, {6, 7, 11}, {7, 12, 11},
                                      {7, 8, 12}, {8, 13, 12}, {8, 9, 13}, {9, 14, 13}, {10, 11, 15},
                                      {11, 16, 15}, {11, 12, 16}, {12, 17, 16}, {12, 13, 17}, {13, 18, 17},
                                      {13, 14, 18}, {14, 19, 18}, {15, 16, 20}, {16, 21, 20}, {16, 17, 21},
                                      {17, 22, 21}, {17, 18, 22}, {18, 23, 22}, {18, 19, 23}, {19, 24, 23}});
    expect_constructions_hold(T, A, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, A, 40, 1e-9), 0); });
}

// Generate_pairs3.py "needle_fan" 35075 (a triangle of the disc around the fan's apex, nearest
// first): twenty needles in T''s plane fanned from one apex 4e-4 rad apart. Where the hyperbola on
// which two needles' edges are as near crosses a needle's edge strip, its chords meet the strip's
// sides at the apex's cluster (arcs leaving a vertex within 4e-4 rad of each other, the vertex
// 8e-9 off the curve): the curve's tangent there put the long chord's end into the wedge on the
// wrong side of the short one, and one loop ran along both sides of the curve. The strip (4e-6
// wide, 0.11 long) where needle 4's edge is nearer went whole to needle 8's (d^2 up to 9 times the
// truth, until a later needle took it). A loop with arcs well on both sides of the curve is now
// re-hooked (DomainMesh::rehook_chords). The oracle: validate() after every insertion (d^2
// continuous across every edge, each domain's polynomial d^2 by brute force at interior points),
// and d^2 by brute force over the needles on a grid at the end.
TEST(Degenerate, ChordsAtAFansApexKeepToTheirSideOfTheCurve) {
    const TriangleMesh T = make_mesh({{0.26901235219540665, 0.07285130414968807, 0.0},
                                      {-0.9944348306008733, 0.10535353666494687, 0.0},
                                      {-0.9076812152624083, -0.41966035249920575, 0.0}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.850607995352486, 0.5258003787012949, 0.0},
                                      {0.8513181280539567, 0.5246498306934892, 0.0},
                                      {0.8507173477798331, 0.5256234338254399, 0.0},
                                      {0.8508266633988162, 0.5254464662072031, 0.0},
                                      {0.8505533053371546, 0.5258888426084368, 0.0},
                                      {0.8512635576965377, 0.5247383684635929, 0.0},
                                      {0.8510997913786467, 0.5250039477139425, 0.0},
                                      {0.8509359422047057, 0.5252694758542417, 0.0},
                                      {0.8508813074036933, 0.5253579738720844, 0.0},
                                      {0.8503891800916275, 0.5261542001952372, 0.0},
                                      {0.8504986061215064, 0.5259773008271124, 0.0},
                                      {0.8507720101906658, 0.5255349528586407, 0.0},
                                      {0.8510451841927732, 0.5250924627742134, 0.0},
                                      {0.8506626761669094, 0.5257119091066437, 0.0},
                                      {0.8509905678012627, 0.5251809721546322, 0.0},
                                      {0.8511543893582922, 0.5249154269747771, 0.0},
                                      {0.85033445327858, 0.526242641342773, 0.0},
                                      {0.8502797172675833, 0.5263310767980155, 0.0},
                                      {0.0, 0.0, 0.0},
                                      {0.8512089781311194, 0.5248269005576748, 0.0},
                                      {0.8513726892027862, 0.5245612872483215, 0.0},
                                      {0.8504438977061335, 0.5260657533563647, 0.0}},
                                     {{18, 2, 13}, {14, 7, 18}, {18, 19, 15}, {12, 18, 6}, {2, 18, 11}, {21, 18, 10},
                                      {16, 17, 18}, {13, 0, 18}, {8, 3, 18}, {18, 7, 8}, {19, 18, 5}, {21, 9, 18},
                                      {18, 20, 1}, {18, 4, 10}, {9, 16, 18}, {18, 0, 4}, {5, 18, 1}, {18, 12, 14},
                                      {18, 3, 11}, {6, 18, 15}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs4.py "hole_fill" 11525 (target 15 of B against three of A's triangles, nearest
// first): a domain along T''s long edge 3e-11 wide and 0.86 long, which the next source's conic
// crosses between two vertices 4.5e-12 apart (on T''s edge and on the strip's other side): no chord
// that short, no pinch (neither part wider than the resolution), so the strip stayed whole on the
// side of its farthest arc, and half of it went to a source whose d^2 there is up to 0.73 where the
// truth is 1e-7. The face's loop passes each vertex once and its arcs keep to one side between
// them: a straight chord now joins them (DomainMesh::sides_part_at). The oracle: validate() after
// every insertion, and d^2 by brute force over the sources on a grid at the end.
TEST(Degenerate, StripCrossedBetweenTwoVerticesCloserThanAChordIsCut) {
    const TriangleMesh T = make_mesh({{0.0014529474164980162, 0.0010458794088679584, -0.010494367057304532},
                                      {0.005223239621163373, 0.006649659062395023, 0.00646811116789574},
                                      {-0.0014792358811749093, -0.0010238585106709202, 0.01049286590138329}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.004280056815820213, 0.0032038197661535335, -0.03148724489944019},
                                      {0.0014529474164980162, 0.0010458794088679584, -0.010494367057304532},
                                      {0.008102872642934798, 0.00876347839331416, -0.014522004189222188},
                                      {-0.0014792358811749093, -0.0010238585106709202, 0.01049286590138329},
                                      {0.005223239621163373, 0.006649659062395023, 0.00646811116789574},
                                      {0.01192568847004938, 0.014323137020474792, 0.0024432365209958165},
                                      {0.0022384793941366632, 0.004623962939250225, 0.02745234181474109},
                                      {0.008993531825828729, 0.012253438715922087, 0.023430589393096016}},
                                     {{0, 2, 1}, {3, 4, 6}, {4, 5, 7}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs5.py "sliver_strip" 794 (target 0 of A against three of B's triangles, in every
// order): the conic crosses a thin lobe of a domain (0.125 long, 7e-9 wide) at its base, between
// two vertices 1e-8 apart, and the face was pinched there, one vertex moved onto the other: the
// lobe turned inside out and the rebuilt face kept it as a hole, on the wrong side (d^2 7.5 times
// the truth there). Where the face's loop passes each vertex once and the arcs on either side of
// them keep to their side of the curve, the straight chord between them now cuts the face, and
// nothing moves (DomainMesh::sides_part_at). The oracle: validate() after every insertion, and
// d^2 by brute force over the sources on a grid at the end.
TEST(Degenerate, LobeCutAtItsBaseIsNotTurnedInsideOut) {
    const TriangleMesh T = make_mesh({{-4.0025189979107125e-06, -5.631991171300558e-06, -2.1115324043117008e-06},
                                      {-5.1405169805686746e-06, -1.7426618515433598e-06, 5.092578409970474e-06},
                                      {3.022092900812974e-06, -1.764046478586332e-06, 6.393530835161678e-06}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-5.274543133280143e-07, -4.12861543809483e-06, 2.3675853397099435e-06},
                                      {-5.906764234756788e-07, -3.912541586997208e-06, 2.767813718281175e-06},
                                      {-4.958432558932293e-07, -4.236652363649826e-06, 2.167471150800615e-06},
                                      {-5.590653660408937e-07, -4.020578512552203e-06, 2.5676995293718473e-06},
                                      {-4.039760262689857e-06, -6.062587784451942e-06, -1.8849462800267458e-06},
                                      {-5.177758245347819e-06, -2.173258464694744e-06, 5.319164534255428e-06},
                                      {-5.067536048824619e-06, -2.5499642392067215e-06, 4.621401521833114e-06}},
                                     {{0, 3, 2}, {0, 1, 3}, {4, 5, 6}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs6.py "stacked_layers" 12326 (target 17 of B against four of A's triangles, in
// every order): a domain made of two slivers 4e-7 wide meeting at (2/3, 0) in the frame, one along
// T''s edge and one along the line x + y = 2/3. A region line cut it where the first is 1e-12 thin:
// the pinch there moved a vertex onto T''s edge and turned the lobe beyond inside out (area
// -3.7e-14), and the rebuilt face kept that lobe as a hole of the other, whose side its arcs then
// decided: the sliver along x + y = 2/3 went to a source whose d^2 there is up to 0.0016 where the
// truth is 2.2e-14. Such a lobe is now a piece of its own (DomainMesh::rebuild_faces). The oracle:
// d^2 by brute force over the sources at points 5e-8 to 2e-7 inside that sliver (and on a grid).
TEST(Degenerate, LobeTurnedInsideOutByAPinchIsAPieceOfItsOwn) {
    const TriangleMesh T = make_mesh({{-6.105111318591985e-10, 8.652365437219276e-10, 9.662982850618321e-10},
                                      {0.0023586929507447927, -0.0006887788587023062, 0.002106975691382966},
                                      {0.0020473253558673347, 0.0008992060902611161, 0.0004883492116760469}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.0002075783965849721, -0.0010586566326422815, 0.001079084319804613},
                                      {0.0022549043629634387, -0.00015945140761770913, 0.001567432565182375},
                                      {0.0021511151646709525, 0.0003698769087034316, 0.0010278904052800682},
                                      {0.0008348491744615812, -0.0004775480708771656, 0.0009550654710521052},
                                      {0.0011462167693390393, -0.0020655330198405875, 0.0025736919507590244},
                                      {0.0015172911632544033, -0.0001778129958689748, 0.0011178482195113592},
                                      {0.0018286587581318615, -0.0017657979448323967, 0.0027364746992182784},
                                      {0.0025111007469246836, -0.001466062869824206, 0.0028992574476775323}},
                                     {{0, 1, 2}, {3, 4, 5}, {4, 6, 5}, {5, 6, 7}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) {
        EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0);
        ASSERT_NEAR(ts.frame().corners[1].x, 1.0, 1e-15);  // the frame the points below are in
        ASSERT_NEAR(ts.frame().corners[2].y, 0.5, 1e-15);
        const Vec2 a{2.0 / 3, 0}, b{0.578072341476, 0.0885943251906};
        int off = 0;
        for (int k = 1; k <= 4; ++k) {
            const Vec2 in = Vec2{1, 1} * (k * 0.5e-7);  // into the sliver
            off += segment_points_off_d2(ts, B, a + in, b + in, 1, 9, 10, 1e-9, 1e-9);
        }
        EXPECT_EQ(off, 0);
    }, true);
}

// Generate_pairs5.py "pow2_coords" 14611 (target 3 of A against three of B's triangles, in every
// order): the difference of a face's and an edge's quadratic is a line pair whose centre lies
// 3.5e-4 outside the face, its lines 7e-6 apart where they cross the face. One line enters the
// face at a vertex and leaves it within 6.5e-7 of another, which the other line passes nearer
// (8.6e-8): counted on that line only, it left the first with one crossing and no chord, and the
// wedge between them (d^2 1.5e-14 to 8.6e-13) went with the rest of the face to the new source
// (1.42e-11 there). A line of a pair that crosses the face an odd number of times now also ends
// at the vertex of the curve nearest it, within kOffCurve (DomainMesh::add_chords_of_component).
// The oracle: d^2 by brute force over the sources at points inside the wedge (and on a grid).
TEST(Degenerate, LineOfAPairCrossingTheFaceOnceEndsAtAVertexTheOtherLinePassesNearer) {
    const TriangleMesh T = make_mesh({{0, 0.001953125, 3.814697265625e-06}, {1.1641532182693481e-10, -1.9073486328125e-06, 6.103515625e-05}, {0, 0, -3.0517578125e-05}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-2.3283064365386963e-10, 1.8189894035458565e-12, 1.52587890625e-05},
                                      {-0.015625, -0.5, -2.3283064365386963e-10},
                                      {-7.4505805969238281e-09, 1.8189894035458565e-12, 2.3283064365386963e-10},
                                      {0, 1.1641532182693481e-10, 2.384185791015625e-07},
                                      {-1.8189894035458565e-12, -0.0078125, -9.3132257461547852e-10},
                                      {-0.0078125, 3.0517578125e-05, 0},
                                      {2.3283064365386963e-10, -3.637978807091713e-12, -3.0517578125e-05},
                                      {-1.862645149230957e-09, -1.862645149230957e-09, 0.0001220703125},
                                      {-0.03125, 0, 0}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) {
        EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0);
        ASSERT_NEAR(ts.frame().corners[1].x, 1.0, 1e-15);  // the frame the points below are in
        ASSERT_NEAR(ts.frame().corners[2].y, 0.04676065714, 1e-10);
        EXPECT_EQ(segment_points_off_d2(ts, B, {0.998116, 0.031042}, {0.998117, 0.0310406}, 0, 10, 10, 1e-14, 1e-9), 0);
    }, true);
}

// Generate_pairs7.py "aniso_grid" 5643 (target 16 of A against five of B's triangles, 1.3e10 from
// the origin; nearest first): two nearly coplanar planes' hyperbola passes 1.7e-7 from two vertices
// 1.2e-8 apart on the face's boundary, at parameters 1.2e-9 apart. One chord came in to one of them,
// the next left from the other, 1.8e-7 long beside the boundary, and the two crossed: the face came
// out one loop through both, and a band 3e-6 wide where the new source is nearer kept the old one
// (d^2 up to 1.5 times the truth). A chord no longer than twice its ends' distance from its curve,
// with a boundary path within kCluster of the segment between its ends, is now that path
// (DomainMesh::noise_chord_hugged). The oracle: d^2 by brute force at points across the band (to 1%:
// the world points' rounding at 1.3e10 is 1e-3 of d^2 there).
TEST(Degenerate, ChordNoLongerThanItsEndsAreOffItsCurveIsTheBoundaryItHugs) {
    const TriangleMesh T = make_mesh({{-12669157569.009398, -7349047197.8005943, 4586511801.4619455},
                                      {-12669156967.035656, -7349047197.8005943, 4586511801.9197111},
                                      {-12669157569.009398, -7349047197.7987747, 4586511801.3707237}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-12669157689.404144, -7349047197.8005943, 4586511801.4032955},
                                      {-12669157328.2199, -7349047197.8005943, 4586511801.6506233},
                                      {-12669157328.2199, -7349047197.7987747, 4586511801.6418753},
                                      {-12669157689.404144, -7349047197.7987747, 4586511801.2864361},
                                      {-12669157328.2199, -7349047197.7969551, 4586511801.6343994},
                                      {-12669157689.404144, -7349047197.7969551, 4586511801.1865654},
                                      {-12669156967.035656, -7349047197.7987747, 4586511802.0285873},
                                      {-12669156967.035656, -7349047197.7969551, 4586511802.1216364}},
                                     {{0, 1, 2}, {3, 2, 4}, {3, 4, 5}, {2, 6, 7}, {2, 7, 4}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) {
        ASSERT_NEAR(ts.frame().corners[2].x, 1.0, 1e-15);  // the frame the points below are in
        ASSERT_NEAR(ts.frame().corners[0].y, 1.5156787e-4, 1e-10);
        EXPECT_EQ(segment_points_off_d2(ts, B, {0.59, 8.3e-5}, {0.59, 8.9e-5}, 0, 12, 12, 0, 0.01), 0);
    }, true);
}

// Generate_pairs5.py "sliver_strip" 7790 (target 2 of A against three of B's triangles, in every
// order): a domain's sliver 0.5 long and 4e-8 wide, which the conic crosses between two vertices
// 1e-8 apart, its curve as decomposed 3e-9 off both and passing outside the sliver between them:
// the chord was dropped, the sliver stayed whole with the old source, and where the new one is
// nearer d^2 was up to 5 times the truth. Its sides part there: the straight chord between the
// two vertices now cuts it (DomainMesh::sides_part_at). The oracle: validate() after every
// insertion, and d^2 by brute force over the sources on a grid at the end.
TEST(Degenerate, SliverCrossedWhereItsCurveRunsOutsideIsCutStraight) {
    const TriangleMesh T = make_mesh({{854.0850354341028, 466.0880596426476, -159.6725285173509},
                                      {949.8912431216271, 731.2471694373725, 213.49715385145987},
                                      {-726.34342518407, -112.54257991634778, 657.2321050090986}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{70.96756125001815, 196.41415540349993, 276.42198693985983},
                                      {106.45134187502721, 294.62123310524987, 414.63298040978975},
                                      {88.70944549057238, 245.51769203129643, 345.5274868133435},
                                      {124.19322611558144, 343.7247697330464, 483.7384802832734},
                                      {658.5118585909054, 241.09609981624806, -340.3769306360206},
                                      {977.8658842159871, 1124.9597991319977, 903.5220105933487},
                                      {733.2515669112884, 447.9502943402107, -49.262226756096375}},
                                     {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs5.py "huge_tiny" 2561 (target 0 of B against two of A's triangles): a needle
// target 2.2e4 long whose tip is 2.5e-12 of it tall; a region line cuts the tip off, and the
// next curve crosses that tip between two vertices 3e-11 apart, its arcs 3e-9 and 1.2e-8 (of
// T') on either side of the curve. Sides that close to the curve were not certain (1e-6, what
// vertices up to kOffCurve off the curve allow), so the tip stayed whole with the farther
// source, d^2 9e-12 where it is 0. Certain now means farther than rounding and the split's
// vertices on the curve allow (here 1e-10). The oracle: validate() after every insertion
// (polynomials against brute-force d^2 at interior points), and d^2 on a grid at the end.
TEST(Degenerate, NeedleTipCutWhereItsSidesPartByLessThanTheVertexTolerance) {
    const TriangleMesh T = make_mesh({{0.0, 0.0, -32768.0},
                                      {-21956.961548609346, 0.0, -24323.520788588372},
                                      {-21956.98587211916, 0.0, -24323.49883161466}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-0.10884081470633866, 0.0, -32767.824502402207},
                                      {-0.10884081470633866, 0.0, -32768.0381177082},
                                      {-0.322456120703641, 0.0, -32767.824502402207},
                                      {0.0, 0.0, -32768.0},
                                      {-0.13181437966366066, 0.1740563406943475, -32768.259427426},
                                      {-0.345429685660963, 0.1740563406943475, -32768.04581212}},
                                     {{0, 1, 2}, {3, 4, 5}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs5.py "huge_tiny" 3914 (target 0 of B against three of A's triangles, nearest
// first): a huge triangle and a tiny one 1e-5 across share a corner near T'. Where the huge
// one's plane comes in, the curve crosses a cluster of domains 7e-6 across through three
// vertices, touching the face's boundary at one; the chords were linked into one loop whose arcs
// lay 1e-8 on either side of the curve, and a lobe where the plane is nearer kept the tiny
// triangle's edge (d^2 1.6 times the truth). Sides that far apart are certain there (the split's
// vertices lie on the curve to 2e-11), though below kMixedSide: the loop is now re-hooked
// (DomainMesh::mixed_cycle with certain_side). The oracle: validate() after every insertion
// (d^2 continuous across every edge, polynomials against brute-force d^2 at interior points),
// and d^2 by brute force over the sources on a grid at the end.
TEST(Degenerate, CurveThroughAClusterTouchingTheBoundaryIsLinkedOnItsSides) {
    const TriangleMesh T = make_mesh({{0.34606595797674278, 0.74463307375979726, -0.71467326115329},
                                      {-1.7209880376990101, -0.015987304409845179, -0.020962143630618251},
                                      {1.3749215220536679, -0.72862028266853573, 0.73566168985266056}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0, 0, 0},
                                      {-6.8901782022771343, -2.5354827616953415, 2.3122863375349865},
                                      {3.4295186225097063, -4.9108479759026302, 4.8344462739979139},
                                      {-9.5948978400253695e-06, -1.056100233577943e-05, 1.0036653554743437e-05},
                                      {3.6600778245255754e-06, -6.6863916750827522e-06, 2.0492143501506054e-05},
                                      {-3.460659579767428, -7.4463307375979717, 7.1467326115329008},
                                      {-1.7303238068929048, -3.7231739360533269, 3.5733747397336653}},
                                     {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs5.py "pow2_coords" 1147 (target 7 of A against three of B's triangles, the
// paper's order): coordinates are powers of two from 2^13 to 2^53; two sources' planes give a
// line pair whose lines cross at a cluster of vertices 1e-7 across on a face's boundary. Cut at
// once, the four chords from the crossing were hooked so that one loop ran along both lines'
// sides, and a quadrant where the nearer plane's d^2 is 2.7e-9 kept 7.3e-7. The face is now cut
// by one line, then each piece by the other (DomainMesh::split_by_line_pair). The oracle:
// validate() after every insertion, and d^2 by brute force over the sources on a grid at the end.
TEST(Degenerate, LinePairCrossingAtAClusterIsCutOneLineAtATime) {
    const TriangleMesh T = make_mesh({{-262144, 9007199254740992, -33554432},
                                      {-4398046511104, -137438953472, 17179869184},
                                      {4503599627370496, -562949953421312, 0}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0, 0, 137438953472},
                                      {35184372088832, -274877906944, -67108864},
                                      {0, 8388608, 0},
                                      {4503599627370496, 68719476736, 4294967296},
                                      {-140737488355328, 67108864, -2251799813685248},
                                      {-4194304, 0, 8796093022208},
                                      {-67108864, 17592186044416, 1073741824},
                                      {0, -281474976710656, 281474976710656},
                                      {-536870912, 0, -549755813888}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs5.py "point_like" 1343 (target 8 of A, a triangle 3e-17 across at the origin,
// against three of B's triangles 1e-6 across that share the origin): a region line passes
// through a hole of a face (a domain 2e-7 across inside it) 1.4e-7 from the face's outer
// boundary. The chord from the hole to the outer boundary counted as hugging the boundary and
// was dropped, so the chord into the hole joined it to the outer loop and cut nothing: the face
// stayed whole inside the region, and its domain reached 5e-3 (of T') beyond the region's line.
// A loop that the chords end on an odd number of times lost one: it is put back
// (DomainMesh::close_hole_crossings). The oracle: validate() after every insertion, which
// checks that each domain's interior points lie in its feature's region (the region's lines
// computed from the source alone), and d^2 by brute force at interior points. No grid check at
// 1e-9: brute-force d^2 here takes differences of corners 1e-6 from a target 3e-17 across and
// is itself only good to about 1e-4 relative (validate() allows for that rounding).
TEST(Degenerate, RegionLineThroughAHoleNearTheBoundaryCutsTheFace) {
    const TriangleMesh T = make_mesh({{0, 0, 0},
                                      {-1.4376607216979174e-17, 5.7031757523314388e-18, 2.5806255998849829e-17},
                                      {1.7434245932259758e-18, -9.7017356827570602e-20, -8.8533878919534599e-19}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0, 0, 0},
                                      {-7.4720501193384015e-07, -5.475918676572421e-08, -1.0981954506385953e-07},
                                      {-6.9244582516811596e-07, -8.0196419869956446e-07, -2.2468870841833642e-07},
                                      {5.475918676572421e-08, -7.4720501193384015e-07, -1.0981954506385953e-07},
                                      {8.0196419869956446e-07, -6.9244582516811596e-07, -2.2468870841833642e-07}},
                                     {{1, 2, 0}, {2, 3, 0}, {0, 3, 4}});
    expect_constructions_hold(T, B, [](const TargetSolver&) {});
}

// Generate_pairs6.py "stacked_layers_far" 609 (target 5 of A against four of B's triangles, 1e7
// from the origin, nearest first): layers of grids 6e-5 of their size apart, one coplanar with T'.
// A chord's end stood 1.6e-7 beyond T''s corner (within the resolution), and the coplanar source
// whose edge runs along T''s edge there has an edge region that meets T' along that edge alone:
// clipped to T', its box was one corner of T' by rounding, the face poking out missed it, and
// kept a layer 6e-5 away (d^2 3.3e-9 beside 1e-19 across an edge). T' is now moved out by
// kCluster before the regions are clipped (DomainMesh::clip_regions_to_target). The oracle:
// validate() after every insertion (d^2 continuous across every edge, polynomials against
// brute-force d^2 at interior points), and d^2 by brute force on a grid at the end.
TEST(Degenerate, EdgeRegionMeetingTheTargetAlongAnEdgeReachesFacesBeyondIt) {
    const TriangleMesh T = make_mesh({{-84581.41527995748, -10788344.297844533, 4446222.1316264784},
                                      {-84581.935680656956, -10788344.315257559, 4446222.1021010745},
                                      {-84581.893551791189, -10788344.273003066, 4446222.2558505516}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-84581.654415352721, -10788344.285452537, 4446222.1937462697},
                                      {-84581.956744568219, -10788344.336413544, 4446222.025234092},
                                      {-84581.893551269575, -10788344.273031805, 4446222.2558583068},
                                      {-84581.734127846619, -10788344.281283556, 4446222.2144425269},
                                      {-84581.776256712386, -10788344.323538048, 4446222.0606930507},
                                      {-84581.935680656956, -10788344.315257559, 4446222.1021010745},
                                      {-84581.893551791189, -10788344.273003066, 4446222.2558505516},
                                      {-84581.654416395948, -10788344.285395062, 4446222.1937307594},
                                      {-84581.717609694591, -10788344.348776801, 4446221.9631065447},
                                      {-84581.893552312802, -10788344.272974327, 4446222.2558427965}},
                                     {{0, 1, 2}, {3, 4, 5}, {3, 5, 6}, {7, 8, 9}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs4.py "strip_vs_tri" 22018 (target 0 of B against two of A's triangles, in every
// order): two needle triangles of one strip, each edge 1.5e-7 long at one end. The second
// needle's curve crosses the first's edge region, a strip 1.5e-7 wide, between two vertices
// 1.53e-7 apart, its curve 7e-8 off them and running outside the strip between them: a chord
// that long was dropped (only one shorter than 1e-7 could be straight or pinched), and the strip
// kept the first needle's d^2 where the second's is up to 0.0019 lower. The straight chord is now
// tried up to 1e-6 where the face's sides part there (kNearChord). The oracle: validate() after
// every insertion (d^2 continuous across every edge, polynomials against brute-force d^2), and
// d^2 by brute force on a grid at the end.
TEST(Degenerate, StripCrossedWhereTheCurveRunsOutsideBetweenVerticesPastTheToleranceIsCut) {
    const TriangleMesh T = make_mesh({{-1077247.5992004815, -2857479.651923954, -1454899.2624891079},
                                      {-1429350.1307138004, -3728517.6413343637, -1541732.7193404362},
                                      {-1324873.6041197807, -2668594.1127637611, -2345532.2035522815}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-1272298.7874507541, -3019716.3873905833, -1834514.6219326339},
                                      {-1268422.8836888396, -3041999.8017069744, -1800569.7307271599},
                                      {-1268422.9750977049, -3041999.9595751185, -1800569.8239237848},
                                      {-1260671.0761650105, -3086566.6303397566, -1732679.9483162118},
                                      {-1256795.263811961, -3108850.2025242914, -1698735.1503073624},
                                      {-1260671.1675738757, -3086566.7882079002, -1732680.0415128367}},
                                     {{0, 1, 2}, {3, 4, 5}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 40, 1e-9), 0); });
}

// Generate_pairs6.py "zero_area" 3977 (target 26 of B, a triangle 1e-11 across, against three of
// A's triangles sharing its corner): a piece 1e-6 across at the cluster of the sources' corners,
// left in no region by the cuts, whose corners the third source's face region holds (to 1e-7) but
// not its middle, 6.7e-7 beyond. A crack rule tried in the eleventh session (the deepest of the
// regions holding every corner, for generate_pairs4.py 21117) gave it to that region, whose domain
// then lay outside its region; DomainMesh::claim_cracks gives a crack only to the region deepest
// at its interior point. The oracle: validate() after every insertion, which checks that each
// domain's points lie in its feature's region (the region's lines from the source alone) and its
// polynomial against brute-force d^2.
TEST(Degenerate, CrackGoesOnlyToARegionHoldingItsMiddle) {
    const TriangleMesh T = make_mesh({{0.31929538487969972, -1.164907280984802, -1.3181680782593481},
                                      {0.3192953848822665, -1.1649072809886438, -1.3181680782507958},
                                      {0.31929538487409131, -1.1649072809815693, -1.3181680782520966}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.31929538487969972, -1.164907280984802, -1.3181680782593481},
                                      {0.33369211124826825, -1.0934000167184859, -1.2586715880921142},
                                      {0.31997641154404127, -1.1848380147466659, -1.2586715880921142},
                                      {0.31115552970690652, -1.2776154832800704, -1.3244320491244574},
                                      {0.31517117128827943, -1.1872109790782381, -1.3889509199486487},
                                      {0.31564992243410911, -1.23479344637129, -1.3873621516390842}},
                                     {{1, 0, 2}, {2, 0, 3}, {0, 4, 5}});
    expect_constructions_hold(T, B, [](const TargetSolver&) {});
}

// Generate_pairs.py "perp" 65235 (A to B): the maximum over A was taken at a domain mesh vertex
// 1.4e-10 outside the middle of a target's edge (a chord's end may stand up to the resolution
// beyond T'), where the distance is 1.2e-10 above the truth, and the certified interval missed
// the truth (the checker's Lipschitz bound, 4 - 3e-14). Candidates are now evaluated at the point
// of T' nearest them (TargetSolver::onto_target). The oracle: the witness point lies on A (brute
// force over A's triangles), and the result is its distance to B by brute force.
TEST(Degenerate, MaximumIsTakenOnTheTargetNotBeyondItsEdge) {
    const TriangleMesh A = make_mesh({{0, 0, 0},
                                      {7.68144509689981, 1.5503686744502163, 1.6098938463753878},
                                      {0.89098596526418361, -0.38503573738371488, -3.8804499082760531},
                                      {8.572431062163993, 1.1653329370665015, -2.2705560619006651},
                                      {1.7819719305283672, -0.77007147476742976, -7.7608998165521061},
                                      {9.4634170274281768, 0.78029719968278655, -6.1510059701767181}},
                                     {{0, 2, 1}, {2, 3, 1}, {2, 4, 3}, {4, 5, 3}});
    const TriangleMesh B = make_mesh({{0.91813419730454915, -0.54221082955664923, -3.8586213352357257},
                                      {6.806087497747825, 0.374639885393109, -5.767009194443073},
                                      {8.599579294204359, 1.0081578448935671, -2.2487274888603381},
                                      {0.86383773322381807, -0.22786064521078056, -3.9022784813163804},
                                      {4.2078565935075964, -0.18955174818054887, -6.5980004383653057},
                                      {4.0240679332732174, -0.013182338814178851, -6.6742172826738448},
                                      {8.5452828301236288, 1.3225080292394358, -2.2923846349409924}},
                                     {{2, 0, 3}, {2, 3, 6}, {4, 1, 5}});
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = hausdorff(A, B, opt).a_to_b;
        EXPECT_LE(brute_distance(r.from_point, A), 1e-13) << "the witness is not on A";
        const double d = brute_distance(r.from_point, B);
        EXPECT_NEAR(r.distance, d, 1e-13);
    }
}

// A needle of B (its corner at the start of A's needle, which runs on from it) is nearest to that
// needle only in a sliver 2.9e-5 of the target long and at most 8.5e-10 of it wide, too thin to cut
// (kVertexTolerance): its domain stays with the neighbour's edge quadratic, which lies above d^2
// there, and the candidates, evaluated directly, miss the true maximum on the sliver's far side
// (generate_pairs.py "sliver" 65010). The certified interval must still contain the distance there.
// Oracle: along each of the target's two edges from that corner, the point where A's two triangles
// are equally far, found by bisection of brute-force point-triangle distances: its distance to A
// is a lower bound of the one-sided distance.
TEST(Degenerate, ThinDomainLeftToANeighbourStillBoundsTheMaximum) {
    const TriangleMesh A = make_mesh({{-1.7995145709702533e-05, 1.3117479096357672e-05, 2.71413692496988e-05},
                                      {-9.7862690262138435e-06, 6.4632557915811119e-06, 1.0833086830265213e-05},
                                      {-9.7858146500267501e-06, 6.4630920167716799e-06, 1.0833382367966089e-05},
                                      {-9.7862689907784692e-06, 6.4632557788088283e-06, 1.0833086853313274e-05},
                                      {-1.5773922364905665e-06, -1.9096755148651432e-07, -5.4751955200707225e-06},
                                      {-1.5769378603034697e-06, -1.9113132629594779e-07, -5.4748999823698485e-06}},
                                     {{1, 2, 0}, {3, 5, 4}});
    const TriangleMesh B = make_mesh({{-1.7995145745120023e-05, 1.3117479109123509e-05, 2.7141369226662374e-05},
                                      {-9.7862689907963534e-06, 6.463255778815275e-06, 1.0833086853301643e-05},
                                      {-1.5773922364726831e-06, -1.9096755149296024e-07, -5.4751955200590894e-06},
                                      {-1.7994691368932926e-05, 1.3117315334314075e-05, 2.7141664764363246e-05},
                                      {-9.7858146146092567e-06, 6.4630920040058414e-06, 1.0833382391002515e-05},
                                      {-1.5769378602855858e-06, -1.9113132630239371e-07, -5.4748999823582153e-06}},
                                     {{0, 4, 3}, {1, 2, 4}, {0, 1, 4}, {2, 5, 4}});
    const auto a0 = A.corners(0), a1 = A.corners(1), t = B.corners(3);
    double lower = 0;
    for (int e = 0; e < 2; ++e) {
        const Vec3 from = t[2], dir = t[e] - t[2];
        auto at = [&](double s, double& d0, double& d1) {
            const Vec3 p = from + dir * s;
            d0 = std::sqrt(closest_point_on_triangle(p, a0[0], a0[1], a0[2]).dist2);
            d1 = std::sqrt(closest_point_on_triangle(p, a1[0], a1[1], a1[2]).dist2);
        };
        double lo = 0, hi = 1e-3, d0, d1;
        at(lo, d0, d1);
        ASSERT_LT(d0, d1);
        at(hi, d0, d1);
        ASSERT_GT(d0, d1);
        for (int i = 0; i < 200; ++i) {
            const double m = 0.5 * (lo + hi);
            at(m, d0, d1);
            (d0 < d1 ? lo : hi) = m;
        }
        at(lo, d0, d1);
        lower = std::max(lower, std::min(d0, d1));
    }
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const OneSidedResult r = hausdorff(A, B, opt).b_to_a;
        EXPECT_GE(r.upper, lower) << "the certified interval misses the distance";
        EXPECT_GE(r.distance, lower * (1 - 1e-12));
        EXPECT_LE(r.lower, lower * (1 + 1e-9));
    }
}

// Generate_pairs5.py "sliver_strip" 893 (target 7 of B, the paper's order): a strip of zero-area
// triangles along one line. A new source's curve, the line x + y = 0.75 in the frame, runs along
// the face's boundary (an older conic within 5e-8 of it) from one of its crossings and then leaves
// it for the face's inside at a vertex 2.3e-8 off the line (not counted on it: that takes 1e-8).
// The chord between its crossings was dropped as outside the face, and a triangle of 4.4e-3 of T'
// kept a source up to 5.4e-3 farther in d^2; DomainMesh::chord_past_departure inserts the part
// past the vertex. The oracle: validate() after every insertion (each domain's polynomial against
// brute-force d^2 at several points, d^2 continuous across every arc), then brute-force d on a grid
// (41 steps: one of 40 puts points on the line, where what stays within 5e-8 of it is off by more).
TEST(Degenerate, CurveLeavingTheBoundaryAtAVertexJustOffItCutsTheFace) {
    const TriangleMesh T = make_mesh({{8.583675369758655, -2.768400822163057, 2.5149910648880756},
                                      {8.256532594579653, -2.9673332228349216, 4.552287893877283},
                                      {9.311593026678654, -2.374965234209307, 3.724921540276959}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{9.64194953370333, -2.18182610241129, 1.6875750770230251},
                                      {6.476768237406327, -3.9589300682881348, 4.169674137823997},
                                      {7.549837916650079, -3.356450714791451, 3.3281851953663932},
                                      {9.46775350056453, -2.3025143068314033, 4.495310414426739},
                                      {9.30949445916601, -2.3913694924688444, 4.619415406388953},
                                      {9.62601258879571, -2.2136590958811597, 4.3712055003088555},
                                      {9.15123537093483, -2.4802247034190876, 4.7435203205068355},
                                      {8.992976329536308, -2.569079889056529, 4.86762531246905},
                                      {9.78427163019423, -2.1248039102437186, 4.247100508346642},
                                      {8.834717241305128, -2.657935100006772, 4.991730226586933}},
                                     {{0, 1, 2}, {3, 4, 5}, {3, 6, 4}, {6, 7, 4}, {8, 3, 5}, {6, 9, 7}});
    expect_constructions_hold(T, B, [&](const TargetSolver& ts) { EXPECT_EQ(grid_points_off_d2(ts, B, 41, 1e-9), 0); });
}

// The angles of the faces at each vertex of the domain mesh, summed: 2 pi where the faces tile the
// plane round it (face 0, the outside, included). A face turned inside out somewhere (a needle of
// it folded over a neighbour) makes it 4 pi there. Counts the vertices where it is not 2 pi, but
// for those in a cluster below the resolution.
int folded_vertices(const DomainMesh& m) {
    const auto& V = m.vertices();
    const auto& E = m.edges();
    const auto& H = m.half_edges();
    auto out_dir = [&](int h) {  // the arc's tangent leaving h's origin
        const auto& e = E[h >> 1];
        const Vec2 d = (h & 1) ? e.curve.derivative(e.z1) * -1.0 : e.curve.derivative(e.z0);
        return d / norm(d);
    };
    std::vector<double> sum(V.size(), 0.0);
    for (size_t h = 0; h < H.size(); ++h) {
        if (!E[h >> 1].alive) continue;
        const Vec2 d1 = out_dir((int)h), d2 = out_dir(H[h].prev ^ 1);
        double angle = std::atan2(cross(d1, d2), dot(d1, d2));
        if (angle <= 0) angle += 2 * M_PI;
        sum[H[h].origin] += angle;
    }
    // Below the resolution (vertices within kVertexTolerance of each other, where several boundaries
    // cross) a piece that small may lie on the wrong side of a line (README "Resolution"): not counted.
    auto clustered = [&](size_t v) {
        for (size_t w = 0; w < V.size(); ++w)
            if (w != v && V[w].alive && norm(V[w].p - V[v].p) <= DomainMesh::kVertexTolerance) return true;
        return false;
    };
    int folded = 0;
    for (size_t v = 0; v < V.size(); ++v)
        folded += V[v].alive && sum[v] > 0 && std::fabs(sum[v] - 2 * M_PI) > 0.5 && !clustered(v);
    return folded;
}

// Generate_pairs4.py "lod_surface" 28934 (target 7 of B, nearest first): the target is a coarse
// triangle, its sources near-coplanar pieces of a 1-to-4 split of it 1.1e-3 away. Three region
// lines cross T' 5e-5 rad apart; after the fourth insertion a face ran 3.4e-6 down one of them and
// back up another 2e-10 beside it, on the far side: a needle turned inside out, covered by the two
// neighbours across those arcs as well, whose source undercuts the face's by up to 4.6e-11 there
// (a step of 2.3e-11 in d^2 at 1.2e-6 across the arc). DomainMesh::unfold_needles gives the needle
// to a neighbour. The oracles: validate() after every insertion (each domain's polynomial against
// brute-force d^2, d^2 continuous across every arc), and the faces' angles round every vertex
// summing to 2 pi (folded_vertices).
TEST(Degenerate, NeedleTurnedInsideOutGoesToANeighbour) {
    const TriangleMesh T = make_mesh({{537.9215398564819, 431.05691878258597, -101.07444399825926},
                                      {879.3109640337265, 213.65908441801503, 588.1032659500538},
                                      {346.3076360026431, -376.7977216009889, 665.8379798795648}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{440.5825424147689, 28.652514081243623, 283.60320222014997},
                                      {707.8501627113733, 323.1195254257001, 244.1251811143802},
                                      {612.0432107844539, -80.80779476608735, 627.5813930532922},
                                      {879.3109640337265, 213.65908441801503, 588.1032659500538},
                                      {346.3076360026431, -376.7977216009889, 665.8379798795648},
                                      {537.9215398564819, 431.05691878258597, -101.07444399825926}},
                                     {{0, 1, 2}, {1, 3, 2}, {0, 2, 4}, {5, 1, 0}});
    expect_constructions_hold(T, S, [](const TargetSolver& ts) { EXPECT_EQ(folded_vertices(*ts.domain_mesh()), 0); });
}

// The domain mesh of T' (frame fr) with every triangle of S inserted in order (the fast insertion),
// validate() checked after each.
void insert_all_validating(DomainMesh& mesh, const TargetFrame& fr, const TriangleMesh& S) {
    for (uint32_t s = 0; s < S.num_triangles(); ++s) {
        mesh.insert(project_source(fr, S.corners(s), s));
        EXPECT_EQ(mesh.validate(), "") << "after source " << s;
    }
}

// Generate_pairs5.py "seam_strip" 211 (target 17 of B, the paper's order; four of its thirteen
// sources, inserted in that order, make the same fault): the last source is a sliver whose face
// region ends in a wedge of 6e-6 rad. Cut by its two lines alone, the wedge ran on 1.5e-4 of T' past
// its tip, inside both lines to 9e-9, and kept the plane's quadratic there, 2.3e-8 below d^2
// (3.2e-7): a step of that across an arc. Each region's corner below 0.1 rad now has a bevel
// (regions.cpp). The oracles: validate() after every insertion (d^2 continuous across every arc),
// then the polynomial against brute-force d over the sources at points of that stretch.
TEST(Degenerate, SliverFaceRegionEndsAtItsTip) {
    const TriangleMesh T = make_mesh({{1738475713.395395, -2045902066.3063233, -1513121292.7978249},
                                      {1738661452.524767, -2046974477.8491502, -1513530549.3060231},
                                      {1738663256.4513733, -2046861909.9048603, -1513712679.4121366}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{1738624629.2805736, -2046946319.6573184, -1513418312.3397837},
                                      {1738543908.6503706, -2047065698.2383132, -1513250154.7070355},
                                      {1738543908.8688874, -2047065699.356681, -1513250155.3960934},
                                      {1738624629.4990904, -2046946320.7756863, -1513418313.0288417},
                                      {1738611084.2345545, -2046718179.2763622, -1513792888.5614827},
                                      {1738647588.7413595, -2046827543.6455245, -1513603809.4485886},
                                      {1738647588.9598765, -2046827544.7638924, -1513603810.1376464}},
                                     {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {5, 0, 3}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    const Vec2 from{0.903708596838, 0.104072536004}, to{0.903708560008, 0.104072732584};
    int off = 0;
    for (int i = 0; i <= 20; ++i) {
        const Vec2 p = from + (to - from) * (i / 20.0);
        const int f = mesh.face_at(p);
        ASSERT_GT(f, 0);
        const double d = brute_distance(fr.to_world(p), S) / fr.scale;
        off += std::fabs(mesh.faces()[f].poly(p) - d * d) > 1e-6 * d * d;
    }
    EXPECT_EQ(off, 0);
}

// Generate_pairs12.py "flat_kite_diagonals" 1338 (side B, target 6, by hand): a coplanar sliver
// source whose face region ends at its corner (0, 0) in a tip 7e-14 rad wide, too narrow for its
// lines' normals to give a bevel, inserted into a target 1.5e-7 tall that lies beyond the tip,
// where an earlier source's corner at (0, 0) ties with the sliver's. That region passed over, the
// crack rule held the target to the face region's lines within kCluster (which, along a tip that
// sharp, reaches 1e8 past it) and gave it the face region: d^2 0 where it is |p|^2. The tip's
// bevel now comes from the sides' directions. The oracle: d^2 by brute force over both sources.
TEST(Degenerate, FaceRegionTipTooSharpForItsNormalsStillEnds) {
    const double m = 7.5e-8;
    const TriangleMesh T = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 2 * m, 0}}, {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0, 0, 0}, {-1, 0.5, 0}, {-1, -0.5, 0},  // its corner region holds T'
                                      {-12, -12 * m, 0}, {-7, -7 * m + 5e-13, 0}},
                                     {{0, 1, 2}, {0, 3, 4}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    const SourceProjection sliver = project_source(fr, S.corners(1), 1);
    const SourceRegion& face = sliver.regions.back();
    ASSERT_EQ(face.kind, Region::abc);
    // The premise: two of its lines meet with normals summing to less than 1e-13.
    bool sharp = false;
    for (size_t i = 0; i < 3; ++i)
        for (size_t j = i + 1; j < 3; ++j) sharp |= norm(face.planes[i].n + face.planes[j].n) < 1e-13;
    ASSERT_TRUE(sharp);
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 40, 1e-9), 0);
    // On the sliver's lines 0.999 past its tip, inside T': d^2 = |p|^2 (frame units: T''s longest
    // side is its unit).
    const Vec3 w{0.999, 0.999 * m, 0};
    const Vec2 beyond = fr.to_frame(w);
    EXPECT_LT(region_margin(face, beyond), -0.5);
    const int f = mesh.face_at(beyond);
    ASSERT_GT(f, 0);
    EXPECT_NEAR(mesh.faces()[f].poly(beyond), norm2(w) / (fr.scale * fr.scale), 1e-9);
}

// Generate_pairs10.py "thin_box" 2884 (side A, target 42, the paper's order; two of its six
// sources): a box 1.2e-12 thin against its own faces split differently. The target lies 2.4e-12 up;
// the sources are side walls standing under it, and source 42's top edge, parallel to T', lies
// 0.8e-12 below it. That edge's plane was taken as holding T' on both of its sides (a parallel
// plane within 1e-12 of T' counted as containing it), so the wall's face region, empty on T', and
// its top edge's region both covered the same strip; inserted after source 47, whose corner and
// edge regions meet across T', the face region's line moved their boundary: d^2 stepped by 0.089
// across it. The oracles: validate() (d^2 continuous across every arc) and d^2 by brute force.
TEST(Degenerate, ParallelPlaneJustBelowTheTargetDoesNotHoldIt) {
    const double z1 = 1.6072982894860258e-12, z2 = 3.2145965789720515e-12, x0 = 0.5965436220630986, x1 = 1.1930872441261973;
    const TriangleMesh T = make_mesh({{0.894815433094648, 0, 2.4109474342290387e-12},
                                      {1.789630866189296, 0, 2.4109474342290387e-12},
                                      {1.789630866189296, 0.4505799015556974, 2.4109474342290387e-12}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{x0, 0, z1}, {x1, 0, z1}, {x1, 0, z2},  // source 47
                                      {x0, 0, 0}, {x1, 0, z1}, {x0, 0, z1}},  // source 42: its top edge 0.8e-12 under T'
                                     {{0, 1, 2}, {3, 4, 5}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    // The premise: the wall's face region is empty on T' (T' lies above the wall's top edge), and
    // its top edge's region is not.
    const SourceProjection wall = project_source(fr, S.corners(1), 1);
    int none = 0;
    for (const HalfPlane& h : wall.regions.back().planes) none += h.kind == HalfPlane::None;
    EXPECT_GE(none, 1);
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 40, 1e-9), 0);
}

// A sliver source perpendicular to T' and straddling its plane (generate_pairs7.py
// "zero_area_in_closed_far" 2321, by hand): its long sides' planes are within 1e-12 of T''s, taken
// as parallel to it, and its face region ran on past its end at (1, 0, 2.5), where a source above
// T' (d = 0.5) was nearer than the sliver's vertex (d > 0.8) but not than its plane (d <= 0.5):
// inserted after it, the sliver's face region took that part with the plane's quadratic. The face
// region now ends at the planes across its longest edge's ends (regions.cpp,
// bound_sliver_face_region). The oracle: d^2 by brute force over both sources on a grid over T'.
TEST(Degenerate, SliverSeenEdgeOnEndsItsFaceRegionAtItsLongestEdge) {
    const TriangleMesh T = make_mesh({{0.5, 0, 0}, {1.5, 0, 0}, {1, 0, 5}}, {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-1, 0.5, 3.3}, {3, 0.5, 3.3}, {1, 0.5, 9},  // above T', inserted first
                                      {1, -2e-13, 2.5}, {1, -2e-13, -0.5}, {1, 8e-13, 0}},
                                     {{0, 1, 2}, {3, 4, 5}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    const SourceProjection sliver = project_source(fr, S.corners(1), 1);
    int lost = 0;  // the premise: two of the face region's sides taken as parallel to T'
    for (const HalfPlane& h : sliver.regions.at(6).planes) lost += h.kind != HalfPlane::Line;
    EXPECT_EQ(lost, 2);
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 40, 1e-9), 0);
}

// Generate_pairs6.py "zero_area" 7181 (target 34 of B, nearest first): a target 1.6e-14 across at
// the hub of a fan of A. Its sources' frame coordinates round by delta = 2.8e-3 of T', and a
// domain's tip came out 1.3e-6 of T' outside its region (2e-20 in world units, far below the
// coordinates' ulps, 7e-18): validate()'s region check allowed the vertex tolerance only, not
// delta, as its continuity check does. The oracle: validate() after every insertion, its
// polynomials against d^2 computed directly from the sources; the region check now holds each
// point to the larger of the two.
TEST(Degenerate, RegionCheckAllowsTheFramesRoundingOnATinyTarget) {
    const TriangleMesh T = make_mesh({{0.054668154383334826, 0.064249255783258838, 0.042383113544536243},
                                      {0.054668154383327554, 0.064249255783260739, 0.042383113544538997},
                                      {0.054668154383341293, 0.064249255783254383, 0.042383113544534688}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.054668154383334826, 0.064249255783258838, 0.042383113544536243},
                                      {0.054662625556680507, 0.063282123805586107, 0.044968014008922197},
                                      {0.05582784213119564, 0.064159546851164734, 0.041455211545112759},
                                      {0.055716634533297275, 0.064688218690654192, 0.040157178616881208},
                                      {0.05332998757319192, 0.065646900263975752, 0.040002389463260339},
                                      {0.053873455452987627, 0.06346743917000916, 0.045268038071615425},
                                      {0.052871625903031565, 0.064688071177531226, 0.043020895771436744}},
                                     {{1, 0, 2}, {2, 0, 3}, {0, 4, 3}, {1, 5, 0}, {5, 6, 0}, {0, 6, 4}});
    expect_constructions_hold(T, B, [](const TargetSolver&) {});
}

// How far, in T' units, the foot of face f's interior point on the feature its label names lies
// from the label's source triangle: sqrt(d_triangle^2 - d_feature^2), both by brute force in
// world coordinates (0 where the point lies in the feature's region).
double offset_from_label_region(const TargetSolver& ts, const TriangleMesh& S, int f) {
    const DomainMesh& m = *ts.domain_mesh();
    Vec2 p;
    if (!m.interior_point(f, p)) return HUGE_VAL;
    const Vec3 x = ts.frame().to_world(p);
    const auto c = S.corners(m.faces()[f].label.source);
    auto line2 = [&](int i, int j) { const Vec3 u = c[j] - c[i]; return norm2(cross(x - c[i], u)) / norm2(u); };
    double feature2 = 0;
    switch (m.faces()[f].label.region) {
        case Region::abc: { const Vec3 n = cross(c[1] - c[0], c[2] - c[0]); feature2 = dot(x - c[0], n) * dot(x - c[0], n) / norm2(n); break; }
        case Region::ab: feature2 = line2(0, 1); break;
        case Region::bc: feature2 = line2(1, 2); break;
        case Region::ca: feature2 = line2(2, 0); break;
        case Region::a: feature2 = norm2(x - c[0]); break;
        case Region::b: feature2 = norm2(x - c[1]); break;
        case Region::c: feature2 = norm2(x - c[2]); break;
    }
    const double triangle2 = closest_point_on_triangle(x, c[0], c[1], c[2]).dist2;
    return std::sqrt(std::max(0.0, triangle2 - feature2)) / ts.frame().scale;
}

// Generate_pairs4.py "thin_shell_far" 37587 (target 0 of A, 1e11 from the origin, the debugger's
// order; 20 of its 44 sources make the same fault): source 11 is a needle 1.4e-10 of T' wide. Its
// face region's line crossed a face of an older source, itself a needle, 2.8e-6 from that face's
// apex, and the piece cut off, a needle 2.8e-6 long, went to no region but the last, the face
// region, which keeps such a piece only if its interior point is within reach of it
// (DomainMesh::leftover_region). That point came from interior_point's fallback, at the piece's
// short end on the needle's line: point_beside stepped from the middle of the long arc's line,
// which the arc's polished end leaves by 4e-10, and missed a piece that thin at every step. So the
// piece kept the plane's quadratic 1.8e-6 of T' beside the needle (d^2 17% low there). A straight
// arc's middle is now its vertices'. The oracles: validate() after every insertion, and for each
// domain of the needle source the foot of its interior point on the label's feature (plane, edge
// line or corner) against the source triangle by brute force in world coordinates: it lies on the
// triangle, up to the region check's allowance.
TEST(Degenerate, PieceBesideANeedlesTipIsProbedFromItsLongArc) {
    const TriangleMesh T = make_mesh({{105050893053.9208, 84239035882.10136, -28277637576.12675},
                                      {105050880175.11977, 84239020520.93385, -28277645824.80031},
                                      {105050894106.01312, 84239017622.15497, -28277662177.07508}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{105050884467.99399, 84239025641.40817, -28277643075.308205},
                                      {105050891434.10898, 84239024191.0616, -28277651250.7065},
                                      {105050895726.80688, 84239029311.78845, -28277648501.409405},
                                      {105050900019.46838, 84239034432.56741, -28277645752.15255},
                                      {105050906984.9546, 84239032983.12134, -28277653928.246204},
                                      {105050902691.90317, 84239027862.90082, -28277656677.934288},
                                      {105050898398.90016, 84239022742.61095, -28277659427.568817},
                                      {105050887141.30928, 84239019070.48055, -28277654000.116184},
                                      {105050894106.01312, 84239017622.15497, -28277662177.07508},
                                      {105050893053.9208, 84239035882.10136, -28277637576.12675},
                                      {105050895726.80688, 84239029311.78845, -28277648501.409405},
                                      {105050888760.94984, 84239030761.76558, -28277640325.72583},
                                      {105050900019.46838, 84239034432.56741, -28277645752.15255},
                                      {105050891434.10898, 84239024191.0616, -28277651250.706505},
                                      {105050884467.99399, 84239025641.40817, -28277643075.308205},
                                      {105050888760.94984, 84239030761.76558, -28277640325.725826},
                                      {105050902691.90317, 84239027862.90082, -28277656677.934288},
                                      {105050898398.90016, 84239022742.61095, -28277659427.56882},
                                      {105050906984.9546, 84239032983.12134, -28277653928.246204},
                                      {105050893053.9208, 84239035882.10136, -28277637576.12675}},
                                     {{0, 1, 2}, {3, 2, 4}, {2, 5, 4}, {2, 1, 5}, {1, 6, 5}, {1, 7, 8}, {1, 8, 6}, {9, 10, 11}, {9, 12, 10}, {11, 13, 14}, {11, 10, 13}, {15, 14, 11}, {6, 5, 16}, {6, 16, 17}, {5, 4, 18}, {5, 18, 16}, {4, 3, 12}, {4, 12, 18}, {3, 19, 9}, {3, 9, 12}});
    expect_constructions_hold(
        T, S,
        [&](const TargetSolver& ts) {
            const auto& F = ts.domain_mesh()->faces();
            for (size_t f = 1; f < F.size(); ++f) {
                if (!F[f].alive || F[f].infinite || F[f].label.source != 11) continue;
                EXPECT_LE(offset_from_label_region(ts, S, (int)f), 4 * DomainMesh::kVertexTolerance) << "face " << f;
            }
        },
        true);
}

// Generate_pairs4.py "f32_export" 21117 (target 7 of B against two of A's triangles, the paper's
// order): the first source's cuts left a sliver 1.2e-7 wide along T''s edge (its corner region),
// and the line between the second source's edge and face regions runs inside it, along it. Both
// cuts dropped that chord as hugging the boundary and took the sliver whole as outside, so it was
// a crack, which went only to the region deepest at its interior point; that point lay at the
// sliver's short end, deepest in a corner region holding none of its far corners, and the sliver
// kept the first source's d^2 = 0.2 where the second gives 1e-15. A crack now goes to the deepest,
// at a point beside its longest arc, of the regions that hold that point and every corner
// (DomainMesh::claim_cracks). The oracles: validate() after every insertion, and d^2 by brute force
// at points 3e-8 and 6e-8 of T' inside each of T''s edges.
TEST(Degenerate, CrackAcrossARegionLineGoesToARegionHoldingItAll) {
    const TriangleMesh T = make_mesh({{0.002670458130974431, 0.01604682107749472, -0.015214456453168218},
                                      {0.0035096783411027207, 0.00870748703277047, -0.014843162899425331},
                                      {0.000667374394962319, 0.01423056922692112, -0.017119838173099658}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0.0046735419891774654, 0.017863072454929352, -0.013309074565768242},
                                      {0.005512761417776346, 0.010523739270865917, -0.01293778046965599},
                                      {0.0026704580523073673, 0.01604682020843029, -0.015214456245303154},
                                      {0.0006673744064755738, 0.014230568893253803, -0.017119837924838066}},
                                     {{0, 1, 2}, {2, 1, 3}});
    expect_constructions_hold(
        T, S,
        [&](const TargetSolver& ts) {
            const auto c = ts.frame().ccw_corners();
            int off = 0;
            for (int e = 0; e < 3; ++e) {
                const Vec2 a = c[e], b = c[(e + 1) % 3], in = perp(b - a) / norm(b - a);
                for (double depth : {3e-8, 6e-8})
                    for (int i = 1; i < 40; ++i) {
                        double poly, d2;
                        ASSERT_TRUE(polynomial_and_d2(ts, S, a + (b - a) * (i / 40.0) + in * depth, poly, d2));
                        off += std::fabs(poly - d2) > 1e-9;
                    }
            }
            EXPECT_EQ(off, 0);
        },
        true);
}

// Generate_pairs10.py "fan_thin" 67, at unit size: a cone of 437 thin triangles, its apex h above
// the middle of a flat 437-gon fanned from a rim vertex (435 long thin triangles, each crossing
// dozens of the cone's). Every point of the cone lies over the polygon, so its distance is its
// height: h at the apex, by hand. The confirmation bounded each piece by one source or a few cut
// apart, and the pieces over dozens of sources outran its budget: 280 of 437 targets stayed open
// and the interval's upper end was 0.24 of the diagonal (2.6e-5 where h was 1e-14, 47 s). They are
// now bounded from the sources that cover them (cover_bound.cpp). Also 1e6 from the origin.
TEST(Degenerate, ConeOverAFlatFanIsConfirmedToTheTolerance) {
    const int n = 437;
    for (const double far : {0.0, 1e6}) {
        std::vector<Vec3> ring;
        for (int i = 0; i < n; ++i)
            ring.push_back(Vec3{std::cos(2 * 3.14159265358979323846 * i / n), std::sin(2 * 3.14159265358979323846 * i / n), 0} + Vec3{far, far, far});
        std::vector<Vec3> pa = ring, pb = ring;
        pa.push_back(Vec3{far, far, far + (far > 0 ? 1e-6 : 1e-10)});
        const double h = pa.back().z - far;  // exact (Sterbenz): the apex's height over the plane z = far
        std::vector<Tri> ta, tb;
        for (int i = 0; i < n; ++i) ta.push_back({uint32_t(n), uint32_t(i), uint32_t((i + 1) % n)});
        for (int i = 1; i + 1 < n; ++i) tb.push_back({0u, uint32_t(i), uint32_t(i + 1)});
        const TriangleMesh A = make_mesh(pa, ta, "cone"), B = make_mesh(pb, tb, "flat fan");
        const VoxelGrid grid(A, B);
        for (Mode mode : {Mode::Paper, Mode::Fast}) {
            HausdorffOptions opt;
            opt.mode = mode;
            const OneSidedResult r = one_sided(grid, 0, opt);
            EXPECT_LE(r.lower, h) << mode_name(mode) << " at " << far;
            EXPECT_GE(r.upper, h) << mode_name(mode) << " at " << far;
            EXPECT_LE(r.upper - r.lower, 1e-9 * 2) << mode_name(mode) << " at " << far;  // the diagonal is 2
        }
    }
}

// Generate_pairs12.py "snapped_corners" 3929 (target 0 of A, the paper's order): three fans of B
// whose apexes lie within 6e-8 of T''s corner (1e-9 of the coordinates, 530 from the origin).
// After six sources one domain is two sectors of T' joined at that corner, where two other
// domains' tips end 4e-8 and 6e-8 below it; the seventh source's face region has its apex there,
// and its line through the corner, 5e-9 and 8e-9 from those tips, crosses one sector. Its chords
// paired the line's far crossing with the farther tip, across the boundary, and the face stayed one
// piece inside the region: the sector outside it took the plane's quadratic, up to 0.0019 below
// d^2. The face is now cut between the places where its loop changes side (domain_split.cpp,
// cut_at_side_changes). The oracles: validate() after every insertion (d^2 continuous across every
// arc) and d^2 by brute force on a grid over T'.
TEST(Degenerate, LineThroughAPinchOfTipsCutsTheSectorItCrosses) {
    const TriangleMesh T = make_mesh({{-18.565128038122328, -297.00825265362465, 529.8912198304737},
                                      {-18.100143653174328, -297.11907737825027, 529.944794501965},
                                      {-18.939175850394992, -297.2063596082291, 529.946080629697}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-18.56512803725182, -297.0082526539985, 529.8912198308277},
                                      {-18.366120380714463, -297.6327492915107, 529.8122805746442},
                                      {-18.99930278493582, -297.1499941743587, 530.0252493811922},
                                      {-18.541970662939544, -296.26859427920243, 529.6856199228521},
                                      {-19.036828415488554, -297.38961851989444, 530.0097589053138},
                                      {-18.652532875315934, -297.3305646131157, 530.1093920066279},
                                      {-18.56512803886199, -297.00825265424453, 529.8912198291928},
                                      {-18.8750942640564, -297.2406359806268, 529.9686918628802},
                                      {-18.89713980989714, -296.1074933437371, 529.8665091159793},
                                      {-19.03965541878976, -297.3610072109301, 529.9665296569323},
                                      {-18.584922412992622, -297.2655694072797, 530.0767200537398}},
                                     {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {6, 7, 8}, {6, 8, 9}, {6, 9, 10}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 60, 1e-9), 0);
}

// Generate_pairs9.py "shared_edge_tiny" 3042 (target 1 of B, nearest first): a target 5.8e-10
// across, 160 from the origin, 1e-11 from an edge that four sources share. Every region line and
// the planes' line pair pass within 1e-7 of one point of T', where a sliver of the first source's
// edge region ends 1.2e-7 from the fourth source's face region line: the face across that line is
// two lobes joined there. One line of the pair (the fourth source's plane against the third's)
// crosses both lobes and the sliver's tip 2.5e-8 past it; its chord ended at the tip, and the lobe
// beyond it went with the other whole, on the wrong side of the line: the fourth source's plane
// kept where the third's is nearer, 0.0019 below d^2 (frame units, where d^2 is 5e-4). Cut between
// the places where the face's loop changes side, at the vertex nearest the line within the
// resolution (domain_split.cpp, cut_at_side_changes), it holds. The oracles: validate() after
// every insertion and d^2 by brute force on a grid over T' (the frame's coordinates round by
// 2.5e-5 of T', and d^2 is up to 1: it holds to 1e-4 (1 + d^2)).
TEST(Degenerate, LineThroughASliversTipCutsBothLobes) {
    const TriangleMesh T = make_mesh({{-106.80828465664456, -1.7713327181354768, -159.79282704517885},
                                      {-106.80828465681455, -1.7713327182971395, -159.79282704465285},
                                      {-106.80828465655517, -1.7713327178102756, -159.79282704473803}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-106.90653066044044, -1.7484272539204178, -159.95582334198215},
                                      {-106.71003865268946, -1.7942381821459563, -159.62983074785836},
                                      {-106.61062500075934, -2.0079187508242375, -159.72835151844512},
                                      {-106.994803038499, -1.5690010527052882, -159.88259805420168},
                                      {-107.023176449152, -1.5857393473990289, -159.9619676833147},
                                      {-106.69854703504177, -1.6388406214182891, -159.85399547093681}},
                                     {{1, 0, 4}, {1, 0, 3}, {0, 1, 2}, {1, 0, 5}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-4), 0);
}

// Generate_pairs7.py "spike_grid" 9835 (target 8 of B, the paper's order, its first three sources):
// where source 1's edge quadratic meets source 0's plane, their difference is nearly a double line
// along an edge of T' (l2 = 1.3e-12, within the rounding of its quadratic part, b2 = -3.7e-10). The
// parabola dropped l2 Y^2 whole, which moved it 1.2e-3 along its axis (l2 Y^2 / 2 b2), and the chord
// ran out to that vertex: d^2 stepped by 6e-7 across an arc. The term is now taken to first order
// there too, as the computed quadratic has it. Oracles: validate() after every insertion (d^2
// continuous across every arc) and brute force on a grid.
TEST(Degenerate, NearlyDoubleLineKeepsItsFirstOrderTerm) {
    const TriangleMesh T = make_mesh({{-31.732226293096424, 12.020943419869326, -12.263207887283993},
                                      {-39.665282866370539, 15.026179274836659, -15.329009859104993},
                                      {-38.10877343019623, 5.1217420959954403, -2.5261856444915769}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-30.175716856922126, 2.1165062410281088, 0.53961632732942066},
                                      {-38.10877343019623, 5.1217420959954403, -2.5261856444915769},
                                      {-44.485320567296029, -1.7774592278784458, 7.2108365983008387},
                                      {-133.21481474907941, -1032.2309939762522, -799.82882416658151},
                                      {-23.79916971982232, 9.0157075649019944, -9.1974059154629941}},
                                     {{0, 1, 2}, {1, 3, 2}, {4, 1, 0}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0);
}

// Generate_pairs11.py "overlap_retri" 3145 (target 134 of B, nearest first; 18 of its 82 sources,
// inserted in that order, make the same fault): a coplanar copy's domain (source 101's face region)
// wrapped around another's wedge, both pinched at T''s corner and at a vertex 1.7e-8 from it, where
// a fan of the copy's slivers meets. An insertion that changed nothing there rebuilt the face's
// loops: the wedge's other side came out as a loop of its own, clockwise, and the point that says
// which outer loop holds it was the middle of its first arc, the one 1.7e-8 long between the two
// pinches, which the ray test counted outside: the loop became a face of area -3.5e-7. Now it is the
// middle of the hole's longest arc. Oracles: validate() after every insertion (areas, d^2
// continuous) and brute force on a grid.
TEST(Degenerate, HoleTouchingItsFaceAtTwoPinchesStaysAHole) {
    const TriangleMesh T = make_mesh({{3.8295992922521237e-06, -7.6546051640398767e-06, 1.4018592090350261e-06},
                                      {-5.046457400564231e-07, -8.5547388238960579e-06, 1.4018588514207401e-06},
                                      {-5.0464560571992152e-07, -9.5916584420227782e-06, 1.4018587266997814e-06}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-5.2213279158384614e-07, -9.578834509251807e-06, 1.4018587278416331e-06},
                                      {-4.8715842323111148e-07, -9.5788345047207567e-06, 1.4018587286496962e-06},
                                      {-4.8715842353318143e-07, -9.5765028801639085e-06, 1.4018587289307658e-06},
                                      {-5.2213279128177609e-07, -9.5811661338086553e-06, 1.4018587275605634e-06},
                                      {-4.8715842292904153e-07, -9.5811661292776067e-06, 1.4018587283686265e-06},
                                      {-4.8715842323111148e-07, -9.5788345047207567e-06, 1.4018587286496962e-06},
                                      {-5.2213279128177609e-07, -9.5811661338086553e-06, 1.4018587275605634e-06},
                                      {-4.8715842323111148e-07, -9.5788345047207567e-06, 1.4018587286496962e-06},
                                      {-5.2213279158384614e-07, -9.578834509251807e-06, 1.4018587278416331e-06},
                                      {-5.2213279097970614e-07, -9.5834977583655035e-06, 1.4018587272794937e-06},
                                      {-4.8715842262697137e-07, -9.583497753834455e-06, 1.4018587280875568e-06},
                                      {-4.8715842292904153e-07, -9.5811661292776067e-06, 1.4018587283686265e-06},
                                      {-5.2213279097970614e-07, -9.5834977583655035e-06, 1.4018587272794937e-06},
                                      {-4.8715842292904153e-07, -9.5811661292776067e-06, 1.4018587283686265e-06},
                                      {-5.2213279128177609e-07, -9.5811661338086553e-06, 1.4018587275605634e-06},
                                      {-5.2213279067763609e-07, -9.5858293829223535e-06, 1.4018587269984241e-06},
                                      {-4.8715842232490143e-07, -9.5858293783913032e-06, 1.4018587278064871e-06},
                                      {-4.8715842262697137e-07, -9.583497753834455e-06, 1.4018587280875568e-06},
                                      {-5.2213279067763609e-07, -9.5858293829223535e-06, 1.4018587269984241e-06},
                                      {-4.8715842262697137e-07, -9.583497753834455e-06, 1.4018587280875568e-06},
                                      {-5.2213279097970614e-07, -9.5834977583655035e-06, 1.4018587272794937e-06},
                                      {-5.2213279037556614e-07, -9.5881610074792018e-06, 1.4018587267173544e-06},
                                      {-4.8715842202283148e-07, -9.5881610029481532e-06, 1.4018587275254175e-06},
                                      {-4.8715842232490143e-07, -9.5858293783913032e-06, 1.4018587278064871e-06},
                                      {-5.2213279037556614e-07, -9.5881610074792018e-06, 1.4018587267173544e-06},
                                      {-4.8715842232490143e-07, -9.5858293783913032e-06, 1.4018587278064871e-06},
                                      {-5.2213279067763609e-07, -9.5858293829223535e-06, 1.4018587269984241e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-4.8964436230287551e-07, -9.5826715457228835e-06, 1.4018587281297172e-06},
                                      {-4.9034038269022242e-07, -9.5816004997275836e-06, 1.4018587282427472e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-4.9286952276312497e-07, -9.5787307400104435e-06, 1.4018587285302531e-06},
                                      {-4.9384459969022135e-07, -9.5779056285695491e-06, 1.4018587286071889e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-4.9384459969022135e-07, -9.5779056285695491e-06, 1.4018587286071889e-06},
                                      {-4.9487730465792835e-07, -9.5771538943390379e-06, 1.401858728673948e-06},
                                      {-5.2213279007349619e-07, -9.5904926320360517e-06, 1.4018587264362847e-06},
                                      {-4.8715842172076153e-07, -9.5904926275050014e-06, 1.4018587272443478e-06},
                                      {-4.8715842202283148e-07, -9.5881610029481532e-06, 1.4018587275254175e-06},
                                      {-5.2213279007349619e-07, -9.5904926320360517e-06, 1.4018587264362847e-06},
                                      {-4.8715842202283148e-07, -9.5881610029481532e-06, 1.4018587275254175e-06},
                                      {-5.2213279037556614e-07, -9.5881610074792018e-06, 1.4018587267173544e-06},
                                      {-5.2213278977142624e-07, -9.5928242565929e-06, 1.401858726155215e-06},
                                      {-4.8715842172076153e-07, -9.5904926275050014e-06, 1.4018587272443478e-06},
                                      {-5.2213279007349619e-07, -9.5904926320360517e-06, 1.4018587264362847e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-5.0322594908724747e-07, -9.5742289789077869e-06, 1.4018587288336463e-06},
                                      {-5.0450200547486855e-07, -9.574171847486821e-06, 1.4018587288110509e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-5.1964684918931205e-07, -9.6006453383750196e-06, 1.4018587252698456e-06},
                                      {-5.1895082880196514e-07, -9.6017163843703195e-06, 1.4018587251568156e-06},
                                      {-5.0464560574609378e-07, -9.5916584420489515e-06, 1.4018587266997814e-06},
                                      {-5.1895082880196514e-07, -9.6017163843703195e-06, 1.4018587251568156e-06},
                                      {-5.181784838601329e-07, -9.6027337668915355e-06, 1.4018587250520182e-06}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}, {21, 22, 23}, {24, 25, 26}, {27, 28, 29}, {30, 31, 32}, {33, 34, 35}, {36, 37, 38}, {39, 40, 41}, {42, 43, 44}, {45, 46, 47}, {48, 49, 50}, {51, 52, 53}});
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0);
}

// Generate_pairs14.py "fin_plate" 3204 (target 0 of A; two of its sources, one triangle of each wall
// of a double-walled fin, 3.6e-11 apart, standing on T'): where the nearer wall's face region meets
// the farther one's domain, g (their difference) is 1.8e-11 in its linear part and 5e-16 in its
// quadratic part, rounding of the two quadratic parts (0.5). Scaled to unit size that noise was a
// conic of 2.8e-5, no chord was found across the strip of the face region, and the strip went whole
// to the farther wall, 7e-13 (3.7e-9 relative) above d^2 over half of it, in every order. The
// quadratic part within its rounding is now dropped: the curve is the line of the rest. Oracle:
// brute force on a grid, to 1e-13 (validate() passes either way: its tolerance is 1e-7 relative).
TEST(Degenerate, ParallelWallsNoiseQuadraticPartIsDropped) {
    const TriangleMesh T = make_mesh({{0.0, 0.0, 0.0},
                                      {-0.14924011367722434, 0.6970775978904878, 0.7012918158575904},
                                      {0.9237222516313933, -0.1547628784230537, 0.35040783852996216}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0.11151926976250412, 0.12755201252064616, 0.6099165687246886},
                                      {0.07420924134319803, 0.30182141199326806, 0.785239522689086},
                                      {0.28791696696306146, 0.47759889294576807, 0.2995119393665218},
                                      {0.11151926979597457, 0.12755201251503842, 0.6099165687373853},
                                      {0.07420924137666848, 0.3018214119876603, 0.785239522701783},
                                      {0.2879169669965319, 0.47759889294016034, 0.2995119393792186}},
                                     {{0, 1, 2}, {3, 5, 4}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-13), 0);
}

// Generate_pairs9.py "tinydiff_coinc_far" 4651 (target 9 of A, nearest first; three of its seven
// sources, inserted in that order, make the same fault): triangles 3e-4 across, 7.8e7 from the
// origin, two of the sources nearly parallel to T' and 0.2 (frame units) from it, the third's edge
// region between them. The edge's and the first plane's boundary is a nearly double line, its
// parabolic form 1.2e-8 off its equation, and the second plane's conics cross it at 3.7e-3
// radians. The first plane's domain found its crossing where the curves meet; the edge's, its
// root along the arc 4.1e-6 away, which polishing onto the curves would have moved more than
// 1e-7: a piece of the arc between the two vertices separated the two planes' domains, d^2
// stepping by 2.2e-11 at 0.041. Now a crossing that polishing moves along its arc (and not across
// it) is taken where the curves meet (polish_along_arc). Oracles: validate() after every insertion
// (d^2 continuous across every arc) and brute force on a grid.
TEST(Degenerate, ShallowCrossingOfAnOffCurveArcIsWhereTheCurvesMeet) {
    const TriangleMesh T = make_mesh({{-78339192.098317564, 13239638.298548847, -1286182.6361326913},
                                      {-78339192.09854795, 13239638.29873435, -1286182.6363395564},
                                      {-78339192.098613605, 13239638.298387969, -1286182.6362621642}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-78339192.098392472, 13239638.298477098, -1286182.6360651799},
                                      {-78339192.098499253, 13239638.29877756, -1286182.6362343021},
                                      {-78339192.098698765, 13239638.298477564, -1286182.6362561423},
                                      {-78339192.098391905, 13239638.298614165, -1286182.6361116297},
                                      {-78339192.098603606, 13239638.298464868, -1286182.636192522},
                                      {-78339192.098614976, 13239638.298730437, -1286182.6362902971},
                                      {-78339192.098530173, 13239638.298577407, -1286182.6361852081},
                                      {-78339192.098396406, 13239638.298602331, -1286182.6361103933},
                                      {-78339192.098446578, 13239638.298656547, -1286182.6361601597}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    // Brute force in double 7.8e7 from the origin is off by 1e-4 of d^2: it runs on both meshes
    // moved by T''s corner (exactly: the coordinates differ by less than a factor 2), which leaves
    // the frame's axes and scale as they were.
    const Vec3 o = T.corners(0)[0];
    const TargetFrame near = TargetFrame::make(shifted(T, -1.0 * o).corners(0));
    ASSERT_EQ(near.scale, fr.scale);
    EXPECT_EQ(grid_points_off_d2(mesh, near, shifted(S, -1.0 * o), 200, 1e-12), 0);
}

// Generate_pairs5.py "cone_fan" 60335 (target 18 of A, nearest first, after its first two
// sources; targets 26 and 34, its rotations, the same): a flat double cone, its apex 1.3e-8 above
// its base's centre. The two sources' edges from one base corner, to the apex and to the centre,
// have quadratics 1.8e-11 apart (of 0.6), and their difference's quadratic part has a smaller
// eigenvalue 1.4e-7 of the larger: within the rounding of the operands' quadratic parts, so
// decompose_conic took the curve as a parabola without it. That moved the curve by 5e-6 across T'
// (l2 (Y - Yr)^2 over the gradient), far past the vertices where g changes sign on the face's
// boundary: no chord was found, and the whole face went to the farther edge, d^2 stepping by
// 2.4e-12 where it is 5.6e-14. The conic itself, a hyperbola centred 5 from T' (the computed
// difference's, which the vertices are roots of), is known there to 2e-11: it is taken where the
// parabolic form would move the curve by more than kVertexTolerance and the central one is a
// hundred times as precise. Oracles: validate() after every insertion and brute force on a grid.
TEST(Degenerate, NoiseEigenvalueOfANearConicIsKept) {
    const TriangleMesh T = make_mesh({{-0.00076837251969463696, 0.00093882159567623387, 6.4140969580335209e-09},
                                      {-0.0015367450393892739, 0.0018776431913524677, 0},
                                      {-0.0022696818389270632, 0.0008577141832594858, 0}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0, 0, 1.2828193916067042e-08},
                                      {0.0022114029347439432, 0.00099841190413861624, 0},
                                      {-0.0019703515397968066, 0.0014159251674224084, 0},
                                      {0, 0, 0}},
                                     {{0, 1, 2}, {3, 2, 1}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-13), 0);
}

// Generate_pairs13.py "ties_cube_center" 4384 (target 7 of A, the paper's order; three of the ten
// sources it had then, inserted in that order, make the same fault): a target 0.07 across at the
// centre of a cube 1660 wide, so d^2 is 1.3e8 in its frame. The third source's face beats the
// first's edge wherever y > 0 (their difference is y (16384 - x), with 3e-16 of noise in x^2 and
// y^2), but the line pair's second line, x = 16384, was moved onto q = 0 at the centre and came out
// as x = 0 (Conic.FarLinePairsOtherLineStaysFarFromT): the sliver the edge still held beside T''s
// edge y = 0 counted as nowhere nearer and kept it, d^2 stepping by 0.0625 at 1.3e8 against the
// face's domain. Oracles: validate() after every insertion and brute force on a grid.
TEST(Degenerate, FarLinePairSplitsTheFaceBesideItsNearLine) {
    const TriangleMesh T = make_mesh({{0, 0, 0},
                                      {-2.6211001680824294e-12, 0.050681270348968153, -0.050681270351340707},
                                      {1.0879075275128357e-12, 0.050681270350154434, -1.1862805828603435e-12}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-6.076838208463282e-08, -1.9436021068279438e-08, -830.36193341693024},
                                      {-4.2944105153862523e-08, 830.36193339749423, -830.36193343636614},
                                      {-830.36193345987431, 830.3619334153185, -830.3619333755978},
                                      {830.36193343475452, 830.36193339910596, -8.0204403153799492e-08},
                                      {1.78242769307703e-08, 830.36193341693024, -1.9436021069583869e-08},
                                      {830.36193337398618, 830.36193337966984, -830.3619334971346},
                                      {1.78242769307703e-08, 830.36193341693024, -1.9436021069583869e-08},
                                      {-4.2944105153862523e-08, 830.36193339749423, -830.36193343636614},
                                      {830.36193337398618, 830.36193337966984, -830.3619334971346}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    insert_all_validating(mesh, fr, S);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-12), 0);
}

// Generate_pairs5.py "coinc_noise_far" 58438 (target 9 of A, the debugger's order; six of its nine
// sources, inserted in that order, make the same fault): a noisy coincident copy 6.6e4 from the
// origin. At T''s corner, where three sources meet, a face's needle 1.26e-5 long and 2.2e-9 wide
// came out folded (its sides crossed), the other domain on both sides. unfold_needles cuts such a
// needle across its base at the foot of its shorter side's end on the longer side, but that foot
// fell 3e-10 past the longer side's end (the side's line runs by its vertex within kOffCurve), and
// the needle was left as it was. The next source's region line runs along it: the split pinched
// the base, the needle became a loop of its own, the line's chord joined it to the rest, and no
// piece was cut: the face, 2e-5 across, kept an edge's quadratic up to 5% above d^2 (2.9e-10)
// where that source's face is nearer. Now a foot past the end, the ends within kVertexTolerance,
// is that end. Oracles: validate() after every insertion of the paper's insertion (as the debugger
// runs it), and brute force on a fine grid at the corner (on both meshes moved by T''s corner,
// which keeps them exact), within the resolution (4e-7 times the gradient).
TEST(Degenerate, FoldedNeedleWhoseFootFallsPastItsLongerSideIsUnfolded) {
    const TriangleMesh T = make_mesh({{66024.720161124205, 1.055852089341107, 0.97033013579797867},
                                      {66025.733709513661, 1.1442500272725102, -1.6412916296919833},
                                      {66023.325536228338, 0.088397937931403256, -2.6116217654899616}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{66023.325639431918, 0.088503395779516186, -2.6118117424670029},
                                      {66025.733730947817, 1.1441766532699507, -1.6413132914155564},
                                      {66026.748024943285, -1.4507652932714203, -1.3353286871935151},
                                      {66022.312166556789, -0.00010769209079488532, 7.6820398628389009e-06},
                                      {66023.325639431918, 0.088503395779516186, -2.6118117424670029},
                                      {66024.339920167986, -2.506433208832235, -2.3056532976063657},
                                      {66022.312166556789, -0.00010769209079488532, 7.6820398628389009e-06},
                                      {66024.720166713814, 1.0559157252099372, 0.97020198459111062},
                                      {66023.325639431918, 0.088503395779516186, -2.6118117424670029},
                                      {66024.720166713814, 1.0559157252099372, 0.97020198459111062},
                                      {66025.733730947817, 1.1441766532699507, -1.6413132914155564},
                                      {66023.325639431918, 0.088503395779516186, -2.6118117424670029},
                                      {66022.312166556789, -0.00010769209079488532, 7.6820398628389009e-06},
                                      {66023.326430677378, -2.5947996040172114, 0.30587828964153507},
                                      {66024.720166713814, 1.0559157252099372, 0.97020198459111062},
                                      {66023.326430677378, -2.5947996040172114, 0.30587828964153507},
                                      {66025.73455963684, -1.5390423269713291, 1.2761846252383726},
                                      {66024.720166713814, 1.0559157252099372, 0.97020198459111062}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    DomainMesh::Listener watch;  // the paper's insertion, every cut reported: the debugger's
    for (uint32_t s = 0; s < S.num_triangles(); ++s) {
        mesh.insert(project_source(fr, S.corners(s), s), {}, &watch);
        EXPECT_EQ(mesh.validate(), "") << "after source " << s;
    }
    const auto c = fr.ccw_corners();
    ASSERT_EQ(c[1].x, 1.0);  // T' is (0, 0), (1, 0), (0.5, 0.5): the fault lay 5e-5 from (1, 0)
    ASSERT_EQ(c[1].y, 0.0);
    const Vec3 o = T.corners(0)[0];
    TargetFrame near = fr;
    near.origin = fr.origin - o;
    const TriangleMesh Sn = shifted(S, -1.0 * o);
    int off = 0, in = 0;
    for (int i = 0; i <= 200; ++i)
        for (int j = 1; j <= 200; ++j) {
            const Vec2 p{0.9999 + 1e-4 * i / 200.0, 1e-4 * j / 200.0};
            const int f = p.x + p.y < 1 ? mesh.face_at(p) : -1;
            if (f <= 0) continue;
            ++in;
            const double q = mesh.faces()[f].poly(p), d2 = brute_d2(near, Sn, p);
            off += std::abs(q - d2) > 1e-7 * d2 + 4e-7 * norm(mesh.faces()[f].poly.gradient(p)) + 1e-15;
        }
    EXPECT_GT(in, 10000);
    EXPECT_EQ(off, 0);
}

// An orphan loop of two needles joined at a waist is cut there, each needle going to the domain
// beside it (DomainMesh::split_orphan_at_waist; generate_pairs4.py "lod_surface" 21658, side B,
// target 3, the debugger's order, after the 9th insertion: the whole loop went to the far side's
// domain, and d^2 stepped by 3.3e-11 at 2.8e-6 along a needle 4e-6 long). Oracle: d^2 by brute
// force at the middle of every arc between two domains, where both domains' quadratics must meet
// it, up to the domain mesh's placement of its vertices (kOffCurve) times their gradients.
TEST(Degenerate, OrphanLoopOfTwoNeedlesIsCutAtItsWaist) {
    const TriangleMesh T = make_mesh({{0.078945240111254644, 0.052906880329141169, 0.031301542223552067},
                                      {0.072602087884097957, 0.048432552679017832, 0.039819275938209553},
                                      {0.079858169853249464, 0.05422496663268439, 0.033590954239641264}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0.075608162007321025, 0.049663665733739572, 0.031087162102680754},
                                      {0.075909355157926628, 0.050106271447265011, 0.031849684966814479},
                                      {0.078340516319176351, 0.052024101526346969, 0.029776035655465438},
                                      {0.078340516319176351, 0.052024101526346969, 0.029776035655465438},
                                      {0.075909355157926628, 0.050106271447265011, 0.031849684966814479},
                                      {0.076211327526701705, 0.050548066229271098, 0.032612361454975307},
                                      {0.078340516319176351, 0.052024101526346969, 0.029776035655465438},
                                      {0.076211327526701705, 0.050548066229271098, 0.032612361454975307},
                                      {0.078642488604684549, 0.052465896395008808, 0.030538712127210078},
                                      {0.078642488604684549, 0.052465896395008808, 0.030538712127210078},
                                      {0.076211327526701705, 0.050548066229271098, 0.032612361454975307},
                                      {0.07651407909803376, 0.050989050096005746, 0.033375191564085221},
                                      {0.078642488604684549, 0.052465896395008808, 0.030538712127210078},
                                      {0.07651407909803376, 0.050989050096005746, 0.033375191564085221},
                                      {0.078945240111254644, 0.052906880329141169, 0.031301542223552067},
                                      {0.078945240111254644, 0.052906880329141169, 0.031301542223552067},
                                      {0.07651407909803376, 0.050989050096005746, 0.033375191564085221},
                                      {0.076817609859780131, 0.051429223060105826, 0.034138175291750263},
                                      {0.078945240111254644, 0.052906880329141169, 0.031301542223552067},
                                      {0.076817609859780131, 0.051429223060105826, 0.034138175291750263},
                                      {0.079248770826743073, 0.053347053341381831, 0.032064525942097293},
                                      {0.07803932327034363, 0.051581495706906601, 0.029013512811396389},
                                      {0.075608162007321025, 0.049663665733739572, 0.031087162102680754},
                                      {0.078340516319176351, 0.052024101526346969, 0.029776035655465438},
                                      {0.07651407909803376, 0.050989050096005746, 0.033375191564085221},
                                      {0.074398915870062962, 0.049498418408883638, 0.036214282524606352},
                                      {0.076817609859780131, 0.051429223060105826, 0.034138175291750263}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}, {21, 22, 23}, {24, 25, 26}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    DomainMesh mesh(fr.ccw_corners());
    DomainMesh::Listener watch;  // the paper's insertion, every cut reported: the debugger's
    for (uint32_t s = 0; s < S.num_triangles(); ++s) {
        mesh.insert(project_source(fr, S.corners(s), s), {}, &watch);
        EXPECT_EQ(mesh.validate(), "") << "after source " << s;
    }
    int arcs = 0;
    EXPECT_EQ(arc_middles_off_d2(mesh, fr, S, arcs), 0);
    EXPECT_GT(arcs, 10);
    EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 300, 1e-9), 0);
}

// A lobe below the resolution, joined to the rest of its face at a neck that the curve crosses,
// wholly on the other side of the curve from the rest, is pinched off and kept on its side
// (DomainMesh::pinched_lobes; generate_pairs15.py "lod_sphere" 4941, side B, target 6, after the 4th
// insertion in the paper's and the debugger's orders: the first source's edge domain ran 0.7 along
// T''s edge, its tip lobe 0.15 long and at most 1e-8 wide by T''s corner (1, 0), joined to the rest
// at a neck 3.7e-12 wide; a line of the 4th source's line pair crossed the neck, and the whole
// face, tip and all, went to the 4th source: 0.0625 in d^2 where the truth is 2.2e-9). Oracles:
// validate() after every insertion, watched and not, and d^2 by brute force at the middle of every
// arc between two domains (the lobe's arcs, 1e-8 wide, hold no grid point) and on a grid over T'.
TEST(Degenerate, LobeAcrossANeckOnTheOtherSideIsPinchedOff) {
    const TriangleMesh T = make_mesh({{1.2824120143208622, -1.30158267196929, 1.873634295617818},
                                      {1.6574361292771798, -1.3748491871043211, 2.196151079636159},
                                      {1.3921890355864446, -1.1503184821183234, 2.555675904230263}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{1.2306850138346019, -1.3701755518278016, 1.5306672859589088},
                                      {1.4166164200871034, -1.4103281857084007, 1.6928987167165017},
                                      {1.2824120143208622, -1.30158267196929, 1.873634295617818},
                                      {1.2306850138346019, -1.3701755518278016, 1.5306672859589088},
                                      {1.2824120143208622, -1.30158267196929, 1.873634295617818},
                                      {1.0964805784147917, -1.2614301041134195, 1.7114028831147718},
                                      {1.0964805784147917, -1.2614301041134195, 1.7114028831147718},
                                      {1.2824120143208622, -1.30158267196929, 1.873634295617818},
                                      {1.1492612969555311, -1.1904910834356006, 2.0537212307030881},
                                      {1.4166164200871034, -1.4103281857084007, 1.6928987167165017},
                                      {1.603601574047653, -1.4481346127449641, 1.8544814671489547},
                                      {1.4693971386278428, -1.3393891650305818, 2.0352170643048177}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}});  // in the order inserted
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    for (bool watched : {false, true}) {
        DomainMesh mesh(fr.ccw_corners());
        DomainMesh::Listener watch;  // the paper's insertion, every cut reported: the debugger's
        for (uint32_t s = 0; s < S.num_triangles(); ++s) {
            mesh.insert(project_source(fr, S.corners(s), s), {}, watched ? &watch : nullptr);
            EXPECT_EQ(mesh.validate(), "") << "after source " << s << (watched ? ", watched" : "");
        }
        int arcs = 0;
        EXPECT_EQ(arc_middles_off_d2(mesh, fr, S, arcs), 0) << (watched ? "watched" : "");
        EXPECT_GT(arcs, 5);
        EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 300, 1e-9), 0);
    }
}


// Generate_pairs15.py "terrain_crack" 4327: a terrain tile with a skirt 0.01 deep hanging from its
// border (A) against B's triangle 23 of a continuous terrain, which coincides with it along that
// border. A skirt triangle nearly perpendicular to T' shares its corner b with two tile triangles
// on T''s edge. Its face region's line along the border is ill-conditioned (the plane through that
// edge perpendicular to the skirt is 8.5e-4 rad from T'): it crosses T''s edge 6.7e-7 from b. In
// the debugger's order the skirt's face domain ends in a sliver 6e-12 wide along T''s edge that
// reaches b, and interior_point's probe lay there: 6.7e-7 outside the label's region, 4e-10 inside
// the neighbour's, and validate() called the label wrong. A sliver thinner than kTinyChord may go
// to either side (the whole-face sliver rule): within kTinyChord of its boundary validate() now
// also takes a neighbour's label. Oracles: validate() after every insertion in the three orders;
// at every probe beyond its label's region, the feature nearest by brute force, whose squared
// distance is the face's polynomial to the rounding; d^2 by brute force at every arc's middle and
// on a grid. (Since the differences that are squares to the operands' rounding are taken as such,
// double_line_sign, the skirt's domains no longer end in that sliver: no probe lies beyond its
// label's region here now, which the test asserts; the checks for such probes stay for a change
// that brings the sliver back.)
TEST(Degenerate, ProbeInATinySliverMayLieInTheNeighboursRegion) {
    const TriangleMesh A = make_mesh(
        {{8.0, 2.5, 1.0000633196212387}, {8.0, 2.625, 1.0000804559864218}, {8.0, 2.75, 0.9998356955058298},
         {8.124999092329809, 2.5, 1.0001103409257561}, {8.124999092329809, 2.625, 0.9999649990745814},
         {8.124999092329809, 2.75, 0.9998227260927531}, {8.249998184659617, 2.5, 1.0000941247230688},
         {8.249998184659617, 2.625, 0.9998731089995309}, {8.249998184659617, 2.75, 0.9999113688507376},
         {8.249998184659617, 2.5, 0.9898614607545015}, {8.249998184659617, 2.625, 0.9896404450309637},
         {8.249998184659617, 2.75, 0.9896787048821704}, {8.250001815340383, 2.5, 1.000094123472355},
         {8.250001815340383, 2.5833333333333335, 0.9999496341510222}, {8.250001815340383, 2.6666666666666665, 0.9998336184105459},
         {8.250001815340383, 2.75, 0.9999113723376621}, {8.333334543560255, 2.5, 1.0000546739882439},
         {8.333334543560255, 2.5833333333333335, 0.9998942709121781}, {8.333334543560255, 2.6666666666666665, 0.9998507935813645},
         {8.333334543560255, 2.75, 0.999995028433169}, {8.416667271780128, 2.5, 0.9999961636587429},
         {8.416667271780128, 2.5833333333333335, 0.9998577816771111}, {8.416667271780128, 2.6666666666666665, 0.9998971519801192},
         {8.416667271780128, 2.75, 1.0000730626370773}, {8.5, 2.5, 0.999928681088042},
         {8.5, 2.5833333333333335, 0.9998489332443766}, {8.5, 2.6666666666666665, 0.9999650924813875},
         {8.5, 2.75, 1.0001333798035636}, {8.250001815340383, 2.5, 0.9898614595037878},
         {8.250001815340383, 2.5833333333333335, 0.9897169701824551}, {8.250001815340383, 2.6666666666666665, 0.9896009544419786},
         {8.250001815340383, 2.75, 0.9896787083690949}},
        {{0, 3, 1},    {3, 4, 1},    {1, 4, 2},    {4, 5, 2},    {3, 6, 4},    {6, 7, 4},    {4, 7, 5},    {7, 8, 5},
         {6, 7, 10},   {6, 10, 9},   {7, 8, 11},   {7, 11, 10},  {12, 16, 17}, {12, 17, 13}, {13, 17, 18}, {13, 18, 14},
         {14, 18, 15}, {18, 19, 15}, {16, 20, 17}, {20, 21, 17}, {17, 21, 22}, {17, 22, 18}, {18, 22, 23}, {18, 23, 19},
         {20, 24, 25}, {20, 25, 21}, {21, 25, 22}, {25, 26, 22}, {22, 26, 27}, {22, 27, 23}, {12, 13, 29}, {12, 29, 28},
         {13, 14, 30}, {13, 30, 29}, {14, 15, 31}, {14, 31, 30}});
    const TriangleMesh T = make_mesh({{8.25, 2.6666666666666665, 0.9998336184208956},
                                      {8.333333333333334, 2.75, 0.9999950272186962},
                                      {8.25, 2.75, 0.9999113705941962}},
                                     {{0, 1, 2}});
    int beyond = 0;  // probes beyond their label's region by more than validate()'s rim allowance
    expect_constructions_hold(T, A, [&](const TargetSolver& ts) {
        const DomainMesh& m = *ts.domain_mesh();
        const TargetFrame& fr = ts.frame();
        for (size_t f = 1; f < m.faces().size(); ++f) {
            const DomainMesh::Face& F = m.faces()[f];
            Vec2 p;
            if (!F.alive || F.infinite || !m.interior_point((int)f, p)) continue;
            const SourceProjection own = project_source(fr, A.corners(F.label.source), F.label.source);
            double margin = HUGE_VAL;
            for (const SourceRegion& r : own.regions)
                if (r.kind == F.label.region) margin = region_margin(r, p, false);
            if (margin >= -4 * DomainMesh::kVertexTolerance) continue;
            ++beyond;
            EXPECT_TRUE(m.near_boundary((int)f, p, DomainMesh::kTinyChord)) << "face " << f;
            // The nearest feature by brute force is another one, as near as the label's quadratic
            // says to the frame's rounding (its coefficients are about 0.5, rounded to 1e-16).
            NearestFeature best;
            for (uint32_t s = 0; s < A.num_triangles(); ++s) {
                const std::array<Vec3, 3> c = source_in_frame(fr, A.corners(s));
                const NearestFeature nf = nearest_feature(Vec3(p.x, p.y, 0), c[0], c[1], c[2]);
                if (nf.d2 < best.d2) best = nf;
            }
            EXPECT_NEAR(F.poly(p), best.d2, 1e-15) << "face " << f;
            EXPECT_NEAR(brute_d2(fr, A, p), best.d2, 1e-15) << "face " << f;
        }
        int arcs = 0;
        EXPECT_EQ(arc_middles_off_d2(m, fr, A, arcs), 0);
        EXPECT_EQ(grid_points_off_d2(m, fr, A, 300, 1e-9), 0);
    });
    EXPECT_EQ(beyond, 0);  // the sliver is gone: every probe lies in its label's region (before, some did not)
}

// Generate_pairs15.py "lod_sphere" 6858 (side B, target 0, nearest first; three of A's triangles):
// a square's half against a sphere's patch of radius 4.9e8, both flat to 5e-10. A source's edge
// region line runs 2.7e-10 inside T''s edge along a domain's side of it, and the boundary between
// the chord's ends passes a conic's tip 1.5e-7 outside T', a little beyond what hugging allows.
// The chord was inserted; the piece it cut off, of no area to the rounding, came out inside out (a
// hole of the face), and the next split, by the bisector of two parallel edges, met the chord
// instead of T''s edge and gave that sliver whole to one side: d^2 0.01125 beside 0.00125 along
// T''s edge. Now no chord is made whose piece beyond is thinner than kTinyChord and within twice
// kCluster of it (DomainMesh::thin_beyond_chord). Oracles: validate() after every insertion in the
// three orders; d^2 by brute force at every arc's middle and on a grid.
TEST(Degenerate, NoChordCutsOffAPieceOfNoArea) {
    const TriangleMesh T = make_mesh({{-3.75, -2.5000000005070917, 0.75}, {-3.75, -2.5000000005070917, 1.75},
                                      {-2.75, -2.5000000005070917, 0.75}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-2.9500000000000002, -2.5000000003448224, 0.75},
                                      {-2.9500000000756308, -2.5000000001825531, 0.95000000044553023},
                                      {-2.75, -2.5000000005070917, 0.75},
                                      {-3.5499999999999998, -2.5000000003448224, 0.75},
                                      {-3.3499999995128218, -2.5000000001014184, 0.95000000001058571},
                                      {-3.3500000000000001, -2.5000000002636877, 0.75},
                                      {-3.1499999999999999, -2.5000000002636877, 0.75},
                                      {-3.1499999994504058, -2.5000000001014184, 0.95000000042202204},
                                      {-2.9500000000000002, -2.5000000003448224, 0.75}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    expect_constructions_hold(T, S, [&](const TargetSolver& ts) {
        int arcs = 0;
        EXPECT_EQ(arc_middles_off_d2(*ts.domain_mesh(), ts.frame(), S, arcs), 0);
        EXPECT_GT(arcs, 3);
        EXPECT_EQ(grid_points_off_d2(ts, S, 300, 1e-9), 0);
    }, true);
}

// Generate_pairs15.py "float32_far" 3640 (B's target 15 and three of A's triangles; the paper's
// order and nearest first): a torus and its jittered copy, rounded to float32, 2906 from the
// origin. A strip of the first source's edge domain along T''s edge ends in a sliver 8e-13 wide
// at T''s corner, too thin for any chord (kTinyChord); the third source, a plane, is nearer over
// its last 4e-7 (5.5e-13 of T''s size squared where the edge's polynomial is 2.2e-12), and the
// probe beside the sliver's 1e-12 arc at the corner lay there. Not a fault of
// the construction's resolution (a sliver that thin goes to either side): within kTinyChord of its
// face's boundary, validate() now takes a neighbour's polynomial as it takes a neighbour's label.
// Oracles: at every probe whose polynomial misses d^2 by brute force (in coordinates moved by
// T''s corner) beyond the rim allowance, found and counted: the probe within kTinyChord of its
// boundary, a neighbour there whose polynomial is d^2, and on a lattice 1e-9 apart within 1e-6 of
// it every point of the face where the polynomial misses d^2 within kTinyChord of its boundary
// (the part that misses is a sliver 8e-13 wide and 4e-7 long).
TEST(Degenerate, SliverEndThinnerThanATinyChordMayHoldTheNeighboursPolynomial) {
    const TriangleMesh T = make_mesh({{4.9040770530700684, 2906.44921875, 0.60072481632232666},
                                      {4.8081531524658203, 2906.282958984375, 0.39927482604980469},
                                      {4.9040770530700684, 2906.44921875, 0.3992750346660614}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{4.9040765762329102, 2906.44921875, 0.60072499513626099},
                                      {4.8081536293029785, 2906.282958984375, 0.3992750346660614},
                                      {4.9040765762329102, 2906.44921875, 0.3992750346660614},
                                      {4.9040765762329102, 2906.44921875, 0.3992750346660614},
                                      {4.8081536293029785, 2906.282958984375, 0.3992750346660614},
                                      {4.8168463706970215, 2906.60009765625, 0.5},
                                      {5.0959234237670898, 2906.44921875, 0.60072499513626099},
                                      {4.9040765762329102, 2906.44921875, 0.3992750346660614},
                                      {5.0959234237670898, 2906.44921875, 0.3992750346660614}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    const Vec3 o = T.corners(0)[0];
    const TriangleMesh Sn = shifted(S, -1.0 * o);
    int missed = 0;          // probes whose polynomial misses d^2 beyond the rim allowance
    int lattice_misses = 0;  // lattice points that do (the sliver is 8e-13 wide: a few fall in it)
    expect_constructions_hold(T, S, [&](const TargetSolver& ts) {
        const DomainMesh& m = *ts.domain_mesh();
        const TargetFrame near = TargetFrame::make(shifted(T, -1.0 * o).corners(0));
        ASSERT_EQ(near.scale, ts.frame().scale);
        auto d2_at = [&](Vec2 p) { return brute_d2(near, Sn, p); };
        auto allowance = [&](const DomainMesh::Face& F, Vec2 p, double d2) {
            return (norm(F.poly.gradient(p)) + 2 * std::sqrt(d2)) * 2 * DomainMesh::kVertexTolerance + 1e-3 * d2;
        };
        for (size_t f = 1; f < m.faces().size(); ++f) {
            const DomainMesh::Face& F = m.faces()[f];
            Vec2 p;
            if (!F.alive || F.infinite || !m.interior_point((int)f, p)) continue;
            const double d2 = d2_at(p);
            if (std::fabs(F.poly(p) - d2) <= allowance(F, p, d2)) continue;
            ++missed;
            EXPECT_TRUE(m.near_boundary((int)f, p, DomainMesh::kTinyChord)) << "face " << f;
            int neighbours = 0;
            for (size_t g = 1; g < m.faces().size(); ++g)
                if (g != f && m.faces()[g].alive && !m.faces()[g].infinite && m.near_boundary((int)g, p, DomainMesh::kTinyChord))
                    neighbours += std::fabs(m.faces()[g].poly(p) - d2) <= 1e-3 * d2;
            EXPECT_GT(neighbours, 0) << "face " << f;
            int off = 0;  // lattice points of the face that miss d^2 farther than kTinyChord inside it
            for (int j = -1000; j <= 1000; ++j)
                for (int i = -1000; i <= 1000; ++i) {
                    const Vec2 q{p.x + i * 1e-9, p.y + j * 1e-9};
                    if (!m.point_in_face((int)f, q)) continue;
                    const double e2 = d2_at(q);
                    if (std::fabs(F.poly(q) - e2) <= allowance(F, q, e2)) continue;
                    ++lattice_misses;
                    off += !m.near_boundary((int)f, q, DomainMesh::kTinyChord);
                }
            EXPECT_EQ(off, 0) << "face " << f;
        }
    });
    EXPECT_GT(missed, 0);  // the case is there
    EXPECT_GT(lattice_misses, 0);
}

// T' (T's one triangle) and S's triangles, in order, into a bare domain mesh, unwatched and
// watched (the paper's insertion, every cut reported: the debugger's): validate() and
// after_each(mesh, frame, s, label) after the insertion of source s, then check(mesh, frame,
// label) on the result.
template <class Check, class AfterEach>
void insert_into_bare_mesh(const TriangleMesh& T, const TriangleMesh& S, Check check, AfterEach after_each) {
    const TargetFrame fr = TargetFrame::make(T.corners(0));
    for (bool watched : {false, true}) {
        DomainMesh mesh(fr.ccw_corners());
        DomainMesh::Listener watch;
        const char* label = watched ? "watched" : "unwatched";
        for (uint32_t s = 0; s < S.num_triangles(); ++s) {
            mesh.insert(project_source(fr, S.corners(s), s), {}, watched ? &watch : nullptr);
            EXPECT_EQ(mesh.validate(), "") << "after source " << s << ", " << label;
            after_each(mesh, fr, s, label);
        }
        check(mesh, fr, label);
    }
}
template <class Check>
void insert_into_bare_mesh(const TriangleMesh& T, const TriangleMesh& S, Check check) {
    insert_into_bare_mesh(T, S, check, [](const DomainMesh&, const TargetFrame&, uint32_t, const char*) {});
}

// A curved chord within kCluster of the face's boundary, but the boundary certainly on one side of
// it all along (every arc farther from the curve than the rounding allows, the farthest a quarter
// of kCluster): a real sliver, cut off, not dropped as hugging the boundary
// (DomainMesh::real_sliver_beside_chord). Two boxes' edges 1.1e-7 apart: the nearer won the farther
// one's domain whole and its arc with a third edge's domain stayed on the old curve, 8.5e-8 off;
// the third's chord along it was dropped, and the sliver between kept the third's quadratic, up to
// 2e-8 above d^2; a plane parallel to T' then took part of it and stepped d^2 by 1.2e-8 at its arc
// (generate_pairs15.py "box_union" 2061, side B, target 14, the 10th and 11th insertions, the
// paper's and the debugger's orders). validate() after each insertion (without the change, "d^2
// jumps by 1.17759e-08" after the 11th); oracle: brute force on a grid 1e-8 apart round the sliver
// from the 10th insertion, every point's domain within 1e-11 of d^2 (without the change 1811 points
// are off, by up to 2e-8), and on a grid over T'.
TEST(Degenerate, CurvedChordBesideTheBoundaryCutsOffARealSliver) {
    const TriangleMesh T = make_mesh({{0.024378926926138328, 1.1054089375915526, -1.1830663233268492},
                                      {-0.055172724400882556, 0.95528927508161565, -0.84876014375631426},
                                      {1.0014238161040061, 1.000307778717177, -0.99776378439477842}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0.021939458365555803, 0.99161795121738017, -1.2347444832870158},
                                      {0.26620068066002273, 0.96534266149878623, -1.1884188485539982},
                                      {0.26864014922060525, 1.0791336478729587, -1.1367406885938314},
                                      {0.021939458365555803, 0.99161795121738017, -1.2347444832870158},
                                      {0.26864014922060525, 1.0791336478729587, -1.1367406885938314},
                                      {0.024378926926138328, 1.1054089375915526, -1.1830663233268492},
                                      {0.021939458365555803, 0.99161795121738017, -1.2347444832870158},
                                      {0.024378926926138328, 1.1054089375915526, -1.1830663233268492},
                                      {-0.055172724400882556, 0.95528927508161565, -0.84876014375631426},
                                      {0.021939458365555803, 0.99161795121738017, -1.2347444832870158},
                                      {-0.055172724400882556, 0.95528927508161565, -0.84876014375631426},
                                      {-0.057612192961465081, 0.84149828870744314, -0.90043830371648093},
                                      {0.021939458365555803, 0.99161795121738017, -1.2347444832870158},
                                      {-0.057612192961465081, 0.84149828870744314, -0.90043830371648093},
                                      {0.26620068066002273, 0.96534266149878623, -1.1884188485539982},
                                      {-0.057612192961465081, 0.84149828870744314, -0.90043830371648093},
                                      {0.18664902933300187, 0.81522299898884909, -0.85411266898346327},
                                      {0.26620068066002273, 0.96534266149878623, -1.1884188485539982},
                                      {0.024378926926138328, 1.1054089375915526, -1.1830663233268492},
                                      {-0.055172724400882556, 0.95528927508161565, -0.84876014375631426},
                                      {0.18908849789358442, 0.92901398536302171, -0.80243450902329649},
                                      {0.024378926926138328, 1.1054089375915526, -1.1830663233268492},
                                      {0.18908849789358442, 0.92901398536302171, -0.80243450902329649},
                                      {0.26864014922060525, 1.0791336478729587, -1.1367406885938314},
                                      {0.2662006784589348, 0.96534255882725695, -1.1884188951822583},
                                      {0.87685373419510215, 0.89965433453077215, -1.0726048083497142},
                                      {0.87685373639619013, 0.89965443720230132, -1.072604761721454},
                                      {0.2662006784589348, 0.96534255882725695, -1.1884188951822583},
                                      {0.87685373639619013, 0.89965443720230132, -1.072604761721454},
                                      {0.26620068066002273, 0.96534266149878623, -1.1884188485539982},
                                      {0.2662006784589348, 0.96534255882725695, -1.1884188951822583},
                                      {0.79730208286808124, 0.74953467202083501, -0.73829862877917918},
                                      {0.87685373419510215, 0.89965433453077215, -1.0726048083497142}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}, {21, 22, 23}, {24, 25, 26}, {27, 28, 29}, {30, 31, 32}});  // in the order inserted
    auto sliver_window = [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
        if (s < 9) return;  // the sliver is there from the 10th insertion
        int in = 0, off = 0;
        for (int i = -100; i <= 100; ++i)
            for (int j = -100; j <= 100; ++j) {
                const Vec2 p{0.452015 + 1e-8 * i, 0.205373 + 1e-8 * j};  // the sliver's arc runs through it
                double poly, d2;
                if (!polynomial_and_d2(mesh, fr, S, p, poly, d2)) continue;
                ++in;
                off += std::abs(poly - d2) > 1e-11;
            }
        EXPECT_GT(in, 30000);
        EXPECT_EQ(off, 0) << "after source " << s << ", " << label;
    };
    insert_into_bare_mesh(
        T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) { EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0) << label; },
        sliver_window);
}

// A lens 2.5e-8 wide (a conic arc and a short bridge edge) touching a face's outer loop at a
// vertex, where a line pair's bisector chord starts: the lens's wedge there, by its tangents, spans
// 5.5 rad and took the chord, which left the outer loop 0.004 rad outside its own wedge; the chord
// joined the lens instead of cutting the face, and a domain where the in-plane source's edge is
// nearer kept the farther one (generate_pairs15.py "box_union" 9594, side B, target 23, the 17th
// insertion; reduced to 4 of its sources). validate() after each insertion (without the change,
// "d^2 jumps by 0.00626173" after the last); oracle: brute force over the four sources on a grid
// over T' (checked to fail without the change).
TEST(Degenerate, ThinLoopsWedgeDoesNotTakeAChordFromTheOuterLoop) {
    const TriangleMesh T = make_mesh({{1.9485026980406461, 1.072618553363021, -1.6915787093389973},
                                      {2.4150721124325267, 2.1024481677302727, -1.204353028509408},
                                      {1.915498399633636, 2.095160193610959, -1.223663855710992}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{1.9485026152449172, 1.072618552155165, -1.6915787125394341},
                                      {1.9228326053727982, 1.86792871679245, -1.32764493749543},
                                      {1.9339817474356948, 0.8642671389541703, -1.237289341086375},
                                      {1.926462822325104, 1.9200165700926988, -1.4412172803586947},
                                      {1.9228326053727982, 1.86792871679245, -1.32764493749543},
                                      {1.9228326881685274, 1.8679287180003061, -1.3276449342949932},
                                      {1.926462822325104, 1.9200165700926988, -1.4412172803586947},
                                      {1.9228326881685274, 1.8679287180003061, -1.3276449342949932},
                                      {1.9264629051208328, 1.9200165713005548, -1.441217277158258},
                                      {1.9228326881685274, 1.8679287180003061, -1.3276449342949932},
                                      {2.422406400967418, 1.8752166921196198, -1.3083341070934091},
                                      {2.4150721124325267, 2.1024481677302727, -1.204353028509408}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}});  // in the order inserted
    insert_into_bare_mesh(T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) {
        EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0) << label;
    });
}

// Three features within 3.2e-10 of each other in d^2 (T' at y = 0.125 over a plane at y = -1.2e-9
// and two box edges at y = 0, one of them meeting the plane's edge): the plane's domain keeps a
// sliver narrower than a vertex's placement on a curve (1e-8) along an edge's arc, where the other
// edge is nearer by 1.2e-10 (generate_pairs15.py "box_union" 10323, side B, target 18, the 45th
// insertion in the debugger's order; reduced to 7 of its sources). validate() passes after each
// insertion (without the change, "d^2 jumps by 1.20033e-10" after the last: checked); oracle: brute
// force along the normal through that arc's middle, the polynomial off d^2 by at most the tie (the
// plane's distance squared less the edges', 3.2e-10 in the frame) and nowhere farther than 1e-8 from
// the arc, and on a grid over T'.
TEST(Degenerate, SliverBelowTheVertexPlacementIsNotAStepInDistance) {
    const double n = -1.210678076508848e-09, top = 0.7499999999818029;
    const TriangleMesh T = make_mesh({{0, 0.125, 0.125}, {0, 0.125, top}, {0.75, 0.125, 0.125}}, {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0, 0.125, 0.125},   {0, 0.375, 0.125}, {0, 0.125, top},       {0, 0.125, 0},
                                      {0.375, 0.125, 0},   {0, 0.375, 0},     {0.375, 0, 0},         {0.375, 0.125, 0},
                                      {0.375, 0, 0.125},   {0.375, 0.125, 0.125}, {0.75, 0.125, top}, {0.75, 0.125, 0.125},
                                      {0, n, 0.125},       {0.375, n, 0.125}, {0.375, 0, 0.125},     {0, 0, 0},
                                      {0, 0, 0.125},       {0.375, 0, 0.125}, {0, n, 0.125},         {0, n, top},
                                      {0.375, n, 0.125}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}, {15, 16, 17}, {18, 19, 20}});
    insert_into_bare_mesh(T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) {
        const double tie = ((0.125 - n) * (0.125 - n) - 0.125 * 0.125) / (fr.scale * fr.scale) * (1 + 1e-6);  // plane less edge
        // The arcs between two domains whose quadratics differ at the middle by more than 1e-11:
        // probe d^2 by brute force along the normal there, 1e-10 to 1e-5 away on either side.
        int steps = 0;
        for (size_t e = 0; e < mesh.edges().size(); ++e) {
            const DomainMesh::Edge& E = mesh.edges()[e];
            const int F = mesh.half_edges()[2 * e].face, G = mesh.half_edges()[2 * e + 1].face;
            if (!E.alive || F <= 0 || G <= 0) continue;
            const double zm = 0.5 * (E.z0 + E.z1);
            const Vec2 m = E.curve(zm);
            if (std::abs(mesh.faces()[F].poly(m) - mesh.faces()[G].poly(m)) <= 1e-11) continue;
            ++steps;
            const Vec2 t = E.curve(zm + 1e-6 * (E.z1 - E.z0)) - E.curve(zm - 1e-6 * (E.z1 - E.z0));
            const Vec2 nrm = Vec2{-t.y, t.x} * (1 / norm(t));
            for (double side : {-1.0, 1.0})
                for (double d = 1e-10; d < 2e-5; d *= 10) {
                    double poly, d2;
                    ASSERT_TRUE(polynomial_and_d2(mesh, fr, S, m + nrm * (side * d), poly, d2));
                    EXPECT_LE(std::abs(poly - d2), tie) << label << ", edge " << e << " at " << side * d;
                    if (d >= 1e-8) {
                        EXPECT_LE(std::abs(poly - d2), 1e-14) << label << ", edge " << e << " at " << side * d;
                    }
                }
        }
        EXPECT_GE(steps, 1) << "the sliver's arc is gone: the test no longer tests the allowance";
        EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0) << label;
    });
}

// A corner's quadratic less that of another source's edge through that corner is a square,
// ((p - c) . u)^2 for the edge's direction u: the two tie on one line, and the edge is nearer
// elsewhere. With the edge nearly perpendicular to T' (its direction 0.0097 in T''s plane) the
// square's coefficients are 1e-4 of the quadratics', and their rounding, scaled up by as much, made
// a parabola whose chord ran out along the line, round a tip 0.002 outside T' and back 1e-7 away;
// the next source's region line crossed that hairpin three times within 2.6e-7 and cut nothing,
// so its corner region took its edge region's place (generate_pairs17.py "terrain_far" 4375, side
// A, target 7, the 5th insertion in the paper's and the debugger's orders; reduced to 3 sources).
// validate() after each insertion; oracle: brute force on a grid over T' (without the change,
// d^2 up to 0.02 high over 14% of T': checked).
TEST(Degenerate, CornerLessAnEdgeThroughItIsASquareNotAHairpin) {
    const TriangleMesh T = make_mesh({{327.79998779296875, 408211.34375, 30.731250762939453},
                                      {327.79998779296875, 407883.53125, -30.731250762939453},
                                      {327.79998779296875, 408211.34375, 0.0}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{218.53334045410156, 407930.375, 0.07308710366487503},
                                      {327.79998779296875, 407930.375, 0.48926103115081787},
                                      {327.79998779296875, 407977.1875, 2.159552574157715},
                                      {218.53334045410156, 407930.375, 0.07308710366487503},
                                      {327.79998779296875, 407977.1875, 2.159552574157715},
                                      {218.53334045410156, 407977.1875, 3.217957019805908},
                                      {218.53334045410156, 408024.03125, 13.457244873046875},
                                      {327.79998779296875, 408024.03125, 6.780330181121826},
                                      {327.79998779296875, 408070.84375, 15.359222412109375}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});  // in the order inserted
    insert_into_bare_mesh(T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) {
        EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0) << label;
    });
}

// A needle of a face folded outside it, its tip not a vertex but a tiny arc: two region lines
// through a source corner, 6e-4 rad apart, run 2.8e-6 from a conic that crosses both 3.7e-9 apart;
// the face's loop went down one line, across the conic and up the other, so its quadratic (a
// plane's, which another source's edge undercuts there by 1.5e-11, 2% of d^2) bounded a sliver
// that its two neighbours covered (generate_pairs16.py "fillet_strip" 4121, B's target 22, the
// debugger's order; reduced to 3 sources). And the same with one side along T''s edge, the needle
// 3.6e-9 outside T' (B's target 33; 4 sources): the face inside gives it up. validate() after each
// insertion (without the change, "d^2 jumps by 1.52378e-11" and "by 2.92572e-11" after the last);
// oracle: at every arc's middle both domains' quadratics are d^2 by brute force, within 1e-8 (the
// precision of a split's vertices) times their gradients and 1e-12 (checked to fail without the
// change), and on a grid over T'.
TEST(Degenerate, NeedleWithATinyArcForItsTipIsUnfolded) {
    const TriangleMesh strip = make_mesh({{0.0, 0.0008751318726591649, 0.0023078013381257157},
                                          {1.5117442404451906, 0.0008751318726591649, 0.0023078013381257157},
                                          {1.5117442404451906, 0.0015209137922920614, 0.0015209137922920606},
                                          {0.0, 0.0003952726162398477, 0.003205554863065362},
                                          {1.5117442404451906, 0.0003952726162398477, 0.003205554863065362}},
                                         {{0, 1, 2}, {0, 3, 1}, {3, 4, 1}});  // in the order inserted
    const TriangleMesh end = make_mesh({{1.5117442404451906, 0.003205554863065362, 0.0003952726162398477},
                                        {1.5117442404451906, 0.002307801338125716, 0.0008751318726591649},
                                        {3.0234884808903812, 0.003205554863065362, 0.0003952726162398477},
                                        {3.0234884808903812, 0.002307801338125716, 0.0008751318726591649},
                                        {1.5117442404451906, 0.0015209137922920614, 0.0015209137922920606},
                                        {3.0234884808903812, 0.0015209137922920614, 0.0015209137922920606}},
                                       {{0, 1, 2}, {1, 3, 2}, {1, 4, 3}, {4, 5, 3}});
    const TriangleMesh T22 = make_mesh({{1.007829493630127, 0.0009917221317900776, 0.0021405176183811824},
                                        {1.007829493630127, 0.00025415002679503394, 0.0035880843802120026},
                                        {2.015658987260254, 0.0009917221317900776, 0.0021405176183811824}},
                                       {{0, 1, 2}});
    const TriangleMesh T33 = make_mesh({{2.015658987260254, 0.003588084380212003, 0.00025415002679503394},
                                        {3.023488480890381, 0.0021405176183811824, 0.0009917221317900776},
                                        {3.023488480890381, 0.003588084380212003, 0.00025415002679503394}},
                                       {{0, 1, 2}});
    for (const auto& [T, S] : {std::pair{&T22, &strip}, std::pair{&T33, &end}})
        insert_into_bare_mesh(*T, *S, [&, S = S](const DomainMesh& mesh, const TargetFrame& fr, const char* label) {
            int arcs = 0;
            EXPECT_EQ(arc_middles_off_d2(mesh, fr, *S, arcs, 1e-8), 0) << label;
            EXPECT_GT(arcs, 3) << label;
            EXPECT_EQ(grid_points_off_d2(mesh, fr, *S, 200, 1e-9), 0) << label;
        });
}

// A region thinner than kCluster (DomainMesh::thin_region_reaches): the lean insertion defers to the
// paper's. A source 3e-8 across stands on T' near its corner, another 7e-5 from it; the first's
// edge region is a strip 3.7e-8 wide, and where a cut by its corner region (whose line is the
// strip's far side) left a sliver of it 1.8e-8 to 3.7e-8 wide and 7e-4 long, joined to the corner
// region the lean insertion passed over as nowhere nearer, the strip's cut dropped its chord as
// hugging the boundary; the sliver kept the far source, 3% above d^2 (generate_pairs9.py
// "perp_corner_tiny" 6680, B's target 1, the paper's order, the 5th insertion; reduced to 3 of its
// sources, unwatched; the paper's insertion cuts the passed-over region along the same line first
// and gets it right). validate() after each insertion (without the change, "d^2 jumps by
// 3.94799e-09" after the third); oracle: brute force on a window round the sliver, 1e-9 across and
// 3.4e-6 along, every point's domain within 1e-12 of d^2 (2181 points off without the change), and
// on a grid over T'.
TEST(Degenerate, LeanInsertionDefersToThePaperWhereARegionIsThin) {
    const TriangleMesh T = make_mesh({{65674.602787029609, -11157.415957116911, -27330.992003479569},
                                      {65674.314305587119, -11157.691286244735, -27330.974283339016},
                                      {65674.572732895715, -11157.359111899535, -27330.598040226243}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{65674.320348258305, -11157.685519068255, -27330.974654513611},
                                      {65674.320348258305, -11157.685519068255, -27330.974654513611},
                                      {65674.32034825829, -11157.685519068298, -27330.974654513626},
                                      {65674.602786943549, -11157.415956958119, -27330.99200236984},
                                      {65674.602786943549, -11157.415956958112, -27330.99200236984},
                                      {65674.602786943549, -11157.415956958115, -27330.99200236984},
                                      {65674.602757072629, -11157.415985707368, -27330.992001639763},
                                      {65674.602757089946, -11157.415985702479, -27330.992001639155},
                                      {65674.602757077184, -11157.415985690086, -27330.992001641916}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});  // in the order inserted
    auto sliver_window = [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
        if (s < 2) return;
        // From near one end of the sliver to near the other, across it and both its sides.
        const Vec2 a{0.500200474262, 0.499695933601}, b{0.500888859050, 0.499008233466}, n{0.706765352, 0.707448046};
        int in = 0, off = 0;
        for (int i = 1; i < 200; ++i)
            for (int k = -30; k <= 50; ++k) {
                const Vec2 p = a + (b - a) * (0.005 * i) + n * (1e-9 * k);
                double poly, d2;
                if (!polynomial_and_d2(mesh, fr, S, p, poly, d2)) continue;
                ++in;
                off += std::abs(poly - d2) > 1e-12;
            }
        EXPECT_GT(in, 15000);
        EXPECT_EQ(off, 0) << "after source " << s << ", " << label;
    };
    insert_into_bare_mesh(
        T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) { EXPECT_EQ(grid_points_off_d2(mesh, fr, S, 200, 1e-9), 0) << label; },
        sliver_window);
}

// Points of T' lying in more than one domain, or in none, on an n x n barycentric grid, but for
// those within `margin` of some domain's boundary: the domains tile T' (an oracle independent of
// validate(): each face's own point-in-face test, its loops as they are).
int grid_points_not_tiled(const DomainMesh& mesh, const TargetFrame& fr, int n, double margin) {
    int off = 0;
    for_each_grid_point(fr, n, [&](Vec2 p) {
        int in = 0;
        bool near = false;
        for (size_t f = 1; f < mesh.faces().size(); ++f) {
            if (!mesh.faces()[f].alive) continue;
            near = near || mesh.near_boundary((int)f, p, margin);
            in += mesh.point_in_face((int)f, p);
        }
        off += !near && in != 1;
    });
    return off;
}

// A hole's test point on an arc it shares with another loop of the face being rebuilt lies on that
// loop too (DomainMesh::rebuild_faces). A target a few ulps across (1e-14) among point-like sources
// (generate_pairs9.py "pointlike_tiny_mesh" 8009, B's target 5, nearest first; reduced to 3 of A's
// faces): the second source's domain is a lens, a hole of the first's; the third's chord, from the
// hole round it and back, cut off a crescent, and the rest of the hole, whose longest arc was a piece
// of that chord, went to the crescent: the first source's domain lost its hole, and the lens's two
// pieces became a face turned inside out over another (validate(): "negative area -4.7122e-05"
// without the change). Oracle: on a grid over T', every point away from the domains' boundaries
// lies in exactly one domain (without the change, the points of the lens lie in three).
TEST(Degenerate, HoleWhoseLongestArcIsAChordGoesToTheFaceAroundIt) {
    const TriangleMesh T = make_mesh({{2.4112529333481203, -22.609394900390409, 8.1366046948539683},
                                      {2.4112529333443651, -22.609394900389702, 8.136604694849666},
                                      {2.411252933342102, -22.609394900391127, 8.1366046948507389}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{2.4112532427846465, -22.609393771878921, 8.1366053358725505},
                                      {2.411252259836532, -22.609394266661035, 8.1366039149130369},
                                      {2.4112531502939274, -22.609395504288205, 8.1366048664837844},
                                      {2.4112529333446635, -22.609394900390768, 8.1366046948511226},
                                      {2.4112529333446635, -22.609394900390768, 8.1366046948511226},
                                      {2.411252933344664, -22.609394900390768, 8.1366046948511244},
                                      {2.4112529333446635, -22.609394900390768, 8.1366046948511226},
                                      {2.4112529333446622, -22.609394900390768, 8.1366046948511208},
                                      {2.4112529333446626, -22.609394900390768, 8.1366046948511226}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});  // in the order inserted
    int lens_points = 0;  // grid points in the second source's lens after its insertion (6e-4 of T')
    insert_into_bare_mesh(
        T, S, [&](const DomainMesh& mesh, const TargetFrame& fr, const char* label) { EXPECT_EQ(grid_points_not_tiled(mesh, fr, 500, 1e-9), 0) << label; },
        [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
            EXPECT_EQ(grid_points_not_tiled(mesh, fr, 500, 1e-9), 0) << "after source " << s << ", " << label;
            if (s != 1) return;
            for_each_grid_point(fr, 500, [&](Vec2 p) {
                const int f = mesh.face_at(p);
                lens_points += f > 0 && mesh.faces()[f].label.source == 1;
            });
        });
    EXPECT_GT(lens_points, 20);  // the case is there (twice: unwatched and watched)
}

// A crossing of a region line with an arc, polished onto both curves, within kSnap of the arc's end
// is that end, as it is before polishing (DomainMesh::split_arc_at_sign_changes). A target 1e-15
// across among near-coincident point-like sources and one large one (generate_pairs9.py
// "tinydiff_coinc" 7754, A's target 3, nearest first; reduced to 5 of B's faces, in the order
// inserted): the fifth source's line between its corner region a and its edge region ab runs
// through a vertex where a face touches itself, and crosses an arc into that vertex 8e-9 from it.
// Kept as a second vertex, it split the line's chord in two whose ends interleaved along the
// face's boundary; the face stayed whole across the line, and a piece of it 0.29 deep in the corner
// region took the edge region's label (validate(true): "lies outside the label's region"; d^2 only
// 3e-12 off, under a coincident source). Oracle: at each domain's interior point, its polynomial is
// the distance to its labelled source by brute force (without the change, 4.3e-12 where that source
// is 0.085 away).
TEST(Degenerate, CrossingPolishedWithinSnapOfAVertexIsThatVertex) {
    const TriangleMesh T = make_mesh({{7.6816791428035023e-05, 9.9815608852796053e-05, 6.6885200143156743e-06},
                                      {7.6816791428609176e-05, 9.9815608852330307e-05, 6.6885200144600477e-06},
                                      {7.6816791428736421e-05, 9.9815608852991847e-05, 6.6885200141230226e-06}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{6.0811849973513276e-05, 4.8033985352764984e-05, 3.3915068127618858e-05},
                                      {8.214224301514364e-05, 0.00010399976887440028, 3.9241389629344196e-06},
                                      {-2.1281655778712219e-06, 7.0844849445157959e-05, 3.1717490731495432e-05},
                                      {7.681679142846022e-05, 9.9815608852706078e-05, 6.6885200142995765e-06},
                                      {7.681679142815022e-05, 9.9815608852511762e-05, 6.6885200144367272e-06},
                                      {7.6816791428420552e-05, 9.981560885223567e-05, 6.68852001453212e-06},
                                      {7.6816791428035037e-05, 9.9815608852796053e-05, 6.6885200143156692e-06},
                                      {7.681679142860919e-05, 9.9815608852330321e-05, 6.6885200144600426e-06},
                                      {7.6816791428736434e-05, 9.981560885299186e-05, 6.6885200141230175e-06},
                                      {7.6816791428372034e-05, 9.9815608852327488e-05, 6.6885200144945999e-06},
                                      {7.6816791428438916e-05, 9.9815608852614639e-05, 6.6885200143466825e-06},
                                      {7.6816791428047736e-05, 9.9815608852843636e-05, 6.6885200142909359e-06},
                                      {7.6816791428435893e-05, 9.9815608852714196e-05, 6.6885200142990665e-06}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {3, 9, 10}, {3, 11, 12}});
    int fifth = 0;  // domains of the fifth source probed (the case is there)
    insert_into_bare_mesh(
        T, S, [](const DomainMesh&, const TargetFrame&, const char*) {},
        [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
            for (size_t f = 1; f < mesh.faces().size(); ++f) {
                const DomainMesh::Face& F = mesh.faces()[f];
                Vec2 p;
                if (!F.alive || F.infinite || !mesh.interior_point((int)f, p)) continue;
                const std::array<Vec3, 3> c = source_in_frame(fr, S.corners(F.label.source));
                const double own = nearest_feature(Vec3(p.x, p.y, 0), c[0], c[1], c[2]).d2;
                EXPECT_NEAR(F.poly(p), own, 1e-9) << "face " << f << " after source " << s << ", " << label;
                fifth += F.label.source == 4;
            }
        });
    EXPECT_GT(fifth, 2);
}

// d^2 at p (frame) by brute force over S's triangles 0 .. last, each taken into the frame
// (nearest_feature): frame units, without the world's rounding of p.
double frame_d2(const TargetFrame& fr, const TriangleMesh& S, uint32_t last, Vec2 p) {
    double best = HUGE_VAL;
    for (uint32_t t = 0; t <= last; ++t) {
        const std::array<Vec3, 3> c = source_in_frame(fr, S.corners(t));
        best = std::min(best, nearest_feature(Vec3(p.x, p.y, 0), c[0], c[1], c[2]).d2);
    }
    return best;
}

// A line pair whose lines come within kOffCurve of each other over the face (crossing at a small
// angle just beyond it) is cut one line at a time, as one crossing on or near the face is
// (DomainMesh::split_by_line_pair): a vertex near both lines may be taken for either, and the
// chords are then found on the wrong line. A needle target 7.6e-5 wide among a grid's triangles
// 2.4e10 from the origin (generate_pairs7.py "aniso_grid" 14329, B's target 33, all three orders;
// reduced to 3 of A's faces): an edge's quadratic less a face's is a line pair whose lines cross
// 5.6e-6 rad apart 0.04 beyond T''s far end, 2.2e-7 apart there. One line crosses a strip 3.3e-6
// wide along the whole needle, from a cluster of vertices at its near end to one at its far end,
// where the vertices lay 9e-8 from the other line and 1.1e-7 to 1.6e-7 from it: each line got one
// end's vertices, neither a chord, and the strip went whole to the face, whose d^2 is up to 7.4e-12
// where the edge's is 1.7e-14 (validate(): "d^2 jumps by 2.02309e-12" after the third source).
// Oracle: on a grid over T', each domain's polynomial is d^2 by brute force over the sources
// inserted, to 1e-13.
TEST(Degenerate, NearlyParallelLinePairIsCutOneLineAtATime) {
    const TriangleMesh T = make_mesh({{24278860832.01427, 27232661521.06016, 19424857556.694656},
                                      {24270922671.9792, 27253545702.08013, 19423570731.310734},
                                      {24270924208.765316, 27253546310.95854, 19423571139.056797}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{24278860567.36482, 27232661420.55138, 19424857557.07078},
                                      {24270927216.538345, 27253547499.096798, 19423571879.446365},
                                      {24270929994.634308, 27253548596.790535, 19423572567.897617},
                                      {24278860764.9805, 27232661494.662937, 19424857541.53589},
                                      {24270924141.73154, 27253546284.561317, 19423571123.89803}},
                                     {{0, 1, 2}, {0, 3, 4}, {0, 4, 1}});
    insert_into_bare_mesh(
        T, S, [](const DomainMesh&, const TargetFrame&, const char*) {},
        [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
            const auto d2_at = [&](Vec2 p) { return frame_d2(fr, S, s, p); };
            EXPECT_EQ(grid_points_off(mesh, fr, 400, 1e-13, d2_at), 0) << "after source " << s << ", " << label;
        });
}

// A piece that a region's cut left outside it, though the source is nearer at a corner of it that
// lies inside the region (deeper than a vertex on the region's line can be), gets the paper's
// insertion (DomainMesh::set_aside_dropped_pieces). A target 5e-14 across far (1e10 times its size)
// from the origin among sources of its size (generate_pairs10.py "unused_verts" 5288, side A,
// target 3, the paper's order, the 7th insertion; reduced to 2 of B's faces): a sliver under 2.6e-7
// wide along T''s edge, which the second source's face region line crosses at 1e-6 rad. The cut
// dropped its chord as hugging the sliver's boundary and sent the whole sliver outside the face
// region, to the edge region across the line, which the lean insertion had passed over as nowhere
// nearer; the end of the sliver inside the face region, up to 1.34e-7 deep, kept the first source,
// d^2 0.202 where the second gives 0.126 ("d^2 jumps by 0.0758406" after the second source,
// unwatched). Oracle: brute force at points 2e-9 to 4e-8 inside T''s edge along that end, each
// domain's polynomial against d^2 over the sources inserted, to 1e-6 (without the change, 86 of the
// 155 are off after the second source).
TEST(Degenerate, PieceADroppedChordLeftOutsideARegionWhereTheSourceIsNearer) {
    const TriangleMesh T = make_mesh({{0.0013591025472424125, -1.9393660898406395e-19, 1.4026773368556679e-19},
                                      {0.0013591025472253966, 3.1436383156409813e-15, 5.1213045583876192e-14},
                                      {0.0013591025472741195, -4.5664473474117023e-14, 5.6341100557705917e-14}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{0.0013591025472424129, 0, 0},
                                      {0.0013591025472032439, -4.9844892725515083e-15, 5.7091843000595889e-14},
                                      {0.0013591025472498384, 1.2111790223660475e-14, 4.4726687231652178e-14},
                                      {0.0013591025472741197, -4.5664431048699598e-14, 5.6341069872848717e-14},
                                      {0.0013591025472275253, -6.2760710544911578e-14, 6.8706225641792427e-14},
                                      {0.0013591025472666943, -5.7776221272360071e-14, 1.161438264119654e-14}},
                                     {{0, 1, 2}, {3, 4, 5}});
    int inside = 0;  // window points inside T' (the case is there)
    insert_into_bare_mesh(
        T, S, [](const DomainMesh&, const TargetFrame&, const char*) {},
        [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
            const auto& c = fr.corners;  // the sliver lies along the edge from c[2] to c[1]
            Vec2 in = perp(c[1] - c[2]) / norm(c[1] - c[2]);
            if (dot(in, c[0] - c[2]) < 0) in = -1.0 * in;
            int off = 0;
            for (int i = 0; i <= 30; ++i)
                for (double w : {2e-9, 5e-9, 1e-8, 2e-8, 4e-8}) {
                    const Vec2 p = c[2] + (c[1] - c[2]) * (0.39 + 0.14 * i / 30) + in * w;
                    const int f = mesh.face_at(p);
                    if (f <= 0) continue;
                    ++inside;
                    off += std::fabs(mesh.faces()[f].poly(p) - frame_d2(fr, S, s, p)) > 1e-6;
                }
            EXPECT_EQ(off, 0) << "after source " << s << ", " << label;
        });
    EXPECT_GT(inside, 500);
}

// A region line through the gap between a hole of the face and its outer loop, narrower than
// kCluster, cuts the face there (DomainMesh::add_hole_candidate). Sources of a 1e-6 mesh whose
// corners were snapped to within 1.4e-15 of T''s corner at the origin (generate_pairs12.py
// "snapped_corners" 8531, side A, target 0, nearest first; reduced to the first three sources):
// after two, the first source's face region holds a hole (the second's domains) ending 2.2e-8 from
// T''s corner; the third's face quadratic less the first's is a line pair centred 1.5e-8 from that
// corner, and one line crosses the gap, the hole and the face beyond. Its chord across the gap,
// as the curve has it, ran outside the face and was dropped; the chord from the hole onwards,
// alone, cut nothing, so the face stayed whole across that line, and a wedge beyond it took the
// sign of the strip between the lines: the third source, d^2 2.2 times the truth ("d^2 jumps by
// 0.000201637" after it). Oracle: brute force on a 400 x 400 grid after each source, each
// domain's polynomial against d^2 over the sources inserted, to 1e-13 (without the change, 6144
// of the 79,401 points are off after the third source, watched or not).
TEST(Degenerate, RegionLineThroughTheGapBesideAHoleCutsTheFace) {
    const TriangleMesh T = make_mesh({{0.0, 0.0, 0.0},
                                      {-3.6135627127318917e-07, -1.529323291763144e-07, -5.427214623002534e-08},
                                      {-6.34089071944075e-07, 5.983670705828916e-07, -1.2223793364994332e-07}},
                                     {{0, 1, 2}});
    const TriangleMesh S = make_mesh({{-5.069274203629245e-18, -1.3944930877329957e-15, -1.300177355741826e-15},
                                      {-3.727101998053915e-07, -1.1508406230429452e-08, -3.7803880752454764e-08},
                                      {-5.930829134257175e-07, 5.272880713866808e-07, -6.015621644044322e-08},
                                      {-3.0445436396472827e-18, -1.190530045510162e-18, -8.498082770023337e-19},
                                      {-6.907303406752535e-08, -3.8030944917909205e-07, 2.6874051027897073e-07},
                                      {-4.6081723960013905e-07, 4.842796067936555e-07, -3.4220961096236485e-07},
                                      {-6.614172588260713e-07, 2.2940918554844065e-07, -5.549924686960566e-07},
                                      {-4.7409624969697205e-07, -1.216843231797279e-07, 2.9438177359971647e-07}},
                                     {{0, 1, 2}, {3, 4, 5}, {3, 6, 7}});
    insert_into_bare_mesh(
        T, S, [](const DomainMesh&, const TargetFrame&, const char*) {},
        [&](const DomainMesh& mesh, const TargetFrame& fr, uint32_t s, const char* label) {
            const auto d2_at = [&](Vec2 p) { return frame_d2(fr, S, s, p); };
            EXPECT_EQ(grid_points_off(mesh, fr, 400, 1e-13, d2_at), 0) << "after source " << s << ", " << label;
        });
}

// A folded piece left over after a needle source's regions are cut in goes to the region deepest
// at its corners' centroid where no point beside its arcs lies in it (DomainMesh::long_arc_point).
// A cone over a fan 1.4e5 from the origin (generate_pairs11.py "a_cone_over_fan" 21079, side A,
// target 8; reduced to three of B's triangles): the first is a needle, 2 long and 6e-10 wide at its
// far end in frame units, nearly parallel to T' 6.6e-4 below it and tilted 0.013 rad across, so
// its face region on T' is a strip 1e-10 wide 8.9e-6 off its corner's projection, near T''s
// corner. A piece of a domain just beside that corner, 2.3e-6 by 1.4e-7 and folded (its loop
// clockwise, its area -1.6e-13, within rounding), was left in no region by the cuts; every point
// beside its arcs lies outside it, so no point of it was found and it went to the face region
// (the last, what the cuts leave), 6e-6 outside that region: the face's plane quadratic, 6.9e-11
// below d^2 there ("d^2 jumps by 6.89644e-11"). Oracle: brute force over B in long double at every
// arc's middle (in double, a world point's rounding 1.4e5 from the origin puts d^2 1e-12 off),
// both domains' quadratics within the vertices' placement (1e-6) times their gradients and 1e-14
// (without the change, off at the folded piece's arcs).
TEST(Degenerate, AFoldedLeftoverPieceGoesToTheRegionAtItsCentroid) {
    const TriangleMesh A = make_mesh({{56179.788399582387, 29995.345794049546, -135368.00072724989},
                                      {56179.782728993297, 29995.360174979585, -135367.99622350128},
                                      {56179.793227166083, 29995.361099125872, -135367.99942357992}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{56179.788402805367, 29995.345792178348, -135368.00071721699},
                                      {56179.820104569517, 29995.344900091546, -135368.01106748378},
                                      {56179.820104569939, 29995.344900090917, -135368.01106748404},
                                      {56179.791167008509, 29995.371320831873, -135367.99684394975},
                                      {56179.792037341358, 29995.371971368157, -135367.99700220706},
                                      {56179.792037341358, 29995.37197136816, -135367.99700220706},
                                      {56179.798564837736, 29995.376850390301, -135367.99818913688}},
                                     {{0, 1, 2}, {0, 3, 4}, {5, 6, 0}});
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        int arcs = 0;
        EXPECT_EQ(arc_middles_off(*ts.domain_mesh(), arcs, 1e-6, 1e-14, [&](Vec2 m) { return (double)brute_d2_ld(ts.frame(), B, m); }), 0);
        EXPECT_GE(arcs, 5);
    }, /*to_the_end=*/true);
}

// A point beside a curved arc is near it, however unevenly the arc's parameter runs
// (DomainMesh::near_arc). Generate_pairs11.py "crack_overlap_step" 6000 (side B, target 153;
// reduced to three of A's triangles, segments 1e-5 of T' long clustered by T''s corner): a
// parabola's arc between two vertex-against-edge domains covers a parameter range of 1.1e-5, its
// first sixteenth 1.1e-6 long in the plane and its last 9e-6. Points beside the arc were searched
// only within tol plus the first cell's length of the samples, so a probe 2.5e-8 off the arc, 2e-6
// from the nearest sample, was "not near" the boundary, and validate() held it to d^2 at 1e-7
// relative where the domain mesh's resolution (a sliver 9e-8 wide along the arc, where a third
// segment's corner is nearer) allows 2.8e-4 ("polynomial 5.51309559116e-09 but d^2 =
// 5.5115738694e-09"). Oracle: points put half the tolerance off every curved arc, at 64 places
// along it, along the arc's normal: each is within the tolerance of the arc by construction.
TEST(Degenerate, APointBesideAnArcWithAnUnevenParameterIsNearIt) {
    const TriangleMesh A = make_mesh({{0.001148755008538389, 0.00080657864451893677, -0.0001185623150612596},
                                      {0.0011780860356982279, 0.0008253031057423579, -0.00011790981624643909},
                                      {0.0011622360387935748, 0.00082337422694321507, -0.00010864057006291242}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{0.0011622358499296154, 0.00082337407071670667, -0.00010864061564469777},
                                      {0.0011622358499296158, 0.00082337407071670754, -0.00010864061564469712},
                                      {0.0011622362159294992, 0.0008233740536694211, -0.00010864090204494612},
                                      {0.0011622361529992319, 0.00082337403533187727, -0.00010864087778963272},
                                      {0.0011622362929887815, 0.00082337424797026149, -0.00010864072984408667},
                                      {0.0011622362929887811, 0.0008233742479702603, -0.0001086407298440877},
                                      {0.0011622362450381528, 0.00082337415148446211, -0.00010864080830714431},
                                      {0.0011622361517849586, 0.00082337403518410528, -0.00010864087707951286},
                                      {0.001162236151768477, 0.00082337403518209951, -0.00010864087706987432}},
                                     {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        const DomainMesh& m = *ts.domain_mesh();
        const double tol = 2 * DomainMesh::kVertexTolerance;
        int tried = 0, missed = 0;
        for (size_t e = 0; e < m.edges().size(); ++e) {
            const DomainMesh::Edge& E = m.edges()[e];
            if (!E.alive || E.curve.straight()) continue;
            for (int k = 0; k < 64; ++k) {
                const Vec2 q = m.edge_point((int)e, (k + 0.5) / 64), n = E.equation.gradient(q);
                if (!(norm(n) > 0)) continue;
                const Vec2 p = q + (0.5 * tol / norm(n)) * n;
                for (int side = 0; side < 2; ++side) {
                    const int f = m.half_edges()[2 * e + side].face;
                    if (f <= 0) continue;
                    ++tried;
                    missed += !m.near_boundary(f, p, tol);
                }
            }
        }
        EXPECT_EQ(missed, 0) << "of " << tried;
        EXPECT_GE(tried, 64);
    }, /*to_the_end=*/true);
}

// A face pinched into two lobes keeps both for the rest of the split (DomainMesh::pinch_face).
// Generate_pairs17.py "export_f32" 12910 (side A, target 0, the paper's order; reduced to four of
// B's triangles, float32 coordinates). Two sources share a corner at T''s corner (1, 0); the
// face region of the first, 5, and the region line of the second, 1, bound a wedge 0.46 long and
// 1.8e-3 rad wide towards that corner, and the line of their planes' line pair where they tie runs
// along the wedge through its tip. That tip was pinched off as a lobe 1e-6 long; the face's loops
// still named only the tip, so the line's chord along the wedge had its middle "outside" the face
// and was dropped, and the whole wedge went to source 1, d^2 up to 7e-5 above the truth (0.09)
// along one side, with a step of 6.8e-5 at the wedge's end. Oracle: d^2 by brute force in long
// double at 41 x 21 points in a band twice the wedge's width about that line, to 1e-12.
TEST(Degenerate, APinchedFaceKeepsBothLobesForTheRestOfTheSplit) {
    const TriangleMesh A = make_mesh({{-0.43537811484215716, -1.563473338508595, -0.7435389166184523},
                                      {0.46385639676635204, -1.9041405554416118, -2.2688380824228385},
                                      {0.7798483807324186, -2.60141662017735, -1.5784716763401374}},
                                     {{0, 1, 2}});
    const TriangleMesh B = make_mesh({{-0.4353453814983368, -2.2099509239196777, -1.5901455879211426},
                                      {0.4982384443283081, -2.3106532096862793, -2.093093156814575},
                                      {-0.2442822903394699, -2.5005736351013184, -1.212581753730774},
                                      {0.6635699272155762, -2.562136173248291, -1.7663781642913818},
                                      {0.03616567328572273, -2.517815113067627, -0.7829623222351074},
                                      {-0.4353781044483185, -1.5634733438491821, -0.7435389161109924},
                                      {-0.4750785231590271, -1.7401700019836426, -1.7932428121566772},
                                      {-0.4353781044483185, -1.5634733438491821, -0.7435389161109924}},
                                     {{0, 1, 2}, {2, 3, 4}, {2, 4, 5}, {6, 0, 7}});
    expect_constructions_hold(A, B, [&](const TargetSolver& ts) {
        const DomainMesh& m = *ts.domain_mesh();
        int tried = 0, off = 0;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 20; ++j) {
                const double x = 0.55 + 0.01 * i, w = 1.8e-3 * (1 - x);
                const Vec2 p{x, 0.24543 * (1 - x) + w * (j - 10) / 10.0};
                const int f = m.face_at(p);
                if (f <= 0 || m.faces()[f].infinite) continue;
                ++tried;
                off += std::fabs(m.faces()[f].poly(p) - (double)brute_d2_ld(ts.frame(), B, p)) > 1e-12;
            }
        EXPECT_EQ(off, 0) << "of " << tried;
        EXPECT_GE(tried, 800);
    }, /*to_the_end=*/true);
}
