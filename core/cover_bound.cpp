// A bound of the distance over a triangle from the nearly parallel triangles that cover it (issue 8:
// the certified interval; design notes, "Certified answer"). See cover_bound.h.
//
// confirm_top.cpp bounds a piece of a target by d(., T) at the piece's corners (convexity), cut
// between neighbouring triangles of B at most kCuts deep. Over a fan of thin coplanar triangles a
// piece lies over dozens of them, and the subdivision needed to close it outruns any budget
// (generate_pairs10.py "fan_thin" 67: 280 of 437 targets left open, the interval's upper end 2.6e-5
// where the distance is 1e-14, 47 s). Here the piece q is seen along its unit normal n:
//   - for each triangle S of B that is not steep to n, a point x whose line x + t n meets S is
//     within |h_S(x)| / |n.n_S| of it (h_S: the signed distance to S's plane), a linear function of
//     x: over the part of q that S covers at most its largest value at that part's corners, b_S
//     (a sliver's plane is uncertain: then the spread of n.(x - S_i) over those corners x and S's
//     corners, along_normal);
//   - the triangles kept (b_S <= goal) cover q along n wherever their projections' union U does.
//     q shrunk by delta on every side (K: convex) lies in U if its centroid does and no edge of U's
//     boundary meets K, since a path from inside U to a point outside crosses that boundary. An edge
//     (by vertex indices) is inside U where kept triangles lie on both its sides: each covers a
//     half-disc of its interior points; a vertex whose edges are all inside is too. Any other edge
//     (a boundary, a T-junction, an overlap, a fold) is inside U where its part in K lies inside
//     other kept triangles; else it is tested: such cases are only left to the subdivision. Which
//     side a triangle lies on must be certain: from its projection, or, for a sliver thinner
//     than the projection's rounding, from its normal (facing);
//   - where a boundary of U crosses K, it may be a crack narrower than the goal (two corners of B
//     a rounding apart where one was meant): the kept triangles grown by w then cover K, each
//     point of K within 1.5 w of U, and the bound adds that (cracks_closed);
//   - a long source S is bounded over its part over q (S clipped to the prism along n over q),
//     not its far corners, where those seem off q by the tilt of n (along_normal_near);
//   - the strip of q outside K is within delta of K but near a corner of angle a, where K's corner
//     lies delta / sin(a / 2) inside, and d is 1-Lipschitz: the bound over q is max b_S plus that;
//   - at a needle's tip that is large (5e-7 of the coordinates for an angle of 3e-8), and the tip's
//     triangle reaching past K's corner is bounded instead by convexity, max over its corners of
//     d(., S) for the one triangle S that makes it least (tip_bound). Needle targets along a seam
//     or a boundary of B had intervals up to 2.6e-5 of the diagonal (generate_pairs11.py
//     "a_needles" 526; generate_pairs6.py "sliver_strip" 58197, 1.8e-7), their pieces' budget
//     spent on tips no subdivision shrinks (delta is the coordinates', not the piece's);
//   - a piece too thin for its own normal (a segment, where a degenerate target's corners
//     coincide) is seen along a well-shaped neighbour's normal instead (thin_cover_bound).
// Everything is relative to o (a corner of the target, an input point): its rounding is that of the
// target's size and the triangles' distance from it, a few ulps of them, below delta (2^-46).
#include "cover_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "point_triangle.h"
#include "regions.h"

