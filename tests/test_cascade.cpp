// Fast mode's culling by cascading bounds (core/cascade.h) is safe: on random, degenerate, far and
// real pairs it gives paper mode's result, witness and certified interval bit for bit, and every
// per-target value it reports is an upper bound of that target's exact maximum (paper mode's), equal
// to it where it says exact. Paper mode is the oracle here; it is itself checked against sampling
// and Lipschitz bounds in test_solver.cpp, and here again on the pairs where that is cheap.
#include <gtest/gtest.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"  // OpenMesh's VectorT() leaves its data uninitialised
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#pragma GCC diagnostic pop

#include <hlens/bounds.h>
#include <hlens/hausdorff.h>

#include "test_meshes.h"

using namespace hlens;
using namespace hlens_test;

namespace {

// Paper mode and fast mode (one and two threads) on A vs B, both directions, compared.
void expect_fast_equals_paper(const TriangleMesh& A, const TriangleMesh& B, const std::string& what,
                              bool check_bounds = false) {
    SCOPED_TRACE(what);
    HausdorffOptions paper, fast1, fast2;
    paper.mode = Mode::Paper;
    fast1.threads = 1;
    fast2.threads = 2;
    HausdorffResult p = hausdorff(A, B, paper), f1 = hausdorff(A, B, fast1), f2 = hausdorff(A, B, fast2);
    for (auto side : {&HausdorffResult::a_to_b, &HausdorffResult::b_to_a}) {
        const OneSidedResult &P = p.*side;
        for (const OneSidedResult* F : {&(f1.*side), &(f2.*side)}) {
            EXPECT_EQ(P.distance, F->distance);
            EXPECT_EQ(P.target, F->target);
            EXPECT_EQ(P.lower, F->lower);
            EXPECT_EQ(P.upper, F->upper);
            EXPECT_EQ(P.from_point, F->from_point);
            EXPECT_LE(F->exact_targets, P.exact_targets);
            ASSERT_EQ(F->target_max.size(), P.target_max.size());
            size_t below = 0, unequal = 0;
            for (size_t t = 0; t < P.target_max.size(); ++t) {
                const double exact = P.target_max[t], tol = 1e-9 * exact + 1e-12 * (1 + A.bounds().diagonal());
                if (F->target_max[t] < exact - tol) ++below;
                if (F->target_exact[t] && std::fabs(F->target_max[t] - exact) > tol) ++unequal;
            }
            EXPECT_EQ(below, 0u) << "targets whose reported bound is below their exact maximum";
            EXPECT_EQ(unequal, 0u) << "targets marked exact whose value differs from paper mode's";
        }
    }
    if (check_bounds) {
        VoxelGrid grid(A, B);
        const double diag = std::max(A.bounds().diagonal(), B.bounds().diagonal());
        for (int s = 0; s < 2; ++s) {
            const double h = s == 0 ? p.a_to_b.distance : p.b_to_a.distance;
            LipschitzBound lb = lipschitz_bounds(grid.mesh(s), grid, s, 1e-7 * diag);
            EXPECT_GE(h, lb.lower - 1e-12 * diag);
            EXPECT_LE(h, lb.upper + 1e-12 * diag);
        }
    }
}

TriangleMesh decimated(const TriangleMesh& m, double fraction) {
    using OM = OpenMesh::TriMesh_ArrayKernelT<>;
    OM om;
    omerr().disable();  // non-manifold faces are skipped, as said: no need to print each
    std::vector<OM::VertexHandle> vh;
    for (const Vec3& p : m.positions) vh.push_back(om.add_vertex(OM::Point(p.x, p.y, p.z)));
    for (const Tri& f : m.triangles) om.add_face(vh[f[0]], vh[f[1]], vh[f[2]]);  // non-manifold faces are skipped
    OpenMesh::Decimater::DecimaterT<OM> dec(om);
    OpenMesh::Decimater::ModQuadricT<OM>::Handle quadric;
    dec.add(quadric);
    dec.initialize();
    dec.decimate_to_faces(0, size_t(fraction * om.n_faces()));
    om.garbage_collection();
    std::vector<Vec3> p;
    std::vector<Tri> t;
    for (auto v : om.vertices()) p.push_back({om.point(v)[0], om.point(v)[1], om.point(v)[2]});
    for (auto f : om.faces()) {
        Tri tri;
        int k = 0;
        for (auto v : om.fv_range(f)) tri[k++] = (uint32_t)v.idx();
        t.push_back(tri);
    }
    return mesh_of(p, t);
}

TriangleMesh shared_mesh(const std::string& name) { return load_mesh(std::string(HLENS_SHARED_MESHES) + "/" + name); }

}  // namespace

