#include "point_triangle.h"

#include <algorithm>
#include <cmath>

namespace hlens {

ClosestPoint closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    Vec3 ab = b - a;
    double l2 = norm2(ab);
    const Vec3 w = p - a;
    double t = l2 > 0 ? dot(w, ab) / l2 : 0.0;
    if (t <= 0) return {a, norm2(w)};  // ends exactly, never a rounded a + 1*ab
    if (t >= 1) return {b, norm2(p - b)};
    // The distance from differences (w - t ab), not from the rounded world point a + t ab, which
    // would be off by an ulp of the coordinates (far from the origin, far more than the distance's).
    return {a + ab * t, norm2(w - ab * t)};
}

static ClosestPoint min_over_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    ClosestPoint r = closest_point_on_segment(p, a, b);
    ClosestPoint s = closest_point_on_segment(p, b, c);
    if (s.dist2 < r.dist2) r = s;
    s = closest_point_on_segment(p, c, a);
    if (s.dist2 < r.dist2) r = s;
    return r;
}

// Why not Ericson's region test: its barycentric numerators are differences of products of size
// |edge|^2 |p-a|^2, so on a sliver (height h << edge L) the face coordinates lose a factor (L/h)^2 of
// precision. Here the plane is spanned by the longest edge e and the re-orthogonalised height vector g,
// which keeps every error at about eps * (L + |p-a|) absolute, whatever the shape.
namespace {
// The corners relabelled so that r[0] -> r[1] is the longest edge and r[2] the opposite corner.
void longest_edge_first(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3* r[3]) {
    const double lab = norm2(b0 - a0), lbc = norm2(c0 - b0), lca = norm2(a0 - c0);
    r[0] = &a0, r[1] = &b0, r[2] = &c0;
    if (lbc >= lab && lbc >= lca) r[0] = &b0, r[1] = &c0, r[2] = &a0;
    else if (lca >= lab && lca >= lbc) r[0] = &c0, r[1] = &a0, r[2] = &b0;
}

enum class Foot { Inside, Outside, NoHeight };
// Where p's foot on the triangle's plane falls. Inside: `out` is the foot and its distance.
// NoHeight (height <= 1e-12 of the longest edge, or one point): `r` holds the corners relabelled
// so that r[0] -> r[1] is the longest edge.
Foot face_foot(const Vec3& p, const Vec3& a0, const Vec3& b0, const Vec3& c0, ClosestPoint& out, const Vec3* r[3]) {
    longest_edge_first(a0, b0, c0, r);
    const Vec3 *a = r[0], *b = r[1], *c = r[2];
    Vec3 e = *b - *a;
    double L2 = norm2(e);
    if (L2 == 0) return Foot::NoHeight;  // all three corners coincide
    Vec3 f = *c - *a;
    Vec3 g = f - e * (dot(f, e) / L2);
    g -= e * (dot(g, e) / L2);  // second Gram-Schmidt pass: "twice is enough" for orthogonality
    double H2 = norm2(g);
    if (H2 <= 1e-24 * L2) return Foot::NoHeight;  // |e x f|^2 = L2*H2 <= 1e-24 L^4

    Vec3 ue = e / std::sqrt(L2), ug = g / std::sqrt(H2), n = cross(ue, ug);
    Vec3 w = p - *a;
    double x = dot(w, ue), y = dot(w, ug);               // p's in-plane coordinates
    double bx = std::sqrt(L2), cx = dot(f, ue), cy = dot(f, ug);  // a = (0,0), b = (bx,0), c = (cx,cy), cy > 0
    bool inside = y >= 0 && (cx - bx) * (y) - (cy) * (x - bx) >= 0 && (-cx) * (y - cy) - (-cy) * (x - cx) >= 0;
    if (!inside) return Foot::Outside;
    double z = dot(w, n);
    out = {*a + ue * x + ug * y, z * z};
    return Foot::Inside;
}
}  // namespace

ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a0, const Vec3& b0, const Vec3& c0) {
    ClosestPoint out{};
    const Vec3* r[3];
    switch (face_foot(p, a0, b0, c0, out, r)) {
        case Foot::Inside: return out;
        case Foot::NoHeight: return min_over_edges(p, *r[0], *r[1], *r[2]);  // (one point: its distance)
        case Foot::Outside: break;
    }
    return min_over_edges(p, a0, b0, c0);  // the closest point is then on the boundary
}

