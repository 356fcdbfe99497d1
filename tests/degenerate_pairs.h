// Random degenerate mesh pairs (issue 8): coplanar overlapping triangulations, nearly coplanar
// tilted grids, slivers, perpendicular and shared-edge configurations, zero-area and duplicated
// triangles, near-coincident copies; at scales 1e-6 to 1e6 and far from the origin. Deterministic
// for a given seed.
#pragma once
#include <cmath>
#include <random>
#include <string>

#include "test_meshes.h"

namespace hlens_test {

struct DegeneratePair {
    std::string kind;
    TriangleMesh a, b;
};

// A flat n x m grid over [0,1]^2 in the plane z = 0, its interior vertices moved in the plane by up
// to `jitter` of a cell; each quad split along a random diagonal.
inline TriangleMesh flat_grid(std::mt19937& rng, int n, int m, double jitter) {
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<Vec3> p;
    std::vector<Tri> t;
    for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool inner = i > 0 && i < n && j > 0 && j < m;
            p.push_back({(i + (inner ? jitter * U(rng) : 0.0)) / n, (j + (inner ? jitter * U(rng) : 0.0)) / m, 0});
        }
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            if (rng() & 1) t.push_back({a, b, d}), t.push_back({a, d, c});
            else t.push_back({a, b, c}), t.push_back({b, d, c});
        }
    return mesh_of(p, t);
}

// x' = R x * scale + offset for a rotation R about the axis (1, 2, 3) by `angle`.
inline TriangleMesh placed(const TriangleMesh& m, double angle, double scale, const Vec3& offset) {
    const Vec3 k = Vec3{1, 2, 3} / std::sqrt(14.0);
    const double c = std::cos(angle), s = std::sin(angle);
    TriangleMesh out = m;
    for (Vec3& p : out.positions) {
        const Vec3 r = p * c + cross(k, p) * s + k * (dot(k, p) * (1 - c));  // Rodrigues
        p = r * scale + offset;
    }
    return out;
}