namespace hlens {

namespace {

constexpr double kSteep = 0.5;  // |n.n_S| below this: S is left out (its bound would be over twice its distance)

struct Side {
    uint32_t a, b;  // vertex indices, a < b
    int side;       // where the triangle lies seen from a to b in the projection: +1 left, -1 right
    Vec2 pa, pb;
    bool operator<(const Side& o) const { return a != o.a ? a < o.a : b < o.b; }
};

// The triangle p counter-clockwise (its last two corners swapped if it is clockwise).
std::array<Vec2, 3> ccw(std::array<Vec2, 3> p) {
    if (cross(p[1] - p[0], p[2] - p[0]) < 0) std::swap(p[1], p[2]);
    return p;
}

// The inward unit normals of a counter-clockwise triangle's edges, edge i from p[i] to p[i + 1].
std::array<Vec2, 3> inward(const std::array<Vec2, 3>& p) {
    std::array<Vec2, 3> m;
    for (int i = 0; i < 3; ++i) {
        const Vec2 e = p[(i + 1) % 3] - p[i];
        m[i] = Vec2{-e.y, e.x} / norm(e);
    }
    return m;
}

// The part a + t (b - a), t in [t0, t1], of the segment [a, b] in K = {x: dot(x - p[i], m[i]) >=
// delta for each i}; false if it misses K.
bool clip(const Vec2& a, const Vec2& b, const std::array<Vec2, 3>& p, const std::array<Vec2, 3>& m, double delta, double& t0,
          double& t1) {
    t0 = 0, t1 = 1;
    for (int i = 0; i < 3; ++i) {
        const double fa = dot(a - p[i], m[i]) - delta, fb = dot(b - p[i], m[i]) - delta;
        if (fa < 0 && fb < 0) return false;
        if (fa < 0) t0 = std::max(t0, fa / (fa - fb));
        if (fb < 0) t1 = std::min(t1, fa / (fa - fb));
    }
    return t0 <= t1;
}

// Whether the intervals `in` (parts of a segment, as parameters) together hold [t0, t1].
bool holds(std::vector<std::pair<double, double>>& in, double t0, double t1) {
    std::sort(in.begin(), in.end());
    double reached = t0;  // [t0, reached] is covered, up to the point itself
    for (const auto& [s0, s1] : in) {
        if (s0 > reached) break;
        reached = std::max(reached, s1);
        if (reached >= t1) return true;
    }
    return false;
}

// Whether the part [t0, t1] of the segment [a, b] lies in the union of the triangles `kept` (either
// orientation), each shrunk by delta: then none of its points is on the union's boundary, whatever
// the triangles on its own sides. (Generate_pairs9.py "tiny_coplanar_retri" 7793: needles of B
// from a corner to a hub of rounding-sized triangles, one folded over its neighbour by the hub's
// rounding, so both lay on one side of their shared edge; the next needle covers that edge.)
bool covered(const Vec2& a, const Vec2& b, double t0, double t1, const std::vector<std::array<Vec2, 3>>& kept, double delta) {
    std::vector<std::pair<double, double>> in;
    for (const std::array<Vec2, 3>& k : kept) {
        const std::array<Vec2, 3> ps = ccw(k);
        double s0, s1;
        if (clip(a, b, ps, inward(ps), delta, s0, s1)) in.push_back({s0, s1});
    }
    return holds(in, t0, t1);
}

// Whether x lies in the triangle p (either orientation) at least delta inside every edge.
bool inside(const Vec2& x, std::array<Vec2, 3> p, double delta) {
    p = ccw(p);
    const std::array<Vec2, 3> m = inward(p);
    for (int i = 0; i < 3; ++i)
        if (!(dot(x - p[i], m[i]) >= delta)) return false;
    return true;
}

// The triangle s (either orientation) grown by `grow` on every side, as the half-planes that
// clip_convex_in_place takes (regions.cpp).
void grown_half_planes(std::array<Vec2, 3> s, double grow, std::vector<HalfPlane>& out) {
    s = ccw(s);
    const std::array<Vec2, 3> m = inward(s);
    out.resize(3);
    for (int k = 0; k < 3; ++k) out[k] = HalfPlane{m[k], dot(m[k], s[k]) - grow};
}

// The corners (counter-clockwise) of the box [lo, hi] grown by r on every side.
std::vector<Vec2> box_corners(Vec2 lo, Vec2 hi, double r) {
    lo = lo - Vec2{r, r}, hi = hi + Vec2{r, r};
    return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
}

// The triangle s (either orientation) grown by w: its edges moved out by w, and each corner sharper
// than a right angle cut across its bisector at w from it; every point lies within sqrt(2) w of s
// (at a cut corner of angle a, the hexagon's corners lie w / cos(pi / 4 - a / 4) from s's; at
// another, w / sin(a / 2)). As half-planes and as corners (counter-clockwise).
void grown_hexagon(std::array<Vec2, 3> s, double w, std::vector<HalfPlane>& planes, std::vector<Vec2>& corners,
                   std::vector<Vec2>& tmp) {
    s = ccw(s);
    const std::array<Vec2, 3> m = inward(s);
    planes.clear();
    Vec2 lo = s[0], hi = s[0];
    for (int k = 0; k < 3; ++k) {
        planes.push_back(HalfPlane{m[k], dot(m[k], s[k]) - w});
        const Vec2 u = s[(k + 1) % 3] - s[k], v = s[(k + 2) % 3] - s[k];
        const Vec2 b = u / norm(u) + v / norm(v);
        if (dot(u, v) > 0) planes.push_back(HalfPlane{b / norm(b), dot(b, s[k]) / norm(b) - w});
        lo = {std::min(lo.x, s[k].x), std::min(lo.y, s[k].y)}, hi = {std::max(hi.x, s[k].x), std::max(hi.y, s[k].y)};
    }
    corners = box_corners(lo, hi, 2 * w);
    clip_convex_in_place(corners, planes, tmp);
}

// Whether the part [t0, t1] of the segment [a, b] lies in the union of the convex polygons `hexes`
// (as half-planes), each shrunk by delta (covered's test for triangles grown by a crack's width).
bool covered_by(const Vec2& a, const Vec2& b, double t0, double t1, const std::vector<std::vector<HalfPlane>>& hexes,
                double delta) {
    std::vector<std::pair<double, double>> in;
    for (const std::vector<HalfPlane>& h : hexes) {
        double s0 = 0, s1 = 1;
        for (const HalfPlane& p : h) {
            const double fa = dot(p.n, a) - p.offset - delta, fb = dot(p.n, b) - p.offset - delta;
            if (fa < 0 && fb < 0) s0 = 2;
            if (fa < 0 && fb >= 0) s0 = std::max(s0, fa / (fa - fb));
            if (fb < 0 && fa >= 0) s1 = std::min(s1, fa / (fa - fb));
        }
        if (s0 <= s1) in.push_back({s0, s1});
    }
    return holds(in, t0, t1);
}

// How far along n a point x of q is from S where its line meets S, at most, over the points xs: by
// S's plane, h_S(x) / |n.n_S| (linear: largest at a corner of their hull), the normal's rounding
// (an angle of a few ulps of the edges' product over |cross|, large for a sliver) allowed for; or,
// as the point met is a convex combination of S's corners, by the spread of n.x - n.S_i, which
// needs no normal. The lesser of the two.
double along_normal(const std::vector<Vec3>& xs, const std::array<Vec3, 3>& S, const Vec3& n, const Vec3& ns, double ls,
                    double cosine) {
    const double angle = 16 * 0x1p-52 * norm(S[1] - S[0]) * norm(S[2] - S[0]) / ls;
    double by_plane = cosine > 2 * angle ? 0.0 : HUGE_VAL, by_corners = 0;
    for (const Vec3& x : xs) {
        if (by_plane < HUGE_VAL)
            by_plane = std::max(by_plane, (std::fabs(dot(x - S[0], ns)) / ls + angle * norm(x - S[0])) / (cosine - angle));
        for (const Vec3& c : S) by_corners = std::max(by_corners, std::fabs(dot(x - c, n)));
    }
    return std::min(by_plane, by_corners);
}

// The same spread over the part of S that lines along n through q meet, where S reaches far past
// q: the corners ys of S clipped to the prism along n over q's projection pq (counter-clockwise,
// inward unit normals m), grown by `grow` (more than the projections' rounding, so that it holds
// the exact part; the clipped corners are off S by a few ulps of their magnitude, as S's own).
// Seen along a normal tilted by rounding, a needle source's far corners seem that tilt times their
// reach off q, and its own plane is no better known (generate_pairs11.py "slivers_strip" 20287,
// A to B: a needle of B 1 long and 6.9e-9 wide, pieces 3e-6 across; its far corners seemed 1e-8
// off q where the goal was 8e-11, and the target stayed open, its interval 1.1e-6 of the diagonal).
double along_normal_near(const std::vector<Vec3>& xs, const std::array<Vec3, 3>& S, const Vec3& n, const Vec3& e1,
                         const Vec3& e2, const std::array<Vec2, 3>& pq, const std::array<Vec2, 3>& m, double grow,
                         std::vector<Vec3>& ys, std::vector<Vec3>& tmp) {
    ys.assign(S.begin(), S.end());
    for (int i = 0; i < 3 && !ys.empty(); ++i) {
        auto f = [&](const Vec3& y) { return dot(Vec2{dot(y, e1), dot(y, e2)} - pq[i], m[i]) + grow; };
        tmp.clear();
        for (size_t k = 0; k < ys.size(); ++k) {
            const Vec3 &a = ys[k], &b = ys[(k + 1) % ys.size()];
            const double fa = f(a), fb = f(b);
            if (fa >= 0) tmp.push_back(a);
            if ((fa >= 0) != (fb >= 0)) tmp.push_back(a + (fa / (fa - fb)) * (b - a));
        }
        ys.swap(tmp);
    }
    if (ys.empty()) return HUGE_VAL;  // only by rounding: S's part was found to meet q's
    double spread = 0;
    for (const Vec3& x : xs)
        for (const Vec3& y : ys) spread = std::max(spread, std::fabs(dot(x - y, n)));
    return spread;
}

// Whether the orientation of the triangle c (input corners) seen along the unit vector n is
// certain from its normal, where its projection is thinner than the projected corners' rounding
// (generate_pairs6.py "sliver_strip" 63741: a sliver of A 1.5e-2 wide at one end and 8e4 long,
// 2e5 from the target's corner, between two triangles of a coplanar strip: left out, it left a gap
// in their union, and the sliver target over it stayed open, its interval 5.8e-9 of the diagonal).
// In long double: the edges (input differences, off by an ulp at most), each component of their
// cross product (off by 4 ulps of its two products' magnitudes at most) and its component along n
// (off by that along n, and 3 ulps of its terms); its sign is certain where it is above twice
// that bound (65541: a sliver 9.4e-12 wide and 12.8 long, its cross product 4.6e-13, where a few
// ulps of the edges' product, 163, was 5.8e-13; its two products, 0.63 each, cancel exactly). S
// not steep to n, as elsewhere. `orient`: +1 counter-clockwise.
bool facing(const std::array<Vec3, 3>& c, const Vec3& n, int& orient) {
    using LD = long double;
    const LD u = std::numeric_limits<LD>::epsilon();
    LD a[3], b[3];
    for (int i = 0; i < 3; ++i) a[i] = (LD)c[1][i] - c[0][i], b[i] = (LD)c[2][i] - c[0][i];
    LD along = 0, err = 0, terms = 0, len2 = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const LD ns = a[j] * b[k] - a[k] * b[j];
        along += n[i] * ns;
        err += std::fabs((LD)n[i]) * 4 * u * (std::fabs(a[j] * b[k]) + std::fabs(a[k] * b[j]));
        terms += std::fabs(n[i] * ns);
        len2 += ns * ns;
    }
    err += 3 * u * terms;
    if (!(std::fabs(along) >= kSteep * std::sqrt(len2) && std::fabs(along) > 2 * err)) return false;
    orient = along > 0 ? 1 : -1;
    return true;
}

// The triangles of g's mesh listed in the voxels of o + q, each once.
std::vector<uint32_t> triangles_near(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q) {
    std::vector<uint32_t> near;
    for (size_t v : g.voxels_of_triangle({o + q[0], o + q[1], o + q[2]})) near.insert(near.end(), g.begin(v), g.end(v));
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
}

// A bound of d over the part of q within `reach` of its corner i (a needle's tip, where K's corner
// lies `reach` inside), or HUGE_VAL: that part lies in the triangle Z of q's corner and the points
// reach / cos(a / 2) along its edges, and d(., S) is convex, so the least over the triangles S
// near q of the largest d(., S) at Z's corners bounds it. Past `reach` from the corner a point of
// the strip outside K is within delta of K: its foot on K's edge lies beyond K's corner. `m`: the
// magnitude of the triangle used (the distances' rounding).
double tip_bound(const std::vector<uint32_t>& near, const TriangleMesh& B, const Vec3& o, const std::array<Vec3, 3>& q, int i,
                 double reach, double& m) {
    const Vec3 &c = q[i], &a = q[(i + 1) % 3], &b = q[(i + 2) % 3];
    const double la = norm(a - c), lb = norm(b - c);
    const double half_cos = 0.5 * norm((a - c) / la + (b - c) / lb);  // cos(a / 2)
    const double r = 1.01 * reach / half_cos;  // (1.01: the directions' rounding, generously)
    if (!(r < 0.5 * std::min(la, lb))) return HUGE_VAL;
    const std::array<Vec3, 3> Z{c, c + (r / la) * (a - c), c + (r / lb) * (b - c)};
    double best = HUGE_VAL;
    for (uint32_t t : near) {
        const auto k = B.corners(t);
        const std::array<Vec3, 3> S{k[0] - o, k[1] - o, k[2] - o};
        if (const double worst = corner_distance_bound(Z, S); worst < best) best = worst, m = std::max({norm(S[0]), norm(S[1]), norm(S[2])});
    }
    return best;
}

double cover_bound_of(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q, Vec3 n, double goal, double& slack,
                      double crack = 0);

// q too thin for its own normal (a segment where a degenerate target's corners coincide, or a
// needle whose normal's rounding, over its length, reaches the goal): bounded over the triangle
// on its longest edge ab, 1e-4 of ab's length wide to one side or the other, seen along the normal
// of the best-shaped triangle of B not steep to ab among those nearest ab's middle (within 1e-3 of
// ab's length of the nearest; a sliver's normal is as uncertain as q's, and seen along it every
// source's distance would be), plus the third corner's distance from ab: every point of q lies
// within that of ab, which that triangle contains. (Generate_pairs6.py "sliver_strip" 58161:
// segment targets 24 long across a fan of slivers, their intervals 2.9e-9 of the diagonal.)
double thin_cover_bound(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q, double goal, double& slack) {
    int i = 0;
    for (int k = 1; k < 3; ++k)
        if (norm(q[(k + 1) % 3] - q[k]) > norm(q[(i + 1) % 3] - q[i])) i = k;
    const Vec3 &a = q[i], &b = q[(i + 1) % 3], &c = q[(i + 2) % 3];
    const double l = norm(b - a);
    if (!(l > 0)) return HUGE_VAL;
    const Vec3 e = (b - a) / l, mid = 0.5 * (a + b);
    const double off = norm((c - a) - dot(c - a, e) * e);
    std::vector<std::pair<double, Vec3>> cands;  // (distance from ab's middle, unit normal times shape)
    double nearest = HUGE_VAL;
    for (uint32_t t : triangles_near(g, o, q)) {
        const auto k = g.mesh().corners(t);
        const std::array<Vec3, 3> S{k[0] - o, k[1] - o, k[2] - o};
        const Vec3 n = cross(S[1] - S[0], S[2] - S[0]);
        const double ln = norm(n);
        if (!(ln > 0) || !(std::fabs(dot(n, e)) <= 0.5 * ln)) continue;
        const double d = std::sqrt(closest_point_on_triangle(mid, S[0], S[1], S[2]).dist2);
        cands.push_back({d, n / (norm(S[1] - S[0]) * norm(S[2] - S[0]))});
        nearest = std::min(nearest, d);
    }
    Vec3 ns;
    double best = 0;
    for (const auto& [d, n] : cands)
        if (d <= nearest + 1e-3 * l && norm(n) > best) best = norm(n), ns = n / best;
    if (!(best > 0)) return HUGE_VAL;
    const Vec3 w = cross(ns, e) / norm(cross(ns, e));
    double bound = HUGE_VAL;
    for (double side : {1.0, -1.0}) {
        double s = 0;
        const double b1 = cover_bound_of(g, o, {a, b, mid + (side * 1e-4 * l) * w}, ns, goal, s);
        if (b1 < bound) bound = b1, slack = s;
        if (bound <= goal) break;
    }
    return bound + off;
}

}  // namespace

