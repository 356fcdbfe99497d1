// The target's 2D frame and the seven regions of a source triangle projected into it.
//
// Straub 2007 §2, Fig. 1: the plane of T' is divided into the Voronoi regions of T, its edges and
// its corners, R_abc, R_ab, R_bc, R_ca, R_a, R_b, R_c; over each, d_T^2 is one quadratic. Every
// region is an intersection of 3D half-spaces with the plane of T', i.e. of 2D half-planes.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "conic.h"
#include "vec.h"

namespace hlens {

// p(x, y) = origin + scale * (x e1 + y e2). The target's longest edge runs from (0,0) to (1,0) and
// its third corner has y > 0, so the target has unit size and every tolerance is relative.
struct TargetFrame {
    Vec3 origin, e1, e2, normal;
    double scale = 1;
    std::array<Vec2, 3> corners;      // the target's corners in mesh order, in the frame
    std::array<int, 3> ccw_order;     // mesh corner indices in counter-clockwise order
    bool degenerate = false;          // zero (or nearly zero) area: handled as a segment or point
    Vec3 to_world(Vec2 p) const { return origin + (p.x * scale) * e1 + (p.y * scale) * e2; }
    Vec2 to_frame(const Vec3& p) const { Vec3 w = (p - origin) / scale; return {dot(w, e1), dot(w, e2)}; }
    std::array<Vec2, 3> ccw_corners() const { return {corners[ccw_order[0]], corners[ccw_order[1]], corners[ccw_order[2]]}; }
    static TargetFrame make(const std::array<Vec3, 3>& corners);
};

enum class Region : uint8_t { abc = 0, ab, bc, ca, a, b, c };
const char* region_name(Region r);

// The tie rule (same_quadratic) for the quadratics of two features of the kinds `kp` and `kq`.
// A face's quadratic and an edge's (or a corner's) differ by the square of the distance, within
// the face's plane, from the edge: times the square of the plane's tilt from T''s normal, which
// is geometry, not rounding, however small against the quadratics' size. So they tie only to
// 1e-13 relative (their rounding is ~1e-16): a source standing 2e-6 off the vertical with its edge
// 1e-6 under T' has the two 4e-12 apart where d^2 is 5e-6, and with the allowance of 1e-11 the
// face's domain took the edge's polynomial, 3e-7 above d^2 (independent pair 803). A corner's
// quadratic and an edge's through it differ the same way, by the square of the offset along the
// edge, ((p - c).e)^2: an edge standing 1.5e-6 off the vertical whose end lies 1.5e-6 under T'
// has the two 1.6e-12 apart where d^2 is 2e-12, and with 1e-11 the corner's domain kept its
// polynomial, twice d^2, over the edge's region (generate_pairs.py "dupfaces" 13814). So features
// of different dimension tie only to 1e-13. Edges among themselves, corners among themselves and
// faces among themselves keep 1e-11: three corners rounded off a line 1e8 from the origin make
// edges 5e-12 apart, and cutting between them makes conics of noise.
inline int feature_dimension(Region k) { return k == Region::abc ? 2 : k <= Region::ca ? 1 : 0; }
inline bool same_feature_quadratic(const Quadratic2& p, Region kp, const Quadratic2& q, Region kq, double delta) {
    return same_quadratic(p, q, delta, feature_dimension(kp) != feature_dimension(kq) ? 1e-13 : 1e-11);
}

// inside: n.p >= offset. `all` and `none` for boundary planes parallel to the target's plane.
struct HalfPlane {
    Vec2 n;
    double offset = 0;
    enum Kind : uint8_t { Line, All, None } kind = Line;
    bool bevel = false;  // a corner's bevel (regions.cpp): no boundary of the region in exact arithmetic
    Quadratic2 as_quadratic() const { return half_plane(n, offset); }
};

struct SourceRegion {
    Region kind;
    std::vector<HalfPlane> planes;  // the region is their intersection (within the plane)
    Quadratic2 poly;                // d_T^2 over the region, in frame units
};

// How deep p lies in region r, in frame units (the lines' normals are unit): the least margin over
// its lines; +inf where no line bounds it, -inf where a boundary plane parallel to T' leaves
// nothing (the region is empty). The one membership test of the construction, validate() and
// the overlay, each with its own tolerance. Without `bevels`, by the region's lines alone: where
// two lines meet at an angle theta, the construction places the corner only to its tolerance over
// theta, and a bevel's margin there is the distance along the wedge (TargetSolver::validate()).
inline double region_margin(const SourceRegion& r, Vec2 p, bool bevels = true) {
    double m = HUGE_VAL;
    for (const HalfPlane& h : r.planes) {
        if (h.kind == HalfPlane::None) return -HUGE_VAL;
        if (h.kind == HalfPlane::Line && (bevels || !h.bevel)) m = std::min(m, dot(h.n, p) - h.offset);
    }
    return m;
}
// Whether p lies in region r to within `tol` (frame units).
inline bool in_region(const SourceRegion& r, Vec2 p, double tol) { return region_margin(r, p) >= -tol; }

// The regions of one source triangle, in the order they are inserted (vertex, edge, then face
// regions, so the face region is what remains). A degenerate source (a segment or a point) has
// three regions or one.
struct SourceProjection {
    uint32_t source = 0;
    std::vector<SourceRegion> regions;
    bool degenerate = false;
    // How far the corners' frame coordinates may be off by rounding (frame units): 64 ulps of
    // their largest distance from the frame's origin, T' itself having unit size. Quadratics that
    // differ by less than this can make are one polynomial (same_quadratic).
    double delta = 0;
};
// The region of `src` that p lies deepest in (the first of equals): the regions tile the plane.
// Only among the regions of `mask` if given (the number of regions if it has none).
inline size_t deepest_region(const SourceProjection& src, Vec2 p, unsigned mask = ~0u) {
    size_t best = src.regions.size();
    double best_margin = -HUGE_VAL;
    for (size_t k = 0; k < src.regions.size(); ++k) {
        if (!(mask >> k & 1u)) continue;
        const double m = region_margin(src.regions[k], p);
        if (best == src.regions.size() || m > best_margin) best_margin = m, best = k;
    }
    return best;
}
SourceProjection project_source(const TargetFrame& frame, const std::array<Vec3, 3>& source, uint32_t index);
// The same into `out`, reusing its storage.
void project_source(const TargetFrame& frame, const std::array<Vec3, 3>& source, uint32_t index, SourceProjection& out);

// The squared distance, in frame units, from the target point p to the source triangle, computed
// directly in 3D (the independent value every candidate is evaluated with).
double source_distance2(const TargetFrame& frame, const std::array<Vec3, 3>& source, Vec2 p);

// A convex polygon: the target triangle clipped by half-planes (empty if nothing is left).
std::vector<Vec2> clip_convex(std::vector<Vec2> poly, const std::vector<HalfPlane>& planes);
// The same on `poly` itself, with `tmp` as the second buffer (both keep their storage).
void clip_convex_in_place(std::vector<Vec2>& poly, const std::vector<HalfPlane>& planes, std::vector<Vec2>& tmp);

}  // namespace hlens
