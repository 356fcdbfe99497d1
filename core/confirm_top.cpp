// Confirming the top of the result without the domain meshes (issue 8: the certified interval is a
// promise; design notes, "Certified answer").
//
// A domain mesh's maximum is exact up to where its vertices sit: a crossing within 1e-8 of a vertex
// snaps onto it, and a vertex polished onto two curves may sit 1e-7 off a third. So a maximum at a
// corner of domains can be measured up to ~1e-7 of the target's size away from where it is, and
// come out lower by as much (d(., B) is 1-Lipschitz). Only a target whose value (or bound) lies
// within kReach of its size below the result can hold a larger value; each of those is bounded
// from above here as the cascade bounds pieces, independently of its domain mesh:
//   - for any triangle T of B, d(., T) is convex, so its maximum over a sub-triangle S is at a
//     corner of S: max_S d <= max over the corners of d(., T), T the nearest triangle to S's centre;
//   - d(., B) is 1-Lipschitz: max_S d <= d(c) + r on S's enclosing ball (c, r).
//   - across a seam of B the corner bound overshoots by a corner's distance past the seam, so a
//     sub-triangle is also cut in two pieces (convex polygons), each bounded by its own triangle:
//     any cut is valid, since d(., B) <= d(., T) for every T; a good one makes both bounds tight.
//     Between the centre's nearest triangle T and the worst corner's nearest U, the cut is the
//     plane bisecting their dihedral where they share an edge (coplanar or folded neighbours),
//     else the line where d(., T) = d(., U) on the piece (nearly straight on a small piece), else
//     the plane through T's edge the corner lies beyond (overlapping triangulations). A piece
//     still above the goal is cut again, up to kCuts deep (a fan of triangles round a vertex).
// A sub-triangle whose bound is at most the largest distance measured so far, plus `tol`, is done;
// the others are split in four (a thin one in two, across its longest edge: children) until their
// radius is below `tol`, and the largest bound of those done bounds the result.
// A centre farther than the result is a point the domain mesh missed: the result is raised to it
// and polished by a local search, so the answer is the largest distance actually measured.
// Without the cuts, a seam where d is flat or has a crease needed splitting down to `tol` along
// its whole length; with them, a target stays open (its node budget spent) only on rare ridges
// between triangles that are not neighbours (none of 114,391 targets in 8,000 degenerate pairs
// was left open). An open target is bounded by what its subdivision had (pending_bound) or, where
// lower, by its longest edge's bound plus its height (edge_bound: a needle among tied triangles).
// Distances are taken relative to a corner of the target (an input point): their rounding scales
// with the target's size and the distances, not with the coordinates' magnitude. Far from the
// origin, where the rounding of a world point reaches the tolerance, which triangle is nearest is
// decided relative to that corner too (exact_distance).
#include "confirm_top.h"

#include <algorithm>
#include <cassert>
#include <array>
#include <cmath>
#include <vector>

#include "cascade.h"
#include "cover_bound.h"
#include "point_triangle.h"
#include "split_pattern.h"