double cover_bound(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q, double goal, double& slack,
                   const std::array<Vec3, 3>* whole) {
    // q is seen along the normal of `whole` where given: a small piece's corners are known to an
    // ulp of the whole's size, so its own normal is off by about that over its size, and a long
    // source's far corners seen along it move by as much (generate_pairs9.py "tiny_coplanar_retri"
    // 7793: needles of B 1.5e-3 long, pieces 1e-10 across them, the bound 2.6e-13 where the goal was
    // 1.9e-13 and every corner is within 3.2e-14 of the plane; the target's subdivision stayed open).
    // Where that does not close q, q's own normal is tried too (a needle target's normal is no
    // better known than its piece's: generate_pairs3.py "needle_fan" 60975, B to A, the interval
    // went from 1.9e-10 to 3.1e-9 of the diagonal along the whole's alone).
    const double lq = std::max({norm(q[1] - q[0]), norm(q[2] - q[0]), norm(q[2] - q[1])});
    bool uncertain = false;  // seen along a normal whose rounding over q's length reaches the goal
    double bound = HUGE_VAL;
    for (const std::array<Vec3, 3>* w : {whole, &q}) {
        if (!w || (bound <= goal)) continue;
        const Vec3 nw = cross((*w)[1] - (*w)[0], (*w)[2] - (*w)[0]);
        const double la = norm((*w)[1] - (*w)[0]), lb = norm((*w)[2] - (*w)[0]), lw = norm(nw);
        double s = 0;
        const double b = lw > 0 ? cover_bound_of(g, o, q, nw / lw, goal, s) : HUGE_VAL;
        if (b < bound) bound = b, slack = s;
        uncertain = uncertain || !(16 * 0x1p-52 * la * lb * lq <= 1e-3 * goal * lw);
    }
    // Seen along a normal whose rounding (an angle, as along_normal's) over q's length reaches the
    // goal, the sources' distances along it are that uncertain: the thin bound may do better. So
    // it may for q thinner than the goal: seen along a needle target's normal, which its corners'
    // rounding tilts from the sources' common plane (by 1e-9 rad for a needle 1e-9 wide at
    // coordinates 1e-2), a needle source's far corners seem that tilt times their reach off q,
    // and its own plane is no better known (generate_pairs6.py "sliver_strip" 65109, B to A:
    // 7e-12 where the goal was 1.8e-12; the needle target stayed open, its interval 9.4e-9 of the
    // diagonal). The thin bound is at least q's height.
    const double height = norm(cross(q[1] - q[0], q[2] - q[0])) / lq;
    if (bound <= goal || !(uncertain || height < goal)) return bound;
    double thin_slack = 0;
    const double thin = thin_cover_bound(g, o, q, goal, thin_slack);
    if (thin < bound) bound = thin, slack = thin_slack;
    return bound;
}