bool closest_point_inside(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, ClosestPoint& out) {
    const Vec3* r[3];
    return face_foot(p, a, b, c, out, r) == Foot::Inside;
}

double corner_distance_bound2(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t) {
    double d2 = 0;
    for (const Vec3& p : s) d2 = std::max(d2, closest_point_on_triangle(p, t[0], t[1], t[2]).dist2);
    return d2;
}

// sqrt is monotone and correctly rounded: the root of the largest square is the largest root.
double corner_distance_bound(const std::array<Vec3, 3>& s, const std::array<Vec3, 3>& t) {
    return std::sqrt(corner_distance_bound2(s, t));
}

double triangle_distance_lower(const Vec3& p, const Vec3& a0, const Vec3& b0, const Vec3& c0) {
    using LD = long double;
    struct V {
        LD x, y, z;
        V operator-(const V& o) const { return {x - o.x, y - o.y, z - o.z}; }
        V operator*(LD s) const { return {x * s, y * s, z * s}; }
    };
    auto dot = [](const V& u, const V& v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
    // Differences of doubles, exact in long double's 64 bits unless their exponents differ by more
    // than 11 (then to 2^-64 of the larger, which the allowances below cover).
    auto sub = [](const Vec3& u, const Vec3& v) { return V{(LD)u.x - v.x, (LD)u.y - v.y, (LD)u.z - v.z}; };
    const double edges = std::sqrt(min_over_edges(p, a0, b0, c0).dist2);
    const Vec3* r[3];  // a -> b the longest edge, as face_foot has it
    longest_edge_first(a0, b0, c0, r);
    const Vec3 &a = *r[0], &b = *r[1], &c = *r[2];
    const V e = sub(b, a), f = sub(c, a), w = sub(p, a);
    const LD L2 = dot(e, e);
    if (L2 == 0) return edges;  // one point
    V g = f - e * (dot(f, e) / L2);
    g = g - e * (dot(g, e) / L2);
    const LD L = std::sqrt(L2), H = std::sqrt(dot(g, g)), W = std::sqrt(dot(w, w));
    const LD ulp = 0x1p-63L * (L + W);  // the rounding of the differences and of g, absolute
    // Every point of the triangle lies within H of its longest edge (the opposite corner's foot is
    // on that edge: the angles beside the longest edge are not obtuse): one bound, loose by H.
    const double near_edge = std::max(0.0L, edges - H - 4 * ulp);
    if (!(H > 1e-30L * L)) return near_edge;
    const V ue = e * (1 / L), ug = g * (1 / H);
    const V n{ue.y * ug.z - ue.z * ug.y, ue.z * ug.x - ue.x * ug.z, ue.x * ug.y - ue.y * ug.x};
    const LD x = dot(w, ue), y = dot(w, ug), z = std::fabs(dot(w, n));
    const LD bx = L, cx = dot(f, ue), cy = dot(f, ug);  // a = (0,0), b = (bx,0), c = (cx,cy), cy > 0
    // The foot's signed distances inside the three edges' lines. The frame (ue, ug, n) is
    // orthonormal to an ulp, and the coordinates of b, c and p in it are those of a triangle and a
    // point moved by a few ulps of the sizes, however thin the triangle (g's direction may be off
    // by ulp / H, but the corners' and p's coordinates are taken in the same frame): the decision
    // is that triangle's, within `margin` of an edge either side's.
    const LD s0 = y, s1 = ((cx - bx) * y - cy * (x - bx)) / std::hypot(cx - bx, cy),
             s2 = (cx * (cy - y) - cy * (cx - x)) / std::hypot(cx, cy);
    const LD margin = 16 * ulp;
    if (std::min({s0, s1, s2}) <= -margin) return edges;  // outside: the nearest point is on an edge
    // The true distance is the plane's (the foot inside) or the edges'. The lesser of the two is a
    // bound, and so is near_edge: the larger of these.
    const double plane = std::max(0.0L, z - 8 * ulp);
    return std::max(std::min(plane, edges), near_edge);
}

}  // namespace hlens
