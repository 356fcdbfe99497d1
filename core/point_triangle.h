// Exact (to rounding) closest point on a triangle, robust for slivers and degenerate triangles.
#pragma once
#include <array>

#include "vec.h"

namespace hlens {

struct ClosestPoint {
    Vec3 point;    // closest point of the triangle (or segment) to the query
    double dist2;  // squared distance from the query to `point`
};

// Closest point of the segment [a,b] to p (a point when a == b).
ClosestPoint closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

// Closest point of the closed triangle abc to p. A triangle whose height is <= 1e-12 of its longest
// edge (|cross|^2 <= 1e-24 * longest^4) is treated as the union of its three edges: the answer is then
// off by at most that height, and collinear or coincident corners are handled exactly.
ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
// The same where p's foot on the plane lies inside the face (true, `out` set); false where the
// closest point is on the boundary or the triangle has no height (the caller then takes the edges).
bool closest_point_inside(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, ClosestPoint& out);

// The largest distance from the corners of s to the closed triangle t (closest_point_on_triangle's):
// d(., t) is convex, so it bounds the distance from every point of the triangle s. The second is
// its square (the first is its square root, to the bit).
double corner_distance_bound(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t);
double corner_distance_bound2(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t);

// A distance from p to the closed triangle abc that the true one is never below (but for a few
// ulps of |p - a| and the edges), for the certified interval's lower end. closest_point_on_triangle
// takes a triangle of height <= 1e-12 of its longest edge as its edges, which is up to that height
// too far. Here the plane is built in long double for any height; where the foot is not clearly
// outside (to a generous bound of its rounding), the lesser of the plane's and the edges' distances
// is taken (the truth is one of them), or the edges' less the height if that is more. Slower than
// closest_point_on_triangle: for a few points, not a search.
double triangle_distance_lower(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace hlens