TEST(Cascade, RandomPairs) {
    std::mt19937 rng(101);
    for (int i = 0; i < 6; ++i) {
        TriangleMesh A = height_field(5 + i, [&](double x, double y) { return 0.2 * std::sin(2 * x + i) * std::cos(3 * y); });
        TriangleMesh B = random_triangle_soup(rng, 30 + 10 * i, 0.3, {0, 0, 0}, 1.0);
        expect_fast_equals_paper(A, B, "soup vs height field " + std::to_string(i), i < 2);
    }
}

// The case the culling is for: a coarse mesh against a fine one (pieces smaller than the coarse
// triangles are split off and solved on their own), and the reverse.
TEST(Cascade, CoarseAgainstFine) {
    for (int i = 0; i < 3; ++i) {
        auto z = [&](double x, double y) { return 0.3 * std::sin(3 * x + i) * std::cos(2 * y - i); };
        TriangleMesh fine = height_field(24, z), coarse = height_field(4 + i, z);
        expect_fast_equals_paper(coarse, fine, "coarse vs fine " + std::to_string(i), i == 0);
    }
    // Most of the coarse mesh is culled: fewer exact constructions than targets.
    auto z = [](double x, double y) { return 0.3 * std::sin(3 * x) * std::cos(2 * y); };
    HausdorffResult r = hausdorff(height_field(8, z), height_field(32, z));
    EXPECT_LT(r.a_to_b.exact_solves, 128u / 2);
}

