// Quadratic polynomials in the plane of a target, the conics they define, and conic arcs.
//
// Straub 2007 §2-3.1: the squared distance to every feature of a source triangle, restricted to
// the plane of T', is a quadratic q(x, y); two domains meet where q1 - q2 = 0, a conic. We keep
// every arc as a rational quadratic curve p(z) = N(z) / w(z) on an interval of z, whatever its
// kind, so that substituting it into a quadratic gives a quartic and its maxima a quintic
// (design notes, "Where the maximum is").
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "poly.h"
#include "vec.h"

namespace hlens {

// A closed interval, for conservative bounds of a quadratic over a box.
struct Interval {
    double lo, hi;
    Interval operator+(const Interval& o) const { return {lo + o.lo, hi + o.hi}; }
    Interval operator*(double s) const { return s >= 0 ? Interval{lo * s, hi * s} : Interval{hi * s, lo * s}; }
    Interval operator*(const Interval& o) const {
        double p[4] = {lo * o.lo, lo * o.hi, hi * o.lo, hi * o.hi};
        return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
    }
};
inline Interval sq(const Interval& x) {
    if (x.lo >= 0) return {x.lo * x.lo, x.hi * x.hi};
    if (x.hi <= 0) return {x.hi * x.hi, x.lo * x.lo};
    return {0, std::max(x.lo * x.lo, x.hi * x.hi)};
}

// q(x,y) = a x^2 + 2 b x y + c y^2 + 2 d x + 2 e y + f
struct Quadratic2 {
    double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0;
    double operator()(Vec2 p) const {
        return a * p.x * p.x + 2 * b * p.x * p.y + c * p.y * p.y + 2 * d * p.x + 2 * e * p.y + f;
    }
    Vec2 gradient(Vec2 p) const { return {2 * (a * p.x + b * p.y + d), 2 * (b * p.x + c * p.y + e)}; }
    Quadratic2 operator-(const Quadratic2& o) const { return {a - o.a, b - o.b, c - o.c, d - o.d, e - o.e, f - o.f}; }
    Quadratic2 operator*(double s) const { return {a * s, b * s, c * s, d * s, e * s, f * s}; }
    double scale() const {  // largest coefficient magnitude (the first of equals, as std::max({...}))
        double s = std::fabs(a);
        s = std::max(s, std::fabs(b));
        s = std::max(s, std::fabs(c));
        s = std::max(s, std::fabs(d));
        s = std::max(s, std::fabs(e));
        return std::max(s, std::fabs(f));
    }
    Interval range(Vec2 lo, Vec2 hi) const;  // contains q over the box [lo, hi]
    // Where q's gradient vanishes, if its quadratic part is definite (a c > b^2): false otherwise.
    bool centre(Vec2& x) const {
        const double det = a * c - b * b;
        if (!(det > 0)) return false;
        x = {(b * e - c * d) / det, (b * d - a * e) / det};
        return true;
    }
    bool is_linear() const { return a == 0 && b == 0 && c == 0; }
    double quad_scale() const { return std::max({std::fabs(a), std::fabs(b), std::fabs(c)}); }  // of the quadratic part
    // The quadratic part's eigenvalues, the larger in magnitude as l1, and their unit eigenvectors.
    void principal_axes(double& l1, double& l2, Vec2& e1, Vec2& e2) const {
        const double theta = 0.5 * std::atan2(2 * b, a - c);
        e1 = {std::cos(theta), std::sin(theta)}, e2 = {-e1.y, e1.x};
        auto quad = [&](Vec2 v) { return a * v.x * v.x + 2 * b * v.x * v.y + c * v.y * v.y; };
        l1 = quad(e1), l2 = quad(e2);
        if (std::fabs(l2) > std::fabs(l1)) std::swap(l1, l2), std::swap(e1, e2);
    }
    std::string to_string() const;
};

// Two quadratics are the same polynomial up to rounding (coplanar sources, shared edges).
inline bool same_polynomial(const Quadratic2& p, const Quadratic2& q, double rel = 1e-11) {
    double s = std::max(p.scale(), q.scale());
    return (p - q).scale() <= rel * std::max(s, 1e-300);
}

// The tie rule: two quadratics are one polynomial when they differ by no more than their rounding
// can make, for inputs known to within `delta` (frame units): relatively `rel` (1e-11), or
// absolutely 2 sqrt(s) delta + delta^2 for coefficients of size s (a squared distance h^2 whose h
// is off by delta is off by that). Coplanar sources' quadratics at height ~0 differ by noise far
// below 1e-11 of themselves; distinct ones (heights differing by more than delta) never tie.
// Between features of different dimension (a face's quadratic and an edge's or a corner's, an
// edge's and a corner's) the relative allowance is 1e-13 (same_feature_quadratic in regions.h).
//
// The relative allowance is of the coefficients' size, not of the values: two squared distances
// whose least values over T' are far below their coefficients may differ by 1e-11 of those while
// one is many times the other where they are least. Edges parallel to T' along one line of T' at
// heights 2.8e-6 and 5e-14 (frame units) have quadratics 8e-12 apart everywhere, 0.9e-11 of their
// size, while d^2 is 6e-7 over much of T' (generate_pairs3.py "parallel_edge" 1079): with the tie a
// domain kept the higher edge's polynomial, 1.3e-5 relative above d^2. So quadratics tie by the
// relative allowance only if their least values over T' ([0, 1]^2 holds it) agree as closely as a
// domain's polynomial must agree with d^2 (1e-7 relative, TargetSolver::validate), or within the
// absolute allowance: then no tie puts a polynomial farther from d^2 where it is least than that.
double min_on_unit_square(const Quadratic2& q);
// The absolute allowance: how far rounding can move a quadratic whose coefficients are of size s
// and whose inputs are known to within delta (a height h off by delta puts h^2 off by this).
inline double rounding_allowance(double s, double delta) { return 2 * std::sqrt(s) * delta + delta * delta; }
inline bool same_quadratic(const Quadratic2& p, const Quadratic2& q, double delta, double rel = 1e-11) {
    const double s = std::max(p.scale(), q.scale()), d = (p - q).scale();
    const double absolute = rounding_allowance(s, delta);
    if (d <= absolute) return true;
    if (!(d <= rel * s)) return false;
    const double mp = min_on_unit_square(p), mq = min_on_unit_square(q);
    return std::fabs(mp - mq) <= 1e-7 * std::min(mp, mq) + absolute;
}

// A bound of |q| where |x|, |y| <= 1 (over T' in its frame): what two quadratics the tie rule
// made one may differ by there.
inline double unit_box_bound(const Quadratic2& q) {
    return std::fabs(q.a) + 2 * std::fabs(q.b) + std::fabs(q.c) + 2 * std::fabs(q.d) + 2 * std::fabs(q.e) + std::fabs(q.f);
}

// The line n.x = offset as a linear quadratic (f >= 0 on the side n points to).
Quadratic2 half_plane(Vec2 n, double offset);
// The least and greatest values of q(o + t u) for t in [lo, hi] (a quadratic A t^2 + B t + C in t:
// at the ends, and at its vertex where that lies between them and is of the kind asked for).
Interval range_along(const Quadratic2& q, Vec2 o, Vec2 u, double lo, double hi);

// p(z) = (n0 + n1 z + n2 z^2) / (w0 + w1 z + w2 z^2); w > 0 on the arcs we build.
struct RationalCurve {
    Vec2 n0, n1, n2;
    double w0 = 1, w1 = 0, w2 = 0;
    Vec2 operator()(double z) const {
        if (w0 == 1 && w1 == 0 && w2 == 0) return n0 + z * (n1 + z * n2);  // w = 1 exactly: x / 1 == x
        double w = w0 + z * (w1 + z * w2);
        return (n0 + z * (n1 + z * n2)) / w;
    }
    Vec2 derivative(double z) const;
    // q(p(z)) * w(z)^2, a polynomial of degree <= 4 with the sign of q(p(z)).
    Poly compose(const Quadratic2& q) const;
    Poly weight() const;
    bool straight() const { return n2.x == 0 && n2.y == 0 && w1 == 0 && w2 == 0; }
};

// The segment from a (z = 0) to b (z = 1), and the line through them (unit normal, a's side).
inline RationalCurve segment_curve(Vec2 a, Vec2 b) {
    RationalCurve c;
    c.n0 = a;
    c.n1 = b - a;
    return c;
}
inline Quadratic2 line_through(Vec2 a, Vec2 b) {
    Vec2 n = perp(b - a);
    const double l = norm(n);
    if (l > 0) n = n / l;
    return half_plane(n, dot(n, a));
}

enum class CurveKind { Line, Ellipse, Hyperbola, Parabola };
const char* curve_kind_name(CurveKind k);

// One connected component of a conic (or a line), with a global parameter t:
//   Line      p = c + t u            Parabola  p = c + t u + t^2 v
//   Ellipse   p = c + u cos t + v sin t        (periodic, u ⟂ v)
//   Hyperbola p = c + u cosh t + v sinh t      (one branch, u ⟂ v)
struct CurveComponent {
    CurveKind kind = CurveKind::Line;
    Vec2 c, u, v;
    Vec2 at(double t) const;
    double param_of(Vec2 p) const;  // parameter of (the foot of) a point on the curve
    // Every parameter where the curve passes p (its feet, nearest first; a thin conic may pass
    // within 1e-7 of p on both of its sides): 1 to 3 of them.
    int feet(Vec2 p, double (&out)[3]) const;
    // The piece [t0, t1] as one or more rational arcs with well-conditioned weights (an ellipse
    // piece spans at most pi per arc, a hyperbola piece at most 3 in t); returns the z-intervals.
    struct Piece { RationalCurve curve; double z0, z1; };
    std::vector<Piece> pieces(double t0, double t1) const;
    void pieces(double t0, double t1, std::vector<Piece>& out) const;  // the same into `out`
    bool closed() const { return kind == CurveKind::Ellipse; }
private:
    double nearer_foot(Vec2 p, double t) const;  // t moved to the foot of p (param_of)
};

// What q = 0 looks like, for display and for the debugger's hover text.
enum class ConicType { Empty, Point, DoubleLine, Line, ParallelLines, LinePair, Ellipse, Hyperbola, Parabola, Everything };
const char* conic_type_name(ConicType t);

struct ConicDecomposition {
    ConicType type = ConicType::Empty;
    std::vector<CurveComponent> components;  // the zero set where q changes sign
};

// Decompose q = 0 into curve components. Zero sets across which q does not change sign (a double
// line, a single point) have no components: they never separate a positive from a negative part.
ConicDecomposition decompose_conic(const Quadratic2& q);
// The same, reusing `out`; `l2_rounding` (in q's units) bounds the rounding of q's quadratic part's
// smaller eigenvalue where the caller knows it (q a difference of quadratics: an ulp of theirs).
void decompose_conic(const Quadratic2& q, ConicDecomposition& out, double l2_rounding = 0);
// The line through `point` along `dir` as decompose_conic gives its lines (unit direction, anchored
// at the foot of the origin, which keeps parameters small).
CurveComponent line_component(Vec2 point, Vec2 dir);

}  // namespace hlens
