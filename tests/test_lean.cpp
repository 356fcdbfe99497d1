// The insertion without a listener (core/domain_reach.cpp: only the regions that may be nearer
// are cut in) against the paper's insertion (with a listener, every cut made and reported), on the
// same targets: the same squared distance everywhere on T', the same maximum, and the lean mesh
// valid by the thorough validate() (brute-force d^2 at several points of every domain) after
// every insertion wherever the paper's is. If a region were passed over where it is nearer, d^2 there would be the old
// domain's, above the truth, and both checks would see it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "degenerate_pairs.h"
#include "test_meshes.h"

#include "hlens/target_solver.h"

using namespace hlens;
using namespace hlens_test;

namespace {

struct Compared {
    long points = 0, paper_faults = 0;
    long faces_paper = 0, faces_lean = 0;
    double worst = 0;  // largest |d2_paper - d2_lean| / (1 + d2), frame units
};

// d^2 at point p of T' by the domain mesh: the polynomial of the domain holding p.
bool mesh_d2(const DomainMesh& m, Vec2 p, double& out) {
    const int f = m.face_at(p);
    if (f < 0 || m.faces()[f].infinite) return false;
    out = m.faces()[f].poly(p);
    return true;
}

// Target t of side 0 solved both ways; adds to `c`, fails the test on a difference.
void compare_target(const VoxelGrid& grid, uint32_t t, const std::string& what, Compared& c) {
    TargetSolver paper(grid, 0, t), lean(grid, 0, t);
    long events = 0;
    paper.on_event([&](const Event&) { ++events; });  // a listener: the paper's insertion
    paper.validate_each_insertion(true);             // thorough, after every insertion
    lean.validate_each_insertion(true);
    try {
        paper.run();
    } catch (const std::logic_error& e) {
        // A fault of the domain mesh itself (README, "Tolerances and degenerate input"), not of the lean
        // insertion: nothing to compare the lean one with.
        ++c.paper_faults;
        std::printf("[ info ] %s: the paper's insertion fails too: %s\n", what.c_str(), e.what());
        return;
    }
    try {
        lean.run();
    } catch (const std::logic_error& e) {
        ADD_FAILURE() << what << ": " << e.what();
        return;
    }
    ASSERT_GT(events, 0);
    const double tol = 1e-9 * std::max(paper.max_sq(), 1e-300) + 4 * (paper.rounding_sq() + lean.rounding_sq());
    EXPECT_NEAR(paper.max_sq(), lean.max_sq(), tol) << what;
    const DomainMesh *mp = paper.domain_mesh(), *ml = lean.domain_mesh();
    if (!mp || !ml) return;  // a sliver target: no domain mesh either way
    c.faces_paper += mp->num_live_faces();
    c.faces_lean += ml->num_live_faces();
    // A barycentric grid over T' (in the frame: the mesh's corners are T''s).
    const auto& v = mp->vertices();
    const Vec2 A = v[0].p, B = v[1].p, C = v[2].p;
    const int n = 24;
    const double unit = paper.frame().scale * paper.frame().scale;
    for (int i = 1; i < n; ++i)
        for (int j = 1; i + j < n; ++j) {
            const Vec2 p = A + (B - A) * (double(i) / n) + (C - A) * (double(j) / n);
            double dp, dl;
            if (!mesh_d2(*mp, p, dp) || !mesh_d2(*ml, p, dl)) continue;
            const double direct = paper.direct_d2(p);
            const double err = std::fabs(dp - dl) / (1 + direct);
            c.worst = std::max(c.worst, err);
            // Both are d^2 up to the domains' rounding (world rounding_sq in frame units).
            EXPECT_LE(std::fabs(dp - dl), 1e-9 * (1 + direct) + 8 * (paper.rounding_sq() + lean.rounding_sq()) / unit)
                << what << " at (" << p.x << ", " << p.y << ")";
            ++c.points;
        }
}

}  // namespace

TEST(Lean, SameDistanceAsThePapersInsertionOnRandomAndRealisticPairs) {
    Compared c;
    std::mt19937 rng(7);
    // Coarse against fine (the case the lean insertion is for): a coarse height field measured
    // against a fine, jittered one of the same surface.
    auto z = [](double x, double y) { return 0.3 * std::sin(2 * x) * std::cos(3 * y); };
    const TriangleMesh coarse = height_field(4, z), fine = jittered(height_field(16, z), 1e-3, 3);
    {
        const VoxelGrid grid(coarse, fine);
        for (uint32_t t = 0; t < coarse.num_triangles(); t += 3) compare_target(grid, t, "coarse target " + std::to_string(t), c);
    }
    // Random soups, and a fine mesh against a coarse one.
    for (int k = 0; k < 4; ++k) {
        const TriangleMesh a = random_triangle_soup(rng, 6, 1.0, {0, 0, 0}, 1.0), b = random_triangle_soup(rng, 30, 0.5, {0, 0, 0}, 1.0);
        const VoxelGrid grid(a, b);
        for (uint32_t t = 0; t < a.num_triangles(); ++t) compare_target(grid, t, "soup " + std::to_string(k) + " target " + std::to_string(t), c);
    }
    {
        const VoxelGrid grid(fine, coarse);
        for (uint32_t t = 0; t < fine.num_triangles(); t += 37) compare_target(grid, t, "fine target " + std::to_string(t), c);
    }
    std::printf("[ info ] %ld points compared, worst relative difference %.3g; live domains: paper %ld, lean %ld; %ld targets "
                "where the paper's insertion itself fails validate()\n", c.points, c.worst, c.faces_paper, c.faces_lean, c.paper_faults);
    EXPECT_GT(c.points, 3000);
}

TEST(Lean, SameDistanceAsThePapersInsertionOnDegeneratePairs) {
    Compared c;
    for (unsigned seed = 0; seed < 60; ++seed) {
        const DegeneratePair P = degenerate_pair(seed);
        const VoxelGrid grid(P.a, P.b);
        const uint32_t n = (uint32_t)P.a.num_triangles();
        for (uint32_t t : {0u, n / 2, n - 1})
            compare_target(grid, t, "seed " + std::to_string(seed) + " (" + P.kind + ") target " + std::to_string(t), c);
    }
    std::printf("[ info ] %ld points compared, worst relative difference %.3g; live domains: paper %ld, lean %ld; %ld targets "
                "where the paper's insertion itself fails validate()\n", c.points, c.worst, c.faces_paper, c.faces_lean, c.paper_faults);
    EXPECT_GT(c.points, 3000);
}