// Sources much smaller than their distance (points, tiny triangles): generate_pairs7.py
// "points_on_circle" 1269 (50 point triangles round a target 5e-10 across) split the target into
// 4^10 pieces, one exact construction each, and took minutes. A triangle 1e-9 across under a point
// at height 1 took 1,048,577 constructions. The oracle: the distance from that triangle's farthest
// corner to the point, sqrt(1 + 1e-18), and d(B, A) = 1 (the foot of the point is a corner).
TEST(Cascade, TinyTargetUnderAPointIsNotSplitToTheLimit) {
    const TriangleMesh A = mesh_of({{0, 0, 0}, {1e-9, 0, 0}, {0, 1e-9, 0}}, {{0, 1, 2}});
    const TriangleMesh B = mesh_of({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {{0, 1, 2}});
    const HausdorffResult r = hausdorff(A, B);
    EXPECT_LT(r.a_to_b.exact_solves, 64u);
    EXPECT_NEAR(r.a_to_b.distance, std::sqrt(1 + 1e-18), 1e-15);
    EXPECT_LE(r.a_to_b.lower, std::sqrt(1 + 1e-18));
    EXPECT_GE(r.a_to_b.upper, std::sqrt(1 + 1e-18));
    EXPECT_NEAR(r.b_to_a.distance, 1.0, 1e-15);
}

// Where L is within the tie margin of 0 no piece can be dropped, and splitting only multiplies the
// solves: a target 1.2e-7 across, 1e-10 above a point 1.7e7 from the origin (the margin's absolute
// part is 1e-11 of the coordinates, 1.7e-4 here, above every distance), split to the limit as
// the point is small against its distance, took 4^10 constructions; eight such targets by a
// cluster of points took hours (generate_pairs9.py "cluster_vertex" 260). The oracle: d over the
// target is largest at a corner (the distance to a point is convex), sqrt(s^2 + h^2), and the
// point's distance to the target is h (its foot is the corner above it).
TEST(Cascade, NothingIsSplitWhereNothingCanBeDropped) {
    const double x0 = 16777216, s = 0x1p-23, h = 1e-10;
    const TriangleMesh A = mesh_of({{x0, 0, h}, {x0 + s, 0, h}, {x0, s, h}}, {{0, 1, 2}});
    const TriangleMesh B = mesh_of({{x0, 0, 0}, {x0, 0, 0}, {x0, 0, 0}}, {{0, 1, 2}});
    const HausdorffResult r = hausdorff(A, B);
    EXPECT_LT(r.a_to_b.exact_solves, 64u);
    const double d = std::sqrt(s * s + h * h);
    EXPECT_NEAR(r.a_to_b.distance, d, 1e-15 * d);
    EXPECT_LE(r.a_to_b.lower, d);
    EXPECT_GE(r.a_to_b.upper, d);
    EXPECT_NEAR(r.b_to_a.distance, h, 1e-6 * h);
    EXPECT_LE(r.b_to_a.lower, h);
    EXPECT_GE(r.b_to_a.upper, h);
}

// There too every target is solved in the cascade as one piece, with no early stop (the threshold
// is 0): paper mode's construction. solve_ties, which solves whole every target that can reach the
// result, took those from the cascade rather than constructing each again (generate_pairs10.py
// "fan_thin" 135: two fans 3e11 from the origin, 965 targets of ~770 insertions each, every one
// solved twice). A grid of 32 triangles 1e-10 above a copy of itself 2.4e7 from the origin: one
// construction per target, and the distance by hand, h both ways (the planes are parallel, every
// point over the other grid).
TEST(Cascade, TargetsSolvedWholeAreNotSolvedAgain) {
    const double x0 = 16777216, s = 0x1p-20, h = 1e-10;
    std::vector<Vec3> pa, pb;
    std::vector<Tri> t;
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i) pa.push_back({x0 + i * s, x0 + j * s, h}), pb.push_back({x0 + i * s, x0 + j * s, 0});
    for (uint32_t j = 0; j < 4; ++j)
        for (uint32_t i = 0; i < 4; ++i) {
            const uint32_t v = 5 * j + i;
            t.push_back({v, v + 1, v + 6});
            t.push_back({v, v + 6, v + 5});
        }
    const TriangleMesh A = mesh_of(pa, t), B = mesh_of(pb, t);
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const HausdorffResult r = hausdorff(A, B, opt);
        for (const OneSidedResult* o : {&r.a_to_b, &r.b_to_a}) {
            EXPECT_EQ(o->exact_targets, 32u) << mode_name(mode);
            EXPECT_EQ(o->exact_solves, 32u) << mode_name(mode);
            EXPECT_NEAR(o->distance, h, 1e-6 * h) << mode_name(mode);
            EXPECT_LE(o->lower, h) << mode_name(mode);
            EXPECT_GE(o->upper, h) << mode_name(mode);
        }
    }
}

