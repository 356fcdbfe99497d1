// Mesh generators shared by the core tests: random soups, height fields, degenerate configurations,
// perturbed and simplified copies. Deterministic for a given seed.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <hlens/mesh_io.h>
#include <hlens/point_triangle.h>

namespace hlens_test {

using namespace hlens;

inline TriangleMesh mesh_of(std::vector<Vec3> p, std::vector<Tri> t) { return make_mesh(std::move(p), std::move(t), "test"); }

// The distance from p to the mesh B by brute force over all of its triangles (an oracle).
inline double brute_distance(const Vec3& p, const TriangleMesh& B) {
    double best = HUGE_VAL;
    for (size_t t = 0; t < B.num_triangles(); ++t) {
        const auto c = B.corners(t);
        best = std::min(best, closest_point_on_triangle(p, c[0], c[1], c[2]).dist2);
    }
    return std::sqrt(best);
}

inline TriangleMesh random_triangle_soup(std::mt19937& rng, int n, double size, Vec3 centre, double spread) {
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<Vec3> p;
    std::vector<Tri> t;
    for (int i = 0; i < n; ++i) {
        Vec3 c = centre + Vec3{spread * U(rng), spread * U(rng), spread * U(rng)};
        for (int k = 0; k < 3; ++k) p.push_back(c + Vec3{size * U(rng), size * U(rng), size * U(rng)});
        t.push_back({(uint32_t)(3 * i), (uint32_t)(3 * i + 1), (uint32_t)(3 * i + 2)});
    }
    return mesh_of(p, t);
}

// A height field over [-1,1]^2 with n x n quads: shared edges and vertices everywhere.
inline TriangleMesh height_field(int n, std::function<double(double, double)> z) {
    std::vector<Vec3> p;
    std::vector<Tri> t;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
            p.push_back({x, y, z(x, y)});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            t.push_back({a, b, d});
            t.push_back({a, d, c});
        }
    return mesh_of(p, t);
}

// A strip of slivers (thin triangles 1e-6 wide in y) along n chords of the circle of radius r about
// (0, 0, cz) in the plane y = 0, over `span` radians either side of its lowest point (a vertex there
// when n is even). Seen from inside the circle, d is largest below the centre.
inline TriangleMesh sliver_arc(int n, double r, double cz, double span) {
    std::vector<Vec3> p;
    std::vector<Tri> t;
    for (int i = 0; i <= n; ++i) {
        const double a = -M_PI / 2 - span + 2 * span * i / n;
        p.push_back({r * std::cos(a), 0, cz + r * std::sin(a)});
        p.push_back({r * std::cos(a), 1e-6, cz + r * std::sin(a)});
    }
    for (uint32_t i = 0; i < (uint32_t)n; ++i) t.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    return mesh_of(p, t);
}

// Every used vertex moved by a random offset of up to `amplitude` in each coordinate.
inline TriangleMesh jittered(const TriangleMesh& m, double amplitude, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    TriangleMesh out = m;
    for (Vec3& p : out.positions) p += Vec3{U(rng), U(rng), U(rng)} * amplitude;
    return out;
}

// Both meshes moved by the same offset (far from the origin when it is large).
inline TriangleMesh shifted(const TriangleMesh& m, const Vec3& by) {
    TriangleMesh out = m;
    for (Vec3& p : out.positions) p += by;
    return out;
}

// A copy with every k-th triangle duplicated and one triangle in `slivers` squashed to a sliver
// (its third corner moved onto the line of the other two, up to `height`).
inline TriangleMesh with_duplicates_and_slivers(const TriangleMesh& m, int k, int slivers, double height) {
    TriangleMesh out = m;
    for (size_t t = 0; t < m.num_triangles(); t += (size_t)k) out.triangles.push_back(m.triangles[t]);
    for (size_t t = 0; slivers > 0 && t < out.num_triangles(); t += out.num_triangles() / (size_t)slivers) {
        Tri f = out.triangles[t];
        Vec3 a = out.positions[f[0]], b = out.positions[f[1]];
        Vec3 mid = 0.5 * (a + b) + Vec3{0, 0, height};
        out.positions.push_back(mid);
        out.triangles[t][2] = (uint32_t)out.positions.size() - 1;
    }
    return out;
}

}  // namespace hlens_test