namespace hlens {

namespace {

constexpr double kReach = 1e-6;      // of the target's size: its domain mesh's vertex error, with margin
constexpr size_t kPerTarget = 4096;  // sub-triangles per target, and
constexpr size_t kBudget = 65536;    // per confirmation; a target not closed within them stays open
constexpr int kCuts = 8;             // a piece is cut between neighbouring triangles of B at most this deep

using Tri3 = std::array<Vec3, 3>;

// A sub-triangle in the target's barycentric coordinates (u, v: p = u E1 + v E2 from the origin
// corner) and the nearest triangle of B to its parent's centre.
struct Sub {
    std::array<Vec2, 3> uv;
    uint32_t hint;
    double bound = HUGE_VAL;  // its parent's upper bound of d over it (HUGE_VAL: none yet)
};

struct Target {
    Vec3 o, e1, e2;  // corner 0 (an input point) and the two edges from it
    double size;
    bool precise;    // the rounding of world points matters at the tolerance (far from the origin)
    Vec3 at(Vec2 uv) const { return uv.x * e1 + uv.y * e2; }  // relative to o
    // The (u, v) of p (relative to o) on the target, clamped into it: the normal equations of
    // p = u e1 + v e2. False, and (0, 0), for a target without area.
    bool uv_of(const Vec3& p, Vec2& uv) const {
        const double a = dot(e1, e1), b = dot(e1, e2), d = dot(e2, e2), det = a * d - b * b;
        uv = {0, 0};
        if (!(det > 0)) return false;
        uv = {std::max(0.0, (d * dot(p, e1) - b * dot(p, e2)) / det), std::max(0.0, (a * dot(p, e2) - b * dot(p, e1)) / det)};
        if (uv.x + uv.y > 1) uv = uv / (uv.x + uv.y);
        return true;
    }
};

// The distance from o + p to triangle T of B, relative to o: exact rounding-wise up to a few ulps
// of |p| + |T - o|.
double dist_rel(const Vec3& p, const Tri3& T) { return std::sqrt(closest_point_on_triangle(p, T[0], T[1], T[2]).dist2); }

Tri3 relative(const TriangleMesh& B, uint32_t t, const Vec3& o) {
    const auto c = B.corners(t);
    return {c[0] - o, c[1] - o, c[2] - o};
}

// The target's size: its longest edge.
double longest_edge(const std::array<Vec3, 3>& c) { return std::max({norm(c[1] - c[0]), norm(c[2] - c[1]), norm(c[0] - c[2])}); }

// The rounding of one such distance: a few ulps of the magnitudes involved, generously.
double rounding(double size, double d, const Tri3& T) {
    const double m = std::max({norm(T[0]), norm(T[1]), norm(T[2])});
    return 256 * 0x1p-52 * (size + d + m);
}

// d(o + p, T), T the triangle the grid finds nearest to the rounded world point: at least
// d(o + p, B), an upper bound wherever the rounding put the point. `world_d2`: the grid's squared
// distance there.
double measure(const MeshGrid& g, const Target& tg, const Vec3& p, uint32_t& hint, double* world_d2 = nullptr) {
    const MeshGrid::Nearest q = g.nearest(tg.o + p, hint);
    if (q.triangle == UINT32_MAX) return HUGE_VAL;
    hint = q.triangle;
    if (world_d2) *world_d2 = q.dist2;
    return dist_rel(p, relative(g.mesh(), q.triangle, tg.o));
}

// d(o + p, B) to within [d - err, d], rounding relative to |p| and the distances aside. Where
// the world point's rounding (an ulp of the coordinates) matters at the tolerance, every triangle
// within reach of the rounded point o + p (its nearest distance, plus how far the rounding moved
// it) is measured relative to o, and err is 0: the grid alone may take the wrong one of two
// triangles an ulp of the coordinates apart, 1e-9 of the diagonal 1e7 diagonals from the origin.
// Elsewhere the grid's nearest triangle is measured, and err covers its choice (twice the
// rounding). `hint` becomes the triangle at that distance.
double exact_distance(const MeshGrid& g, const Target& tg, const Vec3& p, uint32_t& hint, double& err) {
    double world_d2;
    const double d = measure(g, tg, p, hint, &world_d2);
    if (!(d < HUGE_VAL)) return d;
    const Vec3 w = tg.o + p;
    const double off = 0x1p-52 * (std::fabs(w.x) + std::fabs(w.y) + std::fabs(w.z) + norm(p));
    err = tg.precise ? 0.0 : 2 * off;
    if (!tg.precise) return d;
    return g.distance_relative(tg.o, p, (std::sqrt(world_d2) + 4 * off) * (1 + 1e-12) + g.margin(), &hint);
}

// A convex piece of a sub-triangle, relative to the target's corner.
struct Piece {
    std::array<Vec3, 16> p;
    int n = 0;
};

// The halves of Q on either side of the plane dot(x - a, nrm) = 0. Both halves take the same cut
// points, so together they cover Q up to the cut points' rounding (an ulp of the target's size).
// False if a half would not fit.
bool cut(const Piece& Q, const Vec3& a, const Vec3& nrm, Piece& pos, Piece& neg) {
    pos.n = neg.n = 0;
    for (int i = 0; i < Q.n; ++i) {
        const Vec3 &x = Q.p[i], &y = Q.p[(i + 1) % Q.n];
        const double sx = dot(x - a, nrm), sy = dot(y - a, nrm);
        if (pos.n + 2 > (int)pos.p.size() || neg.n + 2 > (int)neg.p.size()) return false;
        if (sx >= 0) pos.p[pos.n++] = x;
        if (sx <= 0) neg.p[neg.n++] = x;
        if ((sx > 0 && sy < 0) || (sx < 0 && sy > 0)) {
            const Vec3 c = x + (sx / (sx - sy)) * (y - x);
            pos.p[pos.n++] = c;
            neg.p[neg.n++] = c;
        }
    }
    return true;
}

// The plane between triangles T and U of B that share an edge: through the edge, bisecting their
// dihedral angle (for coplanar neighbours, the plane through the edge across their plane). T lies
// on its positive side. False if they share no edge or fold onto each other. A corner repeated in
// U matches its other copy, and an "edge" whose two ends are one corner of U is none: 3 - ui[0] -
// ui[1] read U[3] (ASan, generate_pairs.py "zeroarea" 21: a zero-area triangle with a repeated corner).
bool bisector(const Tri3& T, const Tri3& U, Vec3& a, Vec3& nrm) {
    int ti[2], ui[2], k = 0;
    for (int i = 0; i < 3 && k < 2; ++i)
        for (int j = 0; j < 3; ++j)
            if ((k == 0 || j != ui[0]) && T[i].x == U[j].x && T[i].y == U[j].y && T[i].z == U[j].z) {
                ti[k] = i, ui[k] = j, ++k;
                break;
            }
    if (k < 2) return false;
    assert(ti[0] != ti[1] && ui[0] != ui[1]);
    a = T[ti[0]];
    const Vec3 e = T[ti[1]] - a, p = T[3 - ti[0] - ti[1]] - a, q = U[3 - ui[0] - ui[1]] - a;
    const double ee = dot(e, e);
    const Vec3 m = p - e * (dot(p, e) / ee), n = q - e * (dot(q, e) / ee);
    const double lm = norm(m), ln = norm(n);
    if (!(ee > 0 && lm > 0 && ln > 0)) return false;  // a zero-area neighbour
    nrm = m / lm - n / ln;
    return norm(nrm) > 1e-3;
}

// The plane through the edge of T that x lies beyond (seen along T's normal), across T's plane;
// T lies on its positive side. For a neighbour that overlaps T rather than sharing an edge
// (two triangulations of one surface). False if x projects into T or T has no area.
bool across_edge(const Tri3& T, const Vec3& x, Vec3& a, Vec3& nrm) {
    const Vec3 n = cross(T[1] - T[0], T[2] - T[0]);
    double lowest = 0;
    for (int i = 0; i < 3; ++i) {
        const Vec3 m = cross(n, T[(i + 1) % 3] - T[i]);  // into T
        const double lm = norm(m);
        if (!(lm > 0)) return false;
        const double side = dot(x - T[i], m) / lm;
        if (side < lowest) lowest = side, a = T[i], nrm = m / lm;
    }
    return lowest < 0;
}

// The plane across Q's plane through the two points of Q's boundary where d(., T) = d(., U)
// (bisection on the edges where their difference changes sign, or a corner where it is 0 between
// corners of opposite signs), T on its positive side: where the two are not neighbours, the ridge
// between them is a curve, nearly straight over a small piece. False unless there are exactly two
// such points. (The corners: a box's inner facet is 0.125 from two opposite sides along its
// mid-line x = 3.75, where halving puts sub-triangles' corners; with only the edges' sign changes
// counted, no piece across that line could be cut and the interval stayed 1e-4 wide:
// generate_pairs6.py "box_stack" 58688. Not a 0 between corners of one sign: over coplanar
// triangles that overlap, the difference is 0 on a region, and a line through two of its corners
// cut worse than the plane across_edge takes.)
bool ridge(const Piece& Q, const Tri3& T, const Tri3& U, Vec3& a, Vec3& nrm) {
    auto f = [&](const Vec3& x) { return dist_rel(x, T) - dist_rel(x, U); };
    std::array<double, 16> fv;
    for (int i = 0; i < Q.n; ++i) fv[i] = f(Q.p[i]);
    Vec3 at[2];
    int k = 0;
    for (int i = 0; i < Q.n; ++i) {
        const double fp = fv[(i + Q.n - 1) % Q.n], fn = fv[(i + 1) % Q.n];
        if (fv[i] == 0 && ((fp < 0 && fn > 0) || (fp > 0 && fn < 0))) {
            if (k == 2) return false;
            at[k++] = Q.p[i];
        }
    }
    for (int i = 0; i < Q.n; ++i) {
        Vec3 x = Q.p[i], y = Q.p[(i + 1) % Q.n];
        double fx = fv[i], fy = fv[(i + 1) % Q.n];
        if (!((fx < 0 && fy > 0) || (fx > 0 && fy < 0))) continue;
        if (k == 2) return false;
        // Regula falsi, Illinois variant: the difference is smooth along most edges.
        const double stop = 0x1p-40 * norm(y - x);
        for (int it = 0, last = 0; it < 80 && norm(y - x) > stop; ++it) {
            const Vec3 m = x + (fx / (fx - fy)) * (y - x);
            const double fm = f(m);
            if (fm == 0) { x = y = m; break; }
            if ((fm < 0) == (fx < 0)) {
                x = m, fx = fm;
                if (last == -1) fy *= 0.5;
                last = -1;
            } else {
                y = m, fy = fm;
                if (last == 1) fx *= 0.5;
                last = 1;
            }
        }
        at[k++] = 0.5 * (x + y);
    }
    if (k < 2 || at[0] == at[1]) return false;
    const Vec3 n = cross(Q.p[1] - Q.p[0], Q.p[2] - Q.p[0]), line = at[1] - at[0];
    nrm = cross(n, line);
    const double ln = norm(nrm);
    if (!(ln > 0)) return false;
    nrm = nrm / ln;
    a = at[0];
    for (int i = 0; i < Q.n; ++i)  // orient: T's side (where d(., T) is the smaller) positive
        if (const double side = dot(Q.p[i] - a, nrm); std::fabs(side) > 0) {
            if ((side > 0) != (f(Q.p[i]) < 0)) nrm = -1.0 * nrm;
            break;
        }
    return true;
}

// A sub-triangle measured at its centre: its corners and centre (relative to the target's corner),
// its enclosing radius, the triangle of B nearest the centre and d there (d <= dm + r over it: d is
// 1-Lipschitz), and that distance's rounding (+ the sub-triangles' seams). dm is HUGE_VAL where B
// has no triangle.
struct Probe {
    std::array<Vec3, 3> S;
    Vec2 muv;
    Vec3 m;
    double r;
    uint32_t near;
    double dm;
    Tri3 T;
    double slack;
};
Probe probe(const MeshGrid& g, const Target& tg, const Sub& s) {
    Probe p;
    p.S = {tg.at(s.uv[0]), tg.at(s.uv[1]), tg.at(s.uv[2])};
    p.muv = (s.uv[0] + s.uv[1] + s.uv[2]) / 3.0;
    p.m = tg.at(p.muv);
    p.r = std::max({norm(p.S[0] - p.m), norm(p.S[1] - p.m), norm(p.S[2] - p.m)}) * (1 + 1e-12);
    p.near = s.hint;
    p.dm = measure(g, tg, p.m, p.near);
    p.slack = 0;
    if (p.dm < HUGE_VAL) {
        p.T = relative(g.mesh(), p.near, tg.o);
        p.slack = rounding(tg.size, p.dm, p.T) + 0x1p-46 * tg.size;
    }
    return p;
}

// A point of the target (relative to its corner) and a value d(., B) is certainly at least there.
struct Measured {
    double value = -HUGE_VAL;
    Vec3 p;
};

// An upper bound of d(., B) over the piece Q: d(., T), T = triangle t of B, at Q's corners
// (convexity). Where a corner is farther from T than `goal`, Q is cut between T and the corner's
// nearest triangle U (bisector, ridge or across_edge, in that order) and each half is bounded by
// its own triangle, up to `depth` cuts deep: a sub-triangle across a seam of B (where the corner
// bound alone overshoots by the corner's distance past the seam) closes without splitting it down
// to the tolerance. `slack` gathers the distances' rounding; `seen`, the largest distance measured
// at a corner (the worst corner's, measured to find U): on a ridge between triangles that are not
// neighbours the cut's ends are where d is largest, and d there is what the bound is.
double piece_bound(const MeshGrid& g, const Target& tg, const Piece& Q, uint32_t t, double goal, int depth, double& slack,
                   Measured& seen) {
    Tri3 T = relative(g.mesh(), t, tg.o);
    double worst = -HUGE_VAL;
    int wi = 0;
    for (int i = 0; i < Q.n; ++i) {
        const double d = dist_rel(Q.p[i], T);
        if (d > worst) worst = d, wi = i;
    }
    slack = std::max(slack, rounding(tg.size, worst, T));
    if (worst <= goal || depth == 0) return worst;
    // The triangle nearest the centre may be the worst one for the whole piece: a needle of B
    // lying along a crease is nearest on its line only, and every cut kept it on one side
    // (generate_pairs4.py "cap_sliver" 9260: a cap 1.6e-12 high closing a square bent along its
    // diagonal; two targets across it stayed open). Each corner's nearest triangle is tried too,
    // and the one whose corner bound is least is T.
    double err;
    for (int i = 0; i < Q.n; ++i) {
        uint32_t c = t;
        const double d = exact_distance(g, tg, Q.p[i], c, err);
        if (!(d < HUGE_VAL) || c == t) continue;
        if (d - err > seen.value) seen = {d - err, Q.p[i]};
        const Tri3 C = relative(g.mesh(), c, tg.o);
        double w = -HUGE_VAL;
        int wc = 0;
        for (int k = 0; k < Q.n; ++k)
            if (const double dk = dist_rel(Q.p[k], C); dk > w) w = dk, wc = k;
        if (w < worst) worst = w, wi = wc, t = c, T = C, slack = std::max(slack, rounding(tg.size, w, C));
    }
    if (worst <= goal) return worst;
    uint32_t u = t;  // the worst corner's nearest triangle
    const double at_worst = exact_distance(g, tg, Q.p[wi], u, err);
    if (!(at_worst < HUGE_VAL)) return worst;
    if (at_worst - err > seen.value) seen = {at_worst - err, Q.p[wi]};
    if (u == t) return worst;
    const Tri3 U = relative(g.mesh(), u, tg.o);
    // The first cut that leaves Q's corners on both sides: the bisector of two neighbours folded
    // onto each other may pass beside Q, where U is nearer only past its own edge; that cut gave
    // all of Q back to T, kCuts times over, and the ridge between them was never tried
    // (generate_pairs9.py "tiny_coplanar_retri" 9489, B to A: needles of B folded over a triangle
    // at a hub of corners an ulp apart; a target stayed open, its interval 9.2e-9 of the diagonal).
    Vec3 a, nrm;
    Piece pos, neg;
    bool made = false;
    for (int k = 0; k < 3 && !made; ++k) {
        const bool plane = k == 0 ? bisector(T, U, a, nrm) : k == 1 ? ridge(Q, T, U, a, nrm) : across_edge(T, Q.p[wi], a, nrm);
        made = plane && cut(Q, a, nrm, pos, neg) && pos.n >= 3 && neg.n >= 3;
    }
    if (!made) return worst;
    const double on_t = piece_bound(g, tg, pos, t, goal, depth - 1, slack, seen);
    if (!(on_t <= goal)) return worst;  // this side did not close: the whole piece does not
    const double on_u = piece_bound(g, tg, neg, u, goal, depth - 1, slack, seen);
    return std::min(worst, std::max(on_t, on_u));
}

// A sub-triangle's children (uv), by split_pattern of its corners `S` (relative to the target's):
// four, or two where it is thin.
int children(const Sub& s, const std::array<Vec3, 3>& S, std::array<std::array<Vec2, 3>, 4>& out) {
    const SplitPattern sp = split_pattern(S);
    const Vec2 pt[6] = {s.uv[0], s.uv[1], s.uv[2], 0.5 * (s.uv[0] + s.uv[1]), 0.5 * (s.uv[1] + s.uv[2]),
                        0.5 * (s.uv[2] + s.uv[0])};
    for (int n = 0; n < sp.count; ++n)
        for (int i = 0; i < 3; ++i) out[n][i] = pt[sp.child[n][i]];
    return sp.count;
}

// Whether a world point's rounding (a few ulps of `coord`, the coordinates' magnitude) reaches
// 1e-3 of `tol`.
bool rounding_matters(double coord, double tol) { return 16 * 0x1p-52 * coord > 1e-3 * tol; }

// A local search for the largest distance near uv, inside the target: steps from `h` down to the
// last bit, eight directions each.
Vec2 polish(const MeshGrid& g, const Target& tg, Vec2 uv, double h, double& value) {
    uint32_t hint = UINT32_MAX;
    double err;
    value = exact_distance(g, tg, tg.at(uv), hint, err);
    for (; h > 1e-17; h *= 0.5)
        for (int moves = 0; moves < 64; ++moves) {
            bool moved = false;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy) {
                    const Vec2 q{uv.x + dx * h, uv.y + dy * h};
                    if ((dx == 0 && dy == 0) || q.x < 0 || q.y < 0 || q.x + q.y > 1) continue;
                    const double d = exact_distance(g, tg, tg.at(q), hint, err);
                    if (d > value) { value = d; uv = q; moved = true; }
                }
            if (!moved) break;
        }
    return uv;
}

// An upper bound of d over a target whose subdivision stopped with `stack` left: the bound of the
// sub-triangles done, and each one left by its parent's bound, or by d at its centre plus its
// radius where it has none (the target's own triangle, the run's budget spent before it began).
// Its domain mesh's maximum is no bound: it is exact only up to where its vertices sit, 1e-7 of
// its size (generate_pairs4.py "cap_sliver" 9260: two targets along a crease of A left open,
// their domain meshes' 1.429e-12 where d reaches 1.548e-12 by exact rational arithmetic, and the
// interval's upper end, that value plus 1e-13 of the coordinates, was 1.457e-12).
double pending_bound(const MeshGrid& g, const Target& tg, const std::vector<Sub>& stack, double done) {
    double upper = done;
    for (const Sub& s : stack) {
        double b = s.bound;
        if (!(b < HUGE_VAL)) {
            const Probe p = probe(g, tg, s);
            b = p.dm < HUGE_VAL ? p.dm + p.r + p.slack : HUGE_VAL;
        }
        upper = std::max(upper, b);
    }
    return upper;
}

// An upper bound of d over a thin target from its longest edge, for a target its subdivision left
// open (generate_pairs7.py "prism_axis_needle" 14492: a needle on a prism's axis, where the caps'
// triangles tie; every piece across the tie stayed above the goal, and the pieces left had bounds
// 1e-3 of the needle's length above the truth). Every point of a triangle lies within its height h
// (over its longest edge) of that edge, since the angles at the edge's ends are at most 90 degrees: so
// d <= max over the edge + h (d is 1-Lipschitz). Along a segment d(., T) is convex for every
// triangle T of B: its maximum is at an end. A segment is bounded so by the triangles nearest its
// middle and its ends (each end measured once, as its parent's middle), or by d at its middle plus
// half its length, and split in half until that is within tol of L, or it is shorter than 2 tol;
// at most `budget` segments, what is left bounded by its parent. HUGE_VAL where B has no triangle.
double edge_bound(const MeshGrid& g, const Target& tg, double L, double tol, size_t budget, size_t& nodes) {
    const std::array<Vec2, 3> uv{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}};
    int k = 0;  // the longest edge: uv[k] to uv[k + 1]
    for (int i = 1; i < 3; ++i)
        if (norm(tg.at(uv[(i + 1) % 3]) - tg.at(uv[i])) > norm(tg.at(uv[(k + 1) % 3]) - tg.at(uv[k]))) k = i;
    const Vec3 a = tg.at(uv[k]), e = tg.at(uv[(k + 1) % 3]) - a;
    const double le = norm(e), h = (le > 0 ? norm(cross(tg.e1, tg.e2)) / le * (1 + 1e-12) : 0.0) + 0x1p-46 * tg.size;
    struct Seg {
        double s0, s1;
        uint32_t near0, near1;  // the triangles nearest its ends, as measured there (a parent's middle)
        double bound;
    };
    auto worse = [](const Seg& x, const Seg& y) { return x.bound < y.bound; };
    uint32_t ends[2] = {UINT32_MAX, UINT32_MAX};
    if (!(measure(g, tg, a, ends[0]) < HUGE_VAL)) return HUGE_VAL;  // (B has a triangle: so has every measure below)
    ends[1] = ends[0];
    measure(g, tg, a + e, ends[1]);
    std::vector<Seg> heap{{0.0, 1.0, ends[0], ends[1], HUGE_VAL}};
    double upper = -HUGE_VAL;
    for (size_t used = 0; !heap.empty() && used < budget; ++used, ++nodes) {
        std::pop_heap(heap.begin(), heap.end(), worse);
        const Seg s = heap.back();
        heap.pop_back();
        const Vec3 p0 = a + s.s0 * e, p1 = a + s.s1 * e, m = a + (0.5 * (s.s0 + s.s1)) * e;
        const double half = 0.5 * norm(p1 - p0) * (1 + 1e-12);
        // Far from the origin, the middle's nearest triangle is taken relative to the target's
        // corner (exact_distance): the one nearest the rounded world point may be off the exact
        // point's by the rounding, and so was every bound of a segment at a ridge (generate_pairs9.py
        // "sliver_tiny_on_edge" 20192: a segment target 2.4e-4 long 1.3e7 from the origin, y
        // rounded to 7e-12; the segments left had bounds 2.5e-12 above the distance, 1e-8 of the
        // diagonal).
        uint32_t near = s.near0;
        double err = 0;
        const double dm = tg.precise ? exact_distance(g, tg, m, near, err) : measure(g, tg, m, near);
        double slack = 0x1p-46 * tg.size, u = dm + half;
        slack = std::max(slack, rounding(tg.size, dm, relative(g.mesh(), near, tg.o)));
        for (const uint32_t c : {near, s.near0, s.near1}) {
            const Tri3 T = relative(g.mesh(), c, tg.o);
            const double b = std::max(dist_rel(p0, T), dist_rel(p1, T));
            if (b < u) u = b, slack = std::max(slack, rounding(tg.size, b, T));
        }
        u += slack;
        if (u <= L + tol || !(half > tol)) {
            upper = std::max(upper, u);
            continue;
        }
        const double mid = 0.5 * (s.s0 + s.s1);
        for (const Seg& child : {Seg{s.s0, mid, s.near0, near, u}, Seg{mid, s.s1, near, s.near1, u}}) {
            heap.push_back(child);
            std::push_heap(heap.begin(), heap.end(), worse);
        }
    }
    for (const Seg& s : heap) upper = std::max(upper, s.bound);  // (the first segment's HUGE_VAL when no budget)
    return upper + h;
}

}  // namespace

