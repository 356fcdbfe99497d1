// The indexed triangle mesh every part of Hausdorff Lens works on.
// A mesh is its triangles: vertices no triangle uses are not part of the surface, and
// degenerate (zero-area) triangles are still points of it.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "vec.h"

namespace hlens {

using Tri = std::array<uint32_t, 3>;

struct TriangleMesh {
    std::string path;              // where it was read from ("" if built in memory)
    std::vector<Vec3> positions;   // may contain vertices no triangle uses
    std::vector<Tri> triangles;    // indices into positions, all in range

    size_t num_triangles() const { return triangles.size(); }
    std::array<Vec3, 3> corners(size_t t) const {
        const Tri& f = triangles[t];
        return {positions[f[0]], positions[f[1]], positions[f[2]]};
    }
    // Bounding box of the surface: only vertices used by a triangle count.
    Box3 bounds() const {
        Box3 b;
        for (const Tri& f : triangles)
            for (uint32_t i : f) b.add(positions[i]);
        return b;
    }
    Box3 triangle_bounds(size_t t) const {
        Box3 b;
        for (uint32_t i : triangles[t]) b.add(positions[i]);
        return b;
    }
    size_t num_used_vertices() const;
};

inline size_t TriangleMesh::num_used_vertices() const {
    std::vector<char> used(positions.size(), 0);
    size_t n = 0;
    for (const Tri& f : triangles)
        for (uint32_t i : f)
            if (!used[i]) { used[i] = 1; ++n; }
    return n;
}

// Any problem with input: the message names the file and the problem.
struct MeshError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace hlens
