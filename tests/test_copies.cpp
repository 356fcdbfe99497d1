// Targets that are copies of source triangles (core/copies.h): d = 0 on them exactly, found
// without a construction in both modes and in the statistics. Oracles: a mesh against a renumbered
// copy of itself is at distance 0 (not rounding noise); a flat grid against the same grid with one
// vertex raised by h has, by hand, h from the tent to the flat, a known point of the flat at
// h delta / sqrt(h^2 + delta^2) from the tent, and the tent's mean and RMS distance in closed form;
// the copies are exactly the triangles away from the raised vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include <hlens/bounds.h>
#include <hlens/cascade.h>
#include <hlens/copies.h>
#include <hlens/hausdorff.h>
#include <hlens/surface_stats.h>
#include <hlens/target_solver.h>

#include "test_meshes.h"

using namespace hlens;
using namespace hlens_test;

namespace {

// The same surface with its vertices and triangles in another order, every triangle's corners
// rotated and every third one turned over.
TriangleMesh renumbered(const TriangleMesh& m, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<uint32_t> perm(m.positions.size());
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng);
    TriangleMesh out = m;
    for (size_t v = 0; v < perm.size(); ++v) out.positions[perm[v]] = m.positions[v];
    std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
    for (size_t t = 0; t < out.triangles.size(); ++t) {
        Tri f = out.triangles[t];
        for (uint32_t& i : f) i = perm[i];
        out.triangles[t] = {f[1], f[2], f[0]};
        if (t % 3 == 0) std::swap(out.triangles[t][0], out.triangles[t][1]);
    }
    return out;
}

TriangleMesh bumpy_with_a_segment() {
    TriangleMesh m = height_field(10, [](double x, double y) { return 0.2 * std::sin(3 * x) * std::cos(2 * y); });
    // A zero-area triangle (a segment along the surface's edge) and a duplicated face.
    m.triangles.push_back({0, 1, 2});
    m.triangles.push_back(m.triangles[17]);
    return m;
}

std::vector<uint8_t> copies_of(const VoxelGrid& grid, int side) {
    std::vector<double> d2;
    farthest_vertex_sq(grid, side, 1, nullptr, nullptr, &d2);
    return copied_targets(grid, side, d2);
}

}  // namespace

TEST(Copies, MeshAgainstARenumberedCopyIsExactlyZero) {
    // Also two triangles folded along a diagonal: the witness's nearest point, searched, came out
    // 2e-16 off the vertex it is.
    const TriangleMesh fold = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2}}, {{0, 1, 2}, {1, 3, 2}});
    for (const TriangleMesh& A : {bumpy_with_a_segment(), fold}) {
        for (const Vec3& far : {Vec3{0, 0, 0}, Vec3{3e6, -2e6, 1e6}}) {
            const TriangleMesh B = renumbered(A, 7);
            const TriangleMesh FA = shifted(A, far), FB = shifted(B, far);
            const VoxelGrid grid(FA, FB);
            for (int side = 0; side < 2; ++side) {
                const std::vector<uint8_t> c = copies_of(grid, side);
                EXPECT_EQ(std::count(c.begin(), c.end(), 1), (long)c.size()) << "every triangle has its copy";
            }
            for (Mode mode : {Mode::Paper, Mode::Fast})
                for (int threads : {1, 2}) {
                    HausdorffOptions opt;
                    opt.mode = mode;
                    opt.threads = threads;
                    const HausdorffResult r = hausdorff(FA, FB, opt);
                    for (const OneSidedResult* s : {&r.a_to_b, &r.b_to_a}) {
                        SCOPED_TRACE(std::string(mode_name(mode)) + (far.x != 0 ? " far" : ""));
                        // Not rounding noise (1e-17, with an upper end of 6e-15): nothing is constructed.
                        EXPECT_EQ(s->distance, 0.0);
                        EXPECT_EQ(s->lower, 0.0);
                        EXPECT_EQ(s->upper, 0.0);
                        EXPECT_EQ(s->exact_solves, 0u);
                        EXPECT_EQ(s->from_point, s->to_point) << "the witness lies on the other mesh";
                        EXPECT_EQ(*std::max_element(s->target_max.begin(), s->target_max.end()), 0.0);
                    }
                }
        }
    }
}