bool can_reach(const std::array<Vec3, 3>& corners, double bound, double slack, double L) {
    return !(bound + kReach * longest_edge(corners) + slack < L);  // (a NaN bound too)
}

// Kept whole (~70 lines): the subdivision of each target shares the running largest distance, the
// raised witness and the node budgets with the loop over targets.
TopConfirmation confirm_top(const VoxelGrid& grid, int side, const TargetTable& tab, double best, double tol, double coord) {
    const TriangleMesh& A = grid.mesh(side);
    const MeshGrid& g = grid.of(1 - side);
    const TriangleMesh& B = g.mesh();
    TopConfirmation out;
    out.upper = best;
    const bool precise = rounding_matters(coord, tol);
    double L = best;  // the largest distance measured so far
    Vec2 raised_uv;
    double raised_r = 0;
    // The targets that can reach the result, highest first (they get the budget first).
    std::vector<uint32_t> order;
    for (uint32_t t = 0; t < A.num_triangles(); ++t) {
        if (!tab.copy[t] && can_reach(A.corners(t), tab.bound[t], tab.slack[t], L)) order.push_back(t);  // a copy: 0
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return tab.bound[x] > tab.bound[y]; });
    std::vector<Sub> stack;
    for (uint32_t t : order) {
        const auto c = A.corners(t);
        const Target tg{c[0], c[1] - c[0], c[2] - c[0], longest_edge(c), precise};
        if (tab.bound[t] + kReach * tg.size + tab.slack[t] < L) continue;  // L has risen since
        ++out.targets;
        const size_t budget = std::min(out.nodes + kPerTarget, kBudget);
        double target_upper = -HUGE_VAL;
        // Largest bound first: where the budget runs out, what is left is bounded by the least
        // bounds the subdivision had (pending_bound), not by a coarse sibling of a deep path.
        auto worse = [](const Sub& x, const Sub& y) { return x.bound < y.bound; };
        stack.clear();
        stack.push_back({{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, UINT32_MAX});
        while (!stack.empty() && out.nodes < budget) {
            std::pop_heap(stack.begin(), stack.end(), worse);
            const Sub s = stack.back();
            stack.pop_back();
            ++out.nodes;
            const auto [S, muv, m, r, near, dm, T, slack] = probe(g, tg, s);
            if (!(dm < HUGE_VAL)) { out.upper = HUGE_VAL; return out; }  // B has no triangle
            uint32_t nearest = near;  // the centre's nearest triangle without the world point's rounding,
            const bool exact = dm > L + slack;  // known at once where the centre may be farther than L
            double err = 0;
            const double de = exact ? exact_distance(g, tg, m, nearest, err) - err : dm;
            if (exact && de > L + slack) {  // farther than L for certain
                L = de;
                out.raised = true;
                out.target = t;
                out.origin = tg.o;
                raised_uv = muv;
                raised_r = r / std::max(tg.size, 1e-300);
            }
            double u = dm + r;
            if (u > L) u = std::min(u, corner_distance_bound(S, T));
            if (u > L && s.hint != UINT32_MAX && s.hint != near) u = std::min(u, corner_distance_bound(S, relative(B, s.hint, tg.o)));
            double cut_slack = 0;
            if (u + slack > L + tol) {
                if (!exact) exact_distance(g, tg, m, nearest, err);
                Piece Q;
                Q.p[0] = S[0], Q.p[1] = S[1], Q.p[2] = S[2], Q.n = 3;
                Measured seen;
                u = std::min(u, piece_bound(g, tg, Q, nearest, L + 0.5 * tol, kCuts, cut_slack, seen));
                // A corner measured farther than L, for certain: the result rises to it, as to a
                // centre (generate_pairs4.py "subdiv_far" 3329: along a T-junction's seam, 1e-12 wide
                // at coordinates 8.6e3, d peaks on the ridge between two triangles of B that are not
                // neighbours, where no centre falls; each sub-triangle there was bounded by the
                // ridge's true value, above L, down to the budget, and the target stayed open).
                if (seen.value > L + slack) {
                    L = seen.value;
                    out.raised = true;
                    out.target = t;
                    out.origin = tg.o;
                    tg.uv_of(seen.p, raised_uv);
                    raised_r = r / std::max(tg.size, 1e-300);
                }
            }
            if (u + std::max(slack, cut_slack) > L + tol && r > tol) {
                // Over many nearly parallel sources (a fan): bounded from those that cover it.
                double cover_slack = 0;
                const std::array<Vec3, 3> whole{Vec3{0, 0, 0}, tg.e1, tg.e2};
                const double c = cover_bound(g, tg.o, S, L + 0.5 * tol, cover_slack, &whole);
                if (c + cover_slack <= L + tol) u = c, cut_slack = std::max(cut_slack, cover_slack);
            }
            u += std::max(slack, cut_slack);
            if (u <= L + tol || !(r > tol)) {  // done (a NaN radius too)
                target_upper = std::max(target_upper, u);
                continue;
            }
            std::array<std::array<Vec2, 3>, 4> kids;
            const int nk = children(s, S, kids);
            for (int k = 0; k < nk; ++k) {
                stack.push_back({kids[k], near, u});
                std::push_heap(stack.begin(), stack.end(), worse);
            }
        }
        if (stack.empty()) {
            ++out.closed;
            out.upper = std::max(out.upper, target_upper);
        } else {  // not closed within its budget: the bounds it has are its upper end, or, for a
                  // thin target, its longest edge's and its height
            double open = pending_bound(g, tg, stack, target_upper);
            if (out.edge_nodes < kBudget && open > L + tol)
                open = std::min(open, edge_bound(g, tg, L, tol, std::min(kPerTarget, kBudget - out.edge_nodes), out.edge_nodes));
            out.open_upper = std::max(out.open_upper, open);
        }
    }
    out.upper = std::max(out.upper, L);
    out.value = L;
    if (out.raised) {
        const auto c = A.corners(out.target);
        const Target tg{c[0], c[1] - c[0], c[2] - c[0], 0, precise};
        const Vec2 uv = polish(g, tg, raised_uv, std::max(raised_r, 1e-12), out.value);
        out.offset = tg.at(uv);
        out.upper = std::max(out.upper, out.value);
    }
    return out;
}

double longest_edge_bound(const MeshGrid& g, const std::array<Vec3, 3>& target, double L, double tol, double coord) {
    const Target tg{target[0], target[1] - target[0], target[2] - target[0], longest_edge(target), rounding_matters(coord, tol)};
    size_t nodes = 0;
    return edge_bound(g, tg, L, tol, kPerTarget, nodes);
}

bool polish_witness(const VoxelGrid& grid, int side, uint32_t target, const Vec3& point, double value, double tol,
                    double coord, Vec3& origin, Vec3& offset, double& polished) {
    const auto c = grid.mesh(side).corners(target);
    const Target tg{c[0], c[1] - c[0], c[2] - c[0], 0, rounding_matters(coord, tol)};
    Vec2 uv;
    if (!tg.uv_of(point - c[0], uv)) return false;  // a sliver: its slack covers it
    uv = polish(grid.of(1 - side), tg, uv, kReach, polished);
    if (!(polished > value + 256 * 0x1p-52 * (longest_edge(c) + polished))) return false;
    origin = tg.o;
    offset = tg.at(uv);
    return true;
}

}  // namespace hlens