namespace {

// Whether no boundary of U (the kept triangles' projections, with their edges `sides`) meets K
// (q's projection pq shrunk by delta; m: its inward normals): each edge has kept triangles on
// both its sides, or lies outside K, or inside other kept triangles there. Else `open` is one that
// does not.
bool edges_inside(std::vector<Side>& sides, const std::vector<std::array<Vec2, 3>>& kept, const std::array<Vec2, 3>& pq,
                  const std::array<Vec2, 3>& m, double delta, Side& open) {
    std::sort(sides.begin(), sides.end());
    for (size_t i = 0, j; i < sides.size(); i = j) {
        bool left = false, right = false;
        for (j = i; j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b; ++j)
            (sides[j].side > 0 ? left : right) = true;
        if (left && right) continue;  // inside U
        for (size_t k = i; k < j; ++k) {
            double t0, t1;
            if (clip(sides[k].pa, sides[k].pb, pq, m, delta, t0, t1) && !covered(sides[k].pa, sides[k].pb, t0, t1, kept, delta)) {
                open = sides[k];
                return false;
            }
        }
    }
    return true;
}

// Whether the union of the kept triangles grown by `reach` may cover K beyond the edge `open`
// (a boundary of their union through K): false where the point 2 reach past its part in K's middle
// lies in K and in none of them (then the triangles grown by less, cracks_closed's, leave it out:
// a gap, not a crack; on real pairs, most often where the sources steep to n are left out).
bool crack_beside(const Side& open, const std::vector<std::array<Vec2, 3>>& kept, const std::array<Vec2, 3>& pq,
                  const std::array<Vec2, 3>& m, double delta, double reach) {
    double t0, t1;
    if (!clip(open.pa, open.pb, pq, m, delta, t0, t1)) return true;
    const Vec2 d = open.pb - open.pa;
    const Vec2 x = open.pa + (0.5 * (t0 + t1)) * d - (open.side * 2 * reach / norm(d)) * Vec2{-d.y, d.x};
    if (!inside(x, pq, delta)) return true;
    for (const std::array<Vec2, 3>& k : kept)
        if (inside(x, k, -reach)) return true;
    return false;
}

// Whether K (q's projection pq shrunk by delta; m: its inward normals) lies in the union of the
// kept triangles each grown by `crack` (grown_hexagon): the union's boundary lies on the hexagons'
// edges, and an edge's part in K inside another hexagon (shrunk by delta) is not on it. A kept
// sliver thinner than its projection's rounding is left out (its edges' directions are noise):
// the union only shrinks. K's centroid lies in the union (tested by the caller on the triangles).
bool cracks_closed(const std::vector<std::array<Vec2, 3>>& kept, const std::vector<bool>& projected, double crack,
                   const std::array<Vec2, 3>& pq, const std::array<Vec2, 3>& m, double delta) {
    std::vector<std::vector<HalfPlane>> hexes;
    std::vector<std::vector<Vec2>> corners;
    std::vector<Vec2> tmp;
    for (size_t i = 0; i < kept.size(); ++i) {
        if (!projected[i]) continue;
        hexes.emplace_back(), corners.emplace_back();
        grown_hexagon(kept[i], crack, hexes.back(), corners.back(), tmp);
    }
    for (const std::vector<Vec2>& c : corners)
        for (size_t k = 0; k < c.size(); ++k) {
            const Vec2 &a = c[k], &b = c[(k + 1) % c.size()];
            double t0, t1;
            if (clip(a, b, pq, m, delta, t0, t1) && !covered_by(a, b, t0, t1, hexes, delta)) return false;
        }
    return true;
}

// q seen along the unit vector n (its normal, or thin_cover_bound's): the bound is taken over the
// plane through q[0] normal to n, each point of q lying on the line along n of its projection
// there, within `tilt` of it (0 but for rounding where n is q's normal).
double cover_bound_of(const MeshGrid& g, const Vec3& o, const std::array<Vec3, 3>& q, Vec3 n, double goal, double& slack,
                      double crack) {
    const TriangleMesh& B = g.mesh();
    Vec3 e1 = (q[1] - q[0]) - dot(q[1] - q[0], n) * n;
    const double l1 = norm(e1);
    if (!(l1 > 0)) return HUGE_VAL;
    e1 = e1 / l1;
    Vec3 e2 = cross(n, e1);
    if (dot(cross(q[1] - q[0], q[2] - q[0]), n) < 0) n = -1.0 * n, e2 = -1.0 * e2;  // q counter-clockwise seen along n
    const double tilt = std::max(std::fabs(dot(q[1] - q[0], n)), std::fabs(dot(q[2] - q[0], n)));
    auto P = [&](const Vec3& x) { return Vec2{dot(x, e1), dot(x, e2)}; };
    const std::array<Vec2, 3> pq{P(q[0]), P(q[1]), P(q[2])};
    if (!(cross(pq[1] - pq[0], pq[2] - pq[0]) > 0)) return HUGE_VAL;
    Vec2 lo = pq[0], hi = pq[0];
    for (const Vec2& p : pq) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    double M = std::max({norm(q[0]), norm(q[1]), norm(q[2])});

    const std::vector<uint32_t> near = triangles_near(g, o, q);

    std::vector<std::array<Vec2, 3>> kept;
    std::vector<bool> kept_projected;
    std::vector<Side> sides;
    std::vector<HalfPlane> planes;
    std::vector<Vec2> part, tmp;
    std::vector<Vec3> xs, ys, tmp3;
    const std::array<Vec2, 3> mq = inward(pq);
    const double reach = 1.5 * crack;  // a triangle grown by the crack's width, its points' distance (grown_hexagon)
    double bound = -HUGE_VAL;
    for (uint32_t t : near) {
        const auto c = B.corners(t);
        const std::array<Vec3, 3> S{c[0] - o, c[1] - o, c[2] - o};
        const Vec3 ns = cross(S[1] - S[0], S[2] - S[0]);
        const double ls = norm(ns);
        if (!(ls > 0)) continue;
        const double cosine = std::fabs(dot(n, ns)) / ls;
        if (!(cosine >= kSteep)) continue;
        const std::array<Vec2, 3> ps{P(S[0]), P(S[1]), P(S[2])};
        if (std::max({ps[0].x, ps[1].x, ps[2].x}) < lo.x || std::min({ps[0].x, ps[1].x, ps[2].x}) > hi.x ||
            std::max({ps[0].y, ps[1].y, ps[2].y}) < lo.y || std::min({ps[0].y, ps[1].y, ps[2].y}) > hi.y)
            continue;  // beside q: not needed to cover it
        // Its orientation decides which side of its edges it covers: it must be certain. The
        // projected corners are off by a few ulps of their magnitude m, the doubled area by
        // a few ulps of m times the edges; a sliver 1e-12 wide between two triangles is kept.
        const double area2 = cross(ps[1] - ps[0], ps[2] - ps[0]);
        const double m = std::max({norm(S[0]), norm(S[1]), norm(S[2])});
        const bool projected = std::fabs(area2) > 0x1p-46 * m * (norm(ps[1] - ps[0]) + norm(ps[2] - ps[0]));
        int orient = area2 > 0 ? 1 : -1;
        if (!projected && !facing(c, n, orient)) continue;
        // S bounds d only where it covers q: over q's part within S (grown by more than the
        // projections' rounding, so that it holds the exact part), back in q's plane. One that
        // misses q has no edge through q's shrunk part either. Where S's projection is thinner
        // than its rounding, the part is not known: all of q is taken (a larger bound).
        part.assign(pq.begin(), pq.end());
        const double grow = 0x1p-46 * std::max(M, m);  // more than the projections' rounding
        if (reach > 0) {  // q's part within S, q grown by reach (the points a crack's width away)
            part = box_corners(lo, hi, 2 * (reach + grow));
            grown_half_planes(pq, reach + grow, planes);
            clip_convex_in_place(part, planes, tmp);
        }
        if (projected) {
            grown_half_planes(ps, grow, planes);
            clip_convex_in_place(part, planes, tmp);
            if (part.empty()) continue;
        }
        xs.clear();
        for (const Vec2& x : part) xs.push_back(q[0] + (x.x - pq[0].x) * e1 + (x.y - pq[0].y) * e2);
        double b = along_normal(xs, S, n, ns, ls, cosine);
        if (!(b <= goal)) b = std::min(b, along_normal_near(xs, S, n, e1, e2, pq, mq, grow + reach, ys, tmp3));
        if (!(b <= goal)) continue;
        bound = std::max(bound, b);
        M = std::max(M, m);
        kept.push_back(ps);
        kept_projected.push_back(projected);
        const Tri& f = B.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            Side s{f[i], f[j], orient, ps[i], ps[j]};
            if (s.a > s.b) std::swap(s.a, s.b), std::swap(s.pa, s.pb), s.side = -s.side;
            sides.push_back(s);
        }
    }
    if (kept.empty()) return HUGE_VAL;

