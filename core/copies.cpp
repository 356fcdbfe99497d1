// Targets that are copies of source triangles: see copies.h.
#include "copies.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <tuple>
#include <unordered_map>

namespace hlens {

namespace {

// A triangle's corners in lexicographic order: the same key for the same set of corners.
struct Key {
    std::array<Vec3, 3> c;
    bool operator==(const Key& o) const { return c == o.c; }
};

std::array<Vec3, 3> sorted(std::array<Vec3, 3> c) {
    auto less = [](const Vec3& p, const Vec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); };
    std::sort(c.begin(), c.end(), less);
    return c;
}

Key key_of(const std::array<Vec3, 3>& c) { return {sorted(c)}; }

struct KeyHash {
    size_t operator()(const Key& k) const {
        size_t h = 1469598103934665603ull;
        for (const Vec3& p : k.c)
            for (double v : {p.x, p.y, p.z}) {
                v += 0.0;  // -0 and +0 are the same coordinate (and compare equal)
                uint64_t b;
                std::memcpy(&b, &v, sizeof b);
                h = (h ^ b) * 1099511628211ull;
                h ^= h >> 29;
            }
        return h;
    }
};

}  // namespace

bool same_corners(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) { return sorted(a) == sorted(b); }

std::vector<uint8_t> copied_targets(const VoxelGrid& grid, int side, const std::vector<double>& vertex_d2) {
    const TriangleMesh &A = grid.mesh(side), &B = grid.mesh(1 - side);
    Box3 box = A.bounds();
    box.add(B.bounds());
    double coord = 0;
    for (const Vec3& p : {box.lo, box.hi}) coord = std::max({coord, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const double zero = 1e-10 * (coord + box.diagonal()), zero_d2 = zero * zero;
    const size_t n = A.num_triangles();
    std::vector<uint8_t> out(n, 0);
    // Candidates by key; equal triangles of A (duplicated faces) chain through `next`.
    std::unordered_map<Key, uint32_t, KeyHash> first;
    std::vector<uint32_t> next(n, UINT32_MAX);
    for (uint32_t t = 0; t < n; ++t) {
        const Tri& f = A.triangles[t];
        if (vertex_d2[f[0]] > zero_d2 || vertex_d2[f[1]] > zero_d2 || vertex_d2[f[2]] > zero_d2) continue;
        auto [it, fresh] = first.try_emplace(key_of(A.corners(t)), t);
        if (!fresh) {
            next[t] = it->second;
            it->second = t;
        }
    }
    if (first.empty()) return out;
    // Each key's targets are marked once, then the key is dropped: n copies of one triangle in
    // both meshes cost n, not n^2.
    for (size_t s = 0; s < B.num_triangles() && !first.empty(); ++s) {
        const auto it = first.find(key_of(B.corners(s)));
        if (it == first.end()) continue;
        for (uint32_t t = it->second; t != UINT32_MAX; t = next[t]) out[t] = 1;
        first.erase(it);
    }
    return out;
}

}  // namespace hlens