// The solver, run unwatched on a copy, stops at it with d = 0 at a corner; stepped, it shows the
// paper's search (every neighbour within the radius), whose maximum is rounding of 0.
TEST(Copies, SolverStopsAtTheCopyButStepsThroughTheSearch) {
    const TriangleMesh A = bumpy_with_a_segment(), B = renumbered(A, 3);
    const VoxelGrid grid(A, B);
    for (uint32_t t : {0u, 57u, 199u, 200u}) {  // 200: the segment
        TargetSolver run(grid, 0, t);
        run.run();
        EXPECT_EQ(run.max_sq(), 0.0);
        EXPECT_EQ(run.slack(), 0.0);
        EXPECT_EQ(run.insertions(), 1) << "the copy is the nearest source and comes first";
        const auto c = A.corners(t);
        EXPECT_TRUE(run.max_point() == c[0] || run.max_point() == c[1] || run.max_point() == c[2]);
        TargetSolver stepped(grid, 0, t);
        while (stepped.step()) {}
        EXPECT_GT(stepped.insertions(), 1) << "neighbours touching the target are within the radius";
        EXPECT_LE(stepped.max_sq(), 1e-28);
    }
}

TEST(Copies, OnlyTrianglesAwayFromAnEditAreCopies) {
    const int n = 8;
    const double h = 0.05, s = 2.0 / n;
    const TriangleMesh flat = height_field(n, [](double, double) { return 0.0; });
    TriangleMesh tent = flat;
    const uint32_t v = 3 * (n + 1) + 4;  // an interior vertex, at (0, -0.25)
    tent.positions[v].z = h;
    const VoxelGrid grid(flat, tent);
    for (int side = 0; side < 2; ++side) {
        const std::vector<uint8_t> c = copies_of(grid, side);
        for (size_t t = 0; t < c.size(); ++t) {
            const Tri& f = flat.triangles[t];
            const bool touches = f[0] == v || f[1] == v || f[2] == v;
            EXPECT_EQ(c[t], touches ? 0 : 1) << "side " << side << " triangle " << t;
        }
    }
    // By hand: the apex is h above the flat. Below it, the flat is h delta / sqrt(h^2 + delta^2)
    // from the nearest of the tent's six faces (delta = s / sqrt 2, the distance in the plane from
    // the vertex to the far edges of the two faces across the quads' diagonal).
    const double delta = s / std::sqrt(2.0), below = h * delta / std::sqrt(h * h + delta * delta);
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        HausdorffOptions opt;
        opt.mode = mode;
        const HausdorffResult r = hausdorff(flat, tent, opt);
        EXPECT_NEAR(r.b_to_a.distance, h, 1e-15);
        EXPECT_LE(r.b_to_a.lower, h);
        EXPECT_GE(r.b_to_a.upper, h);
        EXPECT_NEAR(r.a_to_b.distance, below, 1e-15);
        EXPECT_LE(r.a_to_b.lower, below);
        EXPECT_GE(r.a_to_b.upper, below);
    }
    // The tent's statistics to the flat: d is the height, linear on each of the six faces (a
    // triangle of area a with corner heights h, 0, 0 has the integrals a h / 3 and a h^2 / 6).
    double faces = 0, total = 0;
    for (size_t t = 0; t < tent.num_triangles(); ++t) {
        const auto c = tent.corners(t);
        const double a = 0.5 * norm(cross(c[1] - c[0], c[2] - c[0]));
        total += a;
        const Tri& f = tent.triangles[t];
        if (f[0] == v || f[1] == v || f[2] == v) faces += a;
    }
    StatsOptions so;
    so.percentiles = {};
    const SurfaceStats st = surface_stats(grid, 1, so);
    EXPECT_NEAR(st.area, total, 1e-12 * total);
    EXPECT_NEAR(st.mean(), faces * h / 3 / total, 1e-9 * h);
    EXPECT_NEAR(st.rms(), std::sqrt(faces * h * h / 6 / total), 1e-9 * h);
    size_t zero = 0;
    for (const TriangleStats& ts : st.triangles) zero += ts.int_d == 0 && ts.int_d2 == 0 && ts.max == 0;
    EXPECT_EQ(zero, tent.num_triangles() - 6) << "the copies' integrals are 0 exactly";
}

// A triangle one ulp off its source's corners is no copy: it is solved, and its distance is not 0.
TEST(Copies, AnUlpOffIsNoCopy) {
    const TriangleMesh A = height_field(4, [](double x, double y) { return 0.1 * x * y; });
    TriangleMesh B = A;
    const Vec3 p = B.positions[7];
    B.positions[7].z = std::nextafter(p.z, 1.0);
    const VoxelGrid grid(A, B);
    const std::vector<uint8_t> c = copies_of(grid, 1);
    for (size_t t = 0; t < c.size(); ++t) {
        const Tri& f = B.triangles[t];
        EXPECT_EQ(c[t], (f[0] == 7 || f[1] == 7 || f[2] == 7) ? 0 : 1);
    }
    HausdorffOptions opt;
    const HausdorffResult r = hausdorff(A, B, opt);
    EXPECT_GT(r.b_to_a.upper, 0.0);
    EXPECT_GT(r.b_to_a.exact_solves, 0u);
}