// A thin target 9 from a strip of 250 slivers, its maximum flat: the cascade split every piece in
// four, and a needle's four children are needles, three of them over the same half of it
// (split_pattern), so the segment was solved in 2,049 pieces and the needle in 1,039
// (generate_pairs11.py "slivers_strip" 1023: 2,052 pieces for three targets). The oracle: a point
// of the target r from the circle's centre is nearest to the chord whose normal is closest in angle
// (delta), at R cos(theta / 2) - r cos(delta) (its foot inside the chord, r < R); least r and
// largest delta, theta / 2, meet at the lowest vertex's middle: h = (R - cz) cos(theta / 2).
TEST(Cascade, ThinTargetsAreHalvedNotQuartered) {
    const int n = 250;
    const double R = 18, cz = 9, span = 2.5 / R, theta = 2 * span / n;
    const TriangleMesh B = sliver_arc(n, R, cz, span);
    const double h = (R - cz) * std::cos(theta / 2);
    const TriangleMesh segment = mesh_of({{-1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, {{0, 1, 2}});
    const TriangleMesh needle = mesh_of({{-1, 0, 0}, {1, 0, 0}, {0.99, 1e-12, 0}}, {{0, 1, 2}});
    for (const TriangleMesh* A : {&segment, &needle}) {
        const HausdorffResult r = hausdorff(*A, B, {}, true);
        const char* name = A == &segment ? "segment" : "needle";
        EXPECT_LT(r.a_to_b.exact_solves, 64u) << name;
        EXPECT_NEAR(r.a_to_b.distance, h, 1e-12 * h) << name;
        EXPECT_LE(r.a_to_b.lower, h * (1 + 1e-15)) << name;
        EXPECT_GE(r.a_to_b.upper, h * (1 - 1e-15)) << name;
    }
}

TEST(Cascade, DegenerateConfigurations) {
    auto bump = [](double x, double y) { return 0.15 * std::sin(x) * std::cos(y - 0.3); };
    TriangleMesh flat = height_field(4, [](double, double) { return 0.0; });
    TriangleMesh bumpy = height_field(12, bump);
    // Result at a vertex of A shared by several targets: every one of them ties.
    expect_fast_equals_paper(bumpy, flat, "bump vs plane", true);
    // Coplanar overlapping triangulations, then one lifted vertex.
    TriangleMesh A = height_field(5, [](double, double) { return 0.0; });
    expect_fast_equals_paper(A, flat, "coplanar");
    A.positions[2 * 6 + 2].z = 0.3;
    expect_fast_equals_paper(A, flat, "coplanar, one vertex lifted");
    // Duplicated triangles and slivers on both sides.
    TriangleMesh D = with_duplicates_and_slivers(bumpy, 5, 3, 1e-13);
    expect_fast_equals_paper(D, with_duplicates_and_slivers(flat, 3, 2, 0.0), "duplicates and slivers");
    // Near-coincident: a copy moved by 1e-7.
    expect_fast_equals_paper(bumpy, shifted(bumpy, {0, 0, 1e-7}), "near-coincident");
    expect_fast_equals_paper(bumpy, jittered(bumpy, 1e-6, 5), "jittered by 1e-6");
}

TEST(Cascade, FarFromTheOrigin) {
    std::mt19937 rng(29);
    TriangleMesh A = height_field(10, [](double x, double y) { return 0.2 * std::sin(2 * x + y); });
    TriangleMesh B = height_field(3, [](double x, double y) { return 0.1 * x * y; });
    const Vec3 far{1e6, -2e6, 5e5};
    expect_fast_equals_paper(shifted(A, far), shifted(B, far), "height fields at 1e6");
    TriangleMesh S = random_triangle_soup(rng, 30, 0.4, {0, 0, 0}, 1.0);
    expect_fast_equals_paper(shifted(A, far), shifted(S, far), "soup at 1e6");
}

TEST(Cascade, MeshesFarApart) {
    // A small mesh far from a large one: every target's distance is about the same.
    TriangleMesh big = height_field(16, [](double x, double y) { return 0.1 * std::sin(4 * x) * y; });
    TriangleMesh small = shifted(height_field(3, [](double x, double) { return 0.05 * x; }), {30, 10, 5});
    expect_fast_equals_paper(small, big, "small far from big");
}

TEST(Cascade, RealMeshesAgainstTheirSimplifications) {
    for (const char* name : {"woody.obj", "suzanne.obj", "elephant.off"}) {
        TriangleMesh A = shared_mesh(name);
        TriangleMesh B = decimated(A, 0.15);
        ASSERT_GT(B.num_triangles(), 20u) << name;
        expect_fast_equals_paper(A, B, std::string(name) + " vs 15%", std::string(name) == "woody.obj");
    }
}

// hlens-cli batch indexes its reference once: a grid shared by several pairs gives each pair the
// result of a grid built for it alone, in both modes.
TEST(Cascade, SharedReferenceGridGivesEachPairItsOwnResult) {
    const TriangleMesh ref = height_field(12, [](double x, double y) { return 0.2 * std::sin(3 * x) * y; });
    const auto ref_grid = std::make_shared<const MeshGrid>(ref);
    for (double lift : {0.01, 0.3}) {
        const TriangleMesh other = shifted(height_field(5, [](double x, double) { return 0.1 * x; }), {0.1, 0, lift});
        for (Mode m : {Mode::Fast, Mode::Paper}) {
            HausdorffOptions opt;
            opt.mode = m;
            const HausdorffResult alone = hausdorff(ref, other, opt);
            const HausdorffResult shared = hausdorff(VoxelGrid(ref_grid, std::make_shared<const MeshGrid>(other)), opt);
            EXPECT_EQ(shared.a_to_b.distance, alone.a_to_b.distance);
            EXPECT_EQ(shared.b_to_a.distance, alone.b_to_a.distance);
            EXPECT_EQ(shared.a_to_b.upper, alone.a_to_b.upper);
            EXPECT_EQ(shared.b_to_a.target, alone.b_to_a.target);
            EXPECT_GT(shared.hausdorff, lift * 0.5);
        }
    }
}