    const double delta = 0x1p-46 * M;  // 16 times the projected corners' rounding
    const std::array<Vec2, 3> m = inward(pq);
    // A point of K in U: the centroid, or halfway from it to a corner (a needle along a seam of U
    // has its centroid on the seam, in no triangle for certain).
    const Vec2 centre = (pq[0] + pq[1] + pq[2]) / 3.0;
    bool in_u = false;
    for (int i = -1; i < 3 && !in_u; ++i) {
        const Vec2 x = i < 0 ? centre : 0.5 * (centre + pq[i]);
        if (!inside(x, pq, delta)) continue;
        for (size_t k = 0; k < kept.size() && !in_u; ++k) in_u = kept_projected[k] && inside(x, kept[k], delta);
    }
    if (!in_u) return HUGE_VAL;
    // A boundary of U through K: a gap, or a crack narrower than the goal between triangles meant
    // to meet (two corners a rounding apart where one was meant). The kept triangles grown by a
    // share of the room left may close it (cracks_closed); a point of K is then within that
    // growth of U, and the bound adds it.
    Side open{};
    if (crack > 0 ? !cracks_closed(kept, kept_projected, crack, pq, m, delta) : !edges_inside(sides, kept, pq, m, delta, open)) {
        const double next = 0.25 * (goal - bound);
        if (crack > 0 || !(next > 0) || !crack_beside(open, kept, pq, m, delta, 1.5 * next)) return HUGE_VAL;
        return cover_bound_of(g, o, q, n, goal, slack, next);
    }
    // The strip outside K: at corner i (angle a), K's corner lies delta / sin(a / 2) inside, and
    // elsewhere a point of the strip is within delta of K. A needle's tip is bounded instead.
    double strip = delta, tips = -HUGE_VAL, tip_m = 0;
    for (int i = 0; i < 3; ++i) {
        const Vec2 u = (pq[(i + 1) % 3] - pq[i]) / norm(pq[(i + 1) % 3] - pq[i]), w = (pq[(i + 2) % 3] - pq[i]) / norm(pq[(i + 2) % 3] - pq[i]);
        const double half_sine = 0.5 * norm(u - w);  // sin(a / 2), also where cos(a) rounds to 1
        if (!(half_sine > 0)) return HUGE_VAL;
        const double at_corner = delta / half_sine;
        if (at_corner > 2 * delta) {
            double m_tip = 0;
            const double tip = tip_bound(near, B, o, q, i, at_corner, m_tip);
            if (tip < bound + at_corner) {
                tips = std::max(tips, tip), tip_m = std::max(tip_m, m_tip);
                continue;
            }
        }
        strip = std::max(strip, at_corner);
    }
    slack = 256 * 0x1p-52 * (std::max(bound, tips) + 2 * std::max(M, tip_m));
    return std::max(bound + strip + (reach > 0 ? reach + delta : 0), tips) + tilt;
}

}  // namespace

}  // namespace hlens