inline DegeneratePair degenerate_pair(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    DegeneratePair P;
    const int kind = (int)(seed % 10);
    auto grid = [&](int n, int m, double jitter) { return flat_grid(rng, n, m, jitter); };
    switch (kind) {
        case 0:  // coplanar overlapping triangulations
            P.kind = "coplanar";
            P.a = grid(1 + rng() % 3, 1 + rng() % 3, 0.3);
            P.b = grid(1 + rng() % 4, 1 + rng() % 4, 0.3);
            break;
        case 1: {  // nearly coplanar: B tilted by a tiny angle about the x axis and lifted a little
            P.kind = "nearly coplanar";
            P.a = grid(2 + rng() % 3, 2 + rng() % 3, 0.2);
            P.b = grid(2 + rng() % 3, 2 + rng() % 2, 0.2);
            const double tilt = std::pow(10.0, -9 + 6 * U(rng)), lift = std::pow(10.0, -10 + 6 * U(rng));
            for (Vec3& p : P.b.positions) p.z = tilt * p.y + lift;
            break;
        }
        case 2: {  // slivers and duplicates
            P.kind = "slivers";
            P.a = with_duplicates_and_slivers(grid(3, 2, 0.2), 3, 2, 1e-9);
            P.b = with_duplicates_and_slivers(grid(2, 3, 0.2), 2, 2, 1e-12);
            for (Vec3& p : P.b.positions) p.z += 0.05 * U(rng);
            break;
        }
        case 3: {  // perpendicular: B stands on A along the line y = 0.5
            P.kind = "perpendicular";
            P.a = grid(2 + rng() % 2, 2 + rng() % 2, 0.2);
            P.b = grid(2, 2, 0.2);
            for (Vec3& p : P.b.positions) p = {p.x, 0.5, p.y * 0.5};
            break;
        }
        case 4: {  // shared edge: B is A's grid folded about x = 0.5 by a small or large angle
            P.kind = "shared edge";
            P.a = grid(2, 2, 0.0);
            P.b = grid(2, 2, 0.0);
            const double fold = (rng() & 1) ? 1e-6 * U(rng) : 1.5 * U(rng);
            for (Vec3& p : P.b.positions)
                if (p.x > 0.5) p = {0.5 + (p.x - 0.5) * std::cos(fold), p.y, (p.x - 0.5) * std::sin(fold)};
            break;
        }
        case 5: {  // zero-area triangles: collinear and coincident corners among ordinary ones
            P.kind = "zero area";
            P.a = grid(2, 2, 0.2);
            P.b = grid(2, 1, 0.2);
            for (Vec3& p : P.b.positions) p.z += 0.1 * U(rng);
            for (TriangleMesh* m : {&P.a, &P.b}) {
                const uint32_t n = (uint32_t)m->positions.size();
                const Vec3 u = m->positions[0], v = m->positions[n - 1];
                m->positions.push_back(0.5 * (u + v));
                m->triangles.push_back({0, n - 1, n});   // collinear corners
                m->triangles.push_back({n, n, n});       // one point
            }
            break;
        }
        case 6: {  // near-coincident copy: duplicated triangles, offset along the normal by a hair
            P.kind = "near-coincident";
            P.a = with_duplicates_and_slivers(grid(3, 2, 0.3), 4, 0, 0);
            P.b = P.a;
            const double off = std::pow(10.0, -9 + 6 * U(rng));
            for (Vec3& p : P.b.positions) p.z += off;
            break;
        }
        case 8: {  // overlapping coplanar triangles: B is two triangulations of one square at once
            P.kind = "overlapping coplanar";
            P.a = grid(1 + rng() % 2, 1 + rng() % 2, 0.2);
            TriangleMesh b1 = grid(1 + rng() % 3, 1 + rng() % 2, 0.3), b2 = grid(1 + rng() % 2, 1 + rng() % 3, 0.3);
            const uint32_t n1 = (uint32_t)b1.positions.size();
            for (const Vec3& p : b2.positions) b1.positions.push_back(p + Vec3{0.3, -0.2, 0});
            for (Tri t : b2.triangles) b1.triangles.push_back({t[0] + n1, t[1] + n1, t[2] + n1});
            P.b = b1;
            const double off = (rng() & 1) ? 0.0 : std::pow(10.0, -8 + 7 * U(rng));
            for (Vec3& p : P.a.positions) p.z += off;
            break;
        }
        case 9: {  // tilted grids: both in the plane z = 0.3 x, B a little above and tilted by a hair
            P.kind = "tilted grids";
            P.a = grid(2 + rng() % 3, 2, 0.25);
            P.b = grid(3, 2 + rng() % 3, 0.25);
            const double lift = (rng() & 1) ? 0.0 : std::pow(10.0, -9 + 7 * U(rng)), tilt = (rng() & 1) ? 0.0 : 1e-9;
            for (Vec3& p : P.a.positions) p.z = 0.3 * p.x;
            for (Vec3& p : P.b.positions) p.z = (0.3 + tilt) * p.x + lift;
            break;
        }
        default: {  // a bumpy grid against a finer, slightly offset copy of itself
            P.kind = "fine against coarse";
            P.a = grid(2, 2, 0.0);
            P.b = grid(4, 4, 0.25);
            for (TriangleMesh* m : {&P.a, &P.b})
                for (Vec3& p : m->positions) p.z = 0.02 * std::sin(6 * p.x) * std::cos(5 * p.y);
            for (Vec3& p : P.b.positions) p.z += 1e-4;
            break;
        }
    }
    // Scale 1e-6 .. 1e6, a rotation, and half the time far from the origin (1e5 .. 1e7 sizes away).
    const double scale = std::pow(10.0, -6 + 12 * U(rng)), angle = 6.28 * U(rng);
    const double far = (rng() & 1) ? std::pow(10.0, 5 + 2 * U(rng)) * scale : 0.0;
    const Vec3 offset = Vec3{0.6, -0.7, 0.4} * far;
    P.a = placed(P.a, angle, scale, offset);
    P.b = placed(P.b, angle, scale, offset);
    if (rng() & 1) std::swap(P.a, P.b);
    return P;
}

}  // namespace hlens_test
