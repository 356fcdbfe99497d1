#include "conic.h"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace hlens {

Interval Quadratic2::range(Vec2 lo, Vec2 hi) const {
    Interval x{lo.x, hi.x}, y{lo.y, hi.y};
    Interval r = sq(x) * a + (x * y) * (2 * b) + sq(y) * c + x * (2 * d) + y * (2 * e);
    r.lo += f;
    r.hi += f;
    // widen by rounding of the evaluation
    double m = 1e-14 * (scale() * (1 + norm2(lo) + norm2(hi)));
    return {r.lo - m, r.hi + m};
}


// The least value of q over [0, 1]^2 (at least 0: the quadratics compared are squared distances),
// from the points where it can be: the corners, the least point along each side, and the centre
// if q is convex there. Each candidate is a value of q, so a rounded centre errs upwards only.
double min_on_unit_square(const Quadratic2& q) {
    double m = std::min({q({0, 0}), q({1, 0}), q({0, 1}), q({1, 1})});
    for (double s : {0.0, 1.0}) {
        if (q.c > 0) {  // x = s: c y^2 + 2 (b s + e) y + ...
            const double y = -(q.b * s + q.e) / q.c;
            if (y > 0 && y < 1) m = std::min(m, q({s, y}));
        }
        if (q.a > 0) {  // y = s
            const double x = -(q.b * s + q.d) / q.a;
            if (x > 0 && x < 1) m = std::min(m, q({x, s}));
        }
    }
    if (Vec2 x; q.a > 0 && q.centre(x) && x.x > 0 && x.x < 1 && x.y > 0 && x.y < 1) m = std::min(m, q(x));
    return std::max(m, 0.0);
}

std::string Quadratic2::to_string() const {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.9g x^2 %+.9g xy %+.9g y^2 %+.9g x %+.9g y %+.9g", a, 2 * b, c, 2 * d, 2 * e, f);
    return buf;
}


Interval range_along(const Quadratic2& q, Vec2 o, Vec2 u, double lo, double hi) {
    const double A = q.a * u.x * u.x + 2 * q.b * u.x * u.y + q.c * u.y * u.y, B = dot(q.gradient(o), u), C = q(o);
    auto at = [&](double t) { return (A * t + B) * t + C; };
    const double vlo = at(lo), vhi = at(hi);
    Interval r{std::min(vlo, vhi), std::max(vlo, vhi)};
    if (A != 0) {
        const double t = -B / (2 * A);
        if (t > lo && t < hi) {
            if (A < 0) r.hi = std::max(r.hi, at(t));
            else r.lo = std::min(r.lo, at(t));
        }
    }
    return r;
}

Quadratic2 half_plane(Vec2 n, double offset) {
    Quadratic2 q;
    q.d = 0.5 * n.x;
    q.e = 0.5 * n.y;
    q.f = -offset;
    return q;
}

Vec2 RationalCurve::derivative(double z) const {
    double w = w0 + z * (w1 + z * w2), dw = w1 + 2 * z * w2;
    Vec2 N = n0 + z * (n1 + z * n2), dN = n1 + 2 * z * n2;
    return (dN * w - N * dw) / (w * w);
}

Poly RationalCurve::weight() const {
    Poly w;
    w.deg = 2;
    w.c[0] = w0; w.c[1] = w1; w.c[2] = w2;
    return w;
}

Poly RationalCurve::compose(const Quadratic2& q) const {
    if (straight() && w0 == 1) {  // most arcs: q(n0 + z n1) directly
        Poly r;
        r.deg = 4;
        r.c[2] = q.a * n1.x * n1.x + 2 * q.b * n1.x * n1.y + q.c * n1.y * n1.y;
        r.c[1] = 2 * (q.a * n0.x * n1.x + q.b * (n0.x * n1.y + n0.y * n1.x) + q.c * n0.y * n1.y + q.d * n1.x + q.e * n1.y);
        r.c[0] = q(n0);
        return r;
    }
    // q.a X^2 + 2 q.b X Y + q.c Y^2 + 2 q.d X W + 2 q.e Y W + q.f W^2 for the quadratics X, Y, W
    // (the numerators and the weight), written out: the same operations in the same order as
    // the Poly arithmetic it replaces (products summed from 0 by increasing i, then j; the six
    // terms scaled, then added left to right), so the same bits, without the temporaries.
    const double X[3] = {n0.x, n1.x, n2.x}, Y[3] = {n0.y, n1.y, n2.y}, W[3] = {w0, w1, w2};
    auto mul = [](const double* a, const double* b, double* r) {
        r[0] = 0.0 + a[0] * b[0];
        r[1] = (0.0 + a[0] * b[1]) + a[1] * b[0];
        r[2] = ((0.0 + a[0] * b[2]) + a[1] * b[1]) + a[2] * b[0];
        r[3] = (0.0 + a[1] * b[2]) + a[2] * b[1];
        r[4] = 0.0 + a[2] * b[2];
    };
    double XX[5], XY[5], YY[5], XW[5], YW[5], WW[5];
    mul(X, X, XX); mul(X, Y, XY); mul(Y, Y, YY); mul(X, W, XW); mul(Y, W, YW); mul(W, W, WW);
    const double sa = q.a, sb = 2 * q.b, sc = q.c, sd = 2 * q.d, se = 2 * q.e, sf = q.f;
    Poly r;
    r.deg = 4;
    for (int i = 0; i < 5; ++i)
        r.c[i] = ((((XX[i] * sa + XY[i] * sb) + YY[i] * sc) + XW[i] * sd) + YW[i] * se) + WW[i] * sf;
    return r;
}

const char* curve_kind_name(CurveKind k) {
    switch (k) {
        case CurveKind::Line: return "line";
        case CurveKind::Ellipse: return "ellipse";
        case CurveKind::Hyperbola: return "hyperbola";
        case CurveKind::Parabola: return "parabola";
    }
    return "?";
}

const char* conic_type_name(ConicType t) {
    switch (t) {
        case ConicType::Empty: return "empty";
        case ConicType::Point: return "point";
        case ConicType::DoubleLine: return "double line";
        case ConicType::Line: return "line";
        case ConicType::ParallelLines: return "parallel lines";
        case ConicType::LinePair: return "line pair";
        case ConicType::Ellipse: return "ellipse";
        case ConicType::Hyperbola: return "hyperbola";
        case ConicType::Parabola: return "parabola";
        case ConicType::Everything: return "everything";
    }
    return "?";
}

Vec2 CurveComponent::at(double t) const {
    switch (kind) {
        case CurveKind::Line: return c + t * u;
        case CurveKind::Parabola: return c + t * u + (t * t) * v;
        case CurveKind::Ellipse: return c + std::cos(t) * u + std::sin(t) * v;
        case CurveKind::Hyperbola: return c + std::cosh(t) * u + std::sinh(t) * v;
    }
    return c;
}

double CurveComponent::param_of(Vec2 p) const {
    double t[3];
    feet(p, t);
    return t[0];
}

// A thin conic (an ellipse or a branch 1e-6 wide and of T''s length, as the difference of an
// edge's quadratic and a nearly parallel plane's is) runs mostly along one of its axes: a
// parameter read off the other coordinate is off by 1e-4 for a point 1e-10 off the curve
// (degenerate pair "mirror" 3994: a vertex on the branch taken 1e-4 away from it, no chord along
// the sliver, the edge's domain lost). So each side's parameter is read off both coordinates,
// the nearer point kept and polished (nearer_foot). Both sides of a thin conic may pass within
// 1e-7 of p (a corner at a hairpin's tip): every such foot is returned.
int CurveComponent::feet(Vec2 p, double (&out)[3]) const {
    const Vec2 w = p - c;
    double cand[3][2];  // per side, the parameter read off either coordinate
    int n = 0;
    switch (kind) {
        case CurveKind::Line: out[0] = dot(w, u) / norm2(u); return 1;
        case CurveKind::Parabola: {
            // Anchored away from the vertex (see decompose_conic), w.u = t |u|^2 + t^2 v.u: its
            // root near w.u / |u|^2; the curve runs nearly along u there.
            const double W = dot(w, u), uu = norm2(u), uv = dot(u, v);
            if (!(std::fabs(uv) <= 1e-9 * std::sqrt(uu) * norm(v))) {
                const double disc = uu * uu + 4 * uv * W;
                out[0] = disc > 0 ? 2 * W / (uu + std::sqrt(disc)) : W / uu;
                return 1;
            }
            // At the vertex (u perpendicular to v): the arms t and -t at p's coordinate along v.
            const double tu = W / uu, tv = std::sqrt(std::max(0.0, dot(w, v) / norm2(v)));
            cand[0][0] = tu, cand[0][1] = std::copysign(tv, W), cand[1][0] = cand[1][1] = -std::copysign(tv, W);
            n = 2;
            break;
        }
        case CurveKind::Ellipse: {
            // The sides theta, -theta (about u) and pi - theta (about v), theta read off the
            // angle and off the coordinate along the longer axis: near the tip of a thin ellipse
            // the angle is off by the point's offset over the short axis, and from the tip, where
            // the distance is locally largest, Newton cannot leave (generate_pairs.py "tjunction"
            // 18728: a vertex on an ellipse 3.6e-6 wide given a foot 5e-6 away, an arc's ends off
            // its vertices, two faces overlapping).
            const double X = dot(w, u) / norm2(u), Y = dot(w, v) / norm2(v), th = std::atan2(Y, X);
            double ta;  // only the longer axis's coordinate is read: one inverse function
            if (norm2(v) > norm2(u)) {
                const double sy = std::asin(std::clamp(Y, -1.0, 1.0));
                ta = X >= 0 ? sy : M_PI - sy;
            } else {
                ta = std::copysign(std::acos(std::clamp(X, -1.0, 1.0)), Y);
            }
            cand[0][0] = th, cand[0][1] = std::remainder(ta, 2 * M_PI);
            cand[1][0] = -th, cand[1][1] = std::remainder(-ta, 2 * M_PI);
            cand[2][0] = std::remainder(M_PI - th, 2 * M_PI), cand[2][1] = std::remainder(M_PI - ta, 2 * M_PI);
            n = 3;
            break;
        }
        case CurveKind::Hyperbola: {  // the sides of the branch at p's coordinate along u
            const double Y = dot(w, v) / norm2(v), tx = std::acosh(std::max(1.0, dot(w, u) / norm2(u)));
            cand[0][0] = std::asinh(Y), cand[0][1] = std::copysign(tx, Y), cand[1][0] = cand[1][1] = -std::copysign(tx, Y);
            n = 2;
            break;
        }
    }
    double d2[3];
    for (int i = 0; i < n; ++i) {
        const double t0 = cand[i][0], t1 = cand[i][1];
        out[i] = nearer_foot(p, norm2(at(t1) - p) < norm2(at(t0) - p) ? t1 : t0);
        d2[i] = norm2(at(out[i]) - p);
    }
    // The nearest first; the others only where they are within 1e-7 and the curve leaves p
    // between them (another pass of the curve, not the same one found twice near a tip).
    for (int i = 1; i < n; ++i)
        if (d2[i] < d2[0]) std::swap(out[i], out[0]), std::swap(d2[i], d2[0]);
    int m = 1;
    for (int i = 1; i < n; ++i) {
        bool other = d2[i] <= 1e-14;
        for (int j = 0; j < m && other; ++j) {
            const double gap = kind == CurveKind::Ellipse ? std::remainder(out[i] - out[j], 2 * M_PI) : out[i] - out[j];
            other = norm2(at(out[j] + 0.5 * gap) - p) > 4e-14;
        }
        if (other) out[m++] = out[i];
    }
    return m;
}

// Newton's method on (at(t) - p) . at'(t) = 0 from t, each step kept only if it brings the curve's
// point nearer to p.
double CurveComponent::nearer_foot(Vec2 p, double t) const {
    const bool hyp = kind == CurveKind::Hyperbola, par = kind == CurveKind::Parabola;
    double best = norm2(at(t) - p);
    for (int it = 0; it < 4 && best > 0; ++it) {
        const double ch = hyp ? std::cosh(t) : std::cos(t), sh = hyp ? std::sinh(t) : std::sin(t);
        const Vec2 d1 = par ? u + (2 * t) * v : hyp ? sh * u + ch * v : ch * v - sh * u;  // at'(t)
        const Vec2 d2 = par ? 2 * v : hyp ? ch * u + sh * v : -(ch * u + sh * v);        // at''(t)
        const Vec2 r = at(t) - p;
        const double den = norm2(d1) + dot(r, d2);
        if (!(den > 0)) break;
        const double tn = t - dot(r, d1) / den, dn = norm2(at(tn) - p);
        if (!(dn < best)) break;
        t = tn, best = dn;
    }
    if (kind == CurveKind::Ellipse && std::fabs(t) > M_PI) t = std::remainder(t, 2 * M_PI);  // atan2's range, as callers expect
    return t;
}

std::vector<CurveComponent::Piece> CurveComponent::pieces(double t0, double t1) const {
    std::vector<Piece> out;
    pieces(t0, t1, out);
    return out;
}

void CurveComponent::pieces(double t0, double t1, std::vector<Piece>& out) const {
    out.clear();
    assert(t1 >= t0);
    if (kind == CurveKind::Line || kind == CurveKind::Parabola) {
        RationalCurve r;
        r.n0 = c; r.n1 = u;
        if (kind == CurveKind::Parabola) r.n2 = v;
        out.push_back({r, t0, t1});
        return;
    }
    // Split so that every piece's weight stays away from zero.
    const double max_span = kind == CurveKind::Ellipse ? M_PI : 3.0;
    int k = std::max(1, (int)std::ceil((t1 - t0) / max_span - 1e-12));
    for (int i = 0; i < k; ++i) {
        double a = t0 + (t1 - t0) * i / k, b = i + 1 == k ? t1 : t0 + (t1 - t0) * (i + 1) / k;
        double tm = 0.5 * (a + b), half = 0.5 * (b - a);
        RationalCurve r;
        if (kind == CurveKind::Ellipse) {
            double cm = std::cos(tm), sm = std::sin(tm);
            r.n0 = c + cm * u + sm * v;
            r.n1 = 2.0 * (-sm * u + cm * v);
            r.n2 = c - cm * u - sm * v;
            r.w0 = 1; r.w1 = 0; r.w2 = 1;
            double z = std::tan(0.5 * half);
            out.push_back({r, -z, z});
        } else {
            double ch = std::cosh(tm), sh = std::sinh(tm);
            r.n0 = c + ch * u + sh * v;
            r.n1 = 2.0 * (sh * u + ch * v);
            r.n2 = -1.0 * c + ch * u + sh * v;
            r.w0 = 1; r.w1 = 0; r.w2 = -1;
            double z = std::tanh(0.5 * half);
            out.push_back({r, -z, z});
        }
    }
}

CurveComponent line_component(Vec2 point, Vec2 dir) {
    CurveComponent cc;
    cc.kind = CurveKind::Line;
    cc.u = dir / norm(dir);
    cc.c = point - dot(point, cc.u) * cc.u;  // foot of the origin: keeps parameters small
    return cc;
}

ConicDecomposition decompose_conic(const Quadratic2& q) {
    ConicDecomposition out;
    decompose_conic(q, out);
    return out;
}

namespace {
// Relative thresholds: the plane is scaled so the target has unit size.
constexpr double eps_quad = 1e-12, eps_par = 1e-10, eps_k = 1e-14, eps_lin = 1e-12, eps_b2 = 1e-13;

void add_line(ConicDecomposition& out, Vec2 point, Vec2 dir) { out.components.push_back(line_component(point, dir)); }

// The line through the root of q nearest `line.c` along the normal of `line` (q restricted to that
// normal is a quadratic A s^2 + B s + C: its smaller root, without cancellation).
CurveComponent refined_line(const Quadratic2& q, const CurveComponent& line) {
    const Vec2 n = perp(line.u);
    const double A = q.a * n.x * n.x + 2 * q.b * n.x * n.y + q.c * n.y * n.y, B = dot(q.gradient(line.c), n), C = q(line.c);
    const double disc = B * B - 4 * A * C;
    if (!(disc >= 0) || B == 0) return line;
    const double s = -2 * C / (B + std::copysign(std::sqrt(disc), B));
    return std::isfinite(s) ? line_component(line.c + s * n, line.u) : line;
}

// Central conic (both eigenvalues l1, l2 of the quadratic part away from 0, eigenvectors e1, e2;
// b1, b2: the linear part along them): l1 X'^2 + l2 Y'^2 + k = 0 around the centre m.
void decompose_central(const Quadratic2& q, double l1, double l2, Vec2 e1, Vec2 e2, double b1, double b2,
                       ConicDecomposition& out) {
    double X0 = -b1 / l1, Y0 = -b2 / l2;
    double k = q.f - b1 * b1 / l1 - b2 * b2 / l2;
    // k's own rounding: its terms are of the order of q at the centre's distance, which for a
    // centre far from T' (the difference of two nearly parallel planes' quadratics, an exact line
    // pair, centred 1e8 away) is far above eps_k. A k within it is 0: a point or a line pair, not
    // an ellipse or hyperbola whose size is rounding noise (and whose points near T' would be
    // sums of terms 1e8 times larger than they are).
    // The eigenvalues are known to ~eps of the larger one and the b's to ~eps of the linear part,
    // so a small eigenvalue (a nearly parabolic difference) makes its term's rounding larger still.
    const double L = std::max(std::fabs(l1), std::fabs(l2)), lin = std::hypot(q.d, q.e);
    auto term_err = [&](double b, double l) { return (b * b + 2 * std::fabs(b) * lin) / std::fabs(l) + L * b * b / (l * l); };
    const double k_tol = eps_k + 64 * 0x1p-52 * (std::fabs(q.f) + term_err(b1, l1) + term_err(b2, l2));
    Vec2 m = X0 * e1 + Y0 * e2;
    if ((l1 > 0) == (l2 > 0)) {
        if (std::fabs(k) <= k_tol) { out.type = ConicType::Point; return; }
        if ((k > 0) == (l1 > 0)) { out.type = ConicType::Empty; return; }
        CurveComponent cc;
        cc.kind = CurveKind::Ellipse;
        cc.c = m;
        cc.u = std::sqrt(-k / l1) * e1;
        cc.v = std::sqrt(-k / l2) * e2;
        out.components.push_back(cc);
        out.type = ConicType::Ellipse;
        return;
    }
    if (std::fabs(k) <= k_tol) {
        double r = std::sqrt(-l1 / l2);
        add_line(out, m, e1 + r * e2);
        add_line(out, m, e1 - r * e2);
        // Lines through a centre far from T' are only as accurate near T' as the centre is far
        // (1e8 away: 1e-7 off, past what the split accepts as on the curve): each is moved onto
        // q = 0 along its normal at its foot of the origin, where q's terms are small.
        // Only a line that passes near T' (its foot of the origin within 1e3): the other's foot may
        // be the centre itself, where its normal runs along the first line and q there is its
        // rounding (generate_pairs13.py "ties_cube_center" 4384, side A, target 7, the paper's
        // order: y (16384 - x) with noise of 1e-20 in x^2, the line x = 16384 moved to x = 0,
        // across T', and a face beside y = 0 went whole to the farther source, d^2 stepping by
        // 0.0625 at 1.3e8).
        if (norm(m) > 1e3)
            for (CurveComponent& line : out.components)
                if (norm(line.c) <= 1e3) line = refined_line(q, line);
        out.type = ConicType::LinePair;
        return;
    }
    // Hyperbola: branches open along the axis whose eigenvalue has the sign opposite to k.
    Vec2 ea = e1, eb = e2;
    double la = l1, lb = l2;
    if ((k > 0) == (l1 > 0)) { std::swap(ea, eb); std::swap(la, lb); }
    double A = std::sqrt(-k / la), Bv = std::sqrt(k / lb);
    for (int sgn : {1, -1}) {
        CurveComponent cc;
        cc.kind = CurveKind::Hyperbola;
        cc.c = m;
        cc.u = (sgn * A) * ea;
        cc.v = Bv * eb;
        out.components.push_back(cc);
    }
    out.type = ConicType::Hyperbola;
}

// How far changing l1 X^2 + 2 b1 X + f (disc = b1^2 - l1 f) by up to `dropped` moves its roots X:
// by dropped / |2 sqrt(disc)| where they are well apart, at most sqrt(dropped / |l1|) where they
// (nearly) meet, or appear there. (Within a factor of 2 of both.)
double roots_moved(double l1, double disc, double dropped) {
    return dropped / (2 * std::sqrt(std::max(disc, 0.0)) + std::sqrt(dropped * std::fabs(l1)));
}

// Parabolic: l2 ~ 0, so q = l1 X^2 + 2 b1 X + 2 b2 Y + f: a parabola, or without the Y term two
// parallel lines, one double line or nothing. The Y term is dropped only where it moves the roots
// by less than 1e-9 over T' (|Y| < 2), however small b2 is: across a thin parabola, 1.4e-5 wide,
// b2 = 1.8e-11 moved them by 3e-6 (independent pair "mirror" 6506, an edge's sliver between the
// arms lost). A b2 within its rounding (eps_b2: q's coefficients are at most 1) is not a parabola:
// where q only touches 0 (a double line, disc ~ 0) b2 = 1e-16 would move its roots by 1e-8
// (independent pair "parallel_offset" 1389: a parabola 4e15 long cut across a domain).
void decompose_parabolic(const Quadratic2& q, double l1, double l2, Vec2 e1, Vec2 e2, double b1, double b2, double disc,
                         bool l2_noise, ConicDecomposition& out) {
    if (std::fabs(b2) > eps_par || (std::fabs(b2) > eps_b2 && roots_moved(l1, disc, 4 * std::fabs(b2)) > 1e-9)) {
        // Y = -(l1 X^2 + 2 b1 X + f) / (2 b2), parametrised by X = Xa + t. Anchored at the vertex
        // (Xa = -b1 / l1) unless that lies far outside the target (a nearly flat parabola, as the
        // difference of two sources' edge quadratics often is): there c + t u + t^2 v would be a
        // small point made of huge cancelling terms, so it is anchored in the target instead.
        double Xa = -b1 / l1;
        double f = q.f;
        // The dropped l2 Y^2 is taken to first order about Yr, the vertex's Y where it lies over
        // T' (the nearest Y of T''s box otherwise): l2 Y^2 = l2 Yr^2 + 2 l2 Yr (Y - Yr) + l2 (Y - Yr)^2,
        // so b2 += l2 Yr and f -= l2 Yr^2, and only l2 (Y - Yr)^2 is dropped. Dropped whole, it
        // moved the vertex along the axis by l2 Y^2 / (2 b2), which a small b2 (g nearly flat along
        // the axis) makes large: generate_pairs3.py "sliver" 506 (and "coinc_retri_far" 272), l2 = -8.9e-11 and b2 = 6.5e-6, a
        // vertex 1.7e-6 off at Y = 0.5, past kOffCurve from the vertex of the face that ends the
        // chord there: no chord, and a sliver 0.2 long, where the other source is nearer by up to
        // 1e-6 in d^2, went to the farther one. Only where that term is a correction (the centre of
        // the conic, -b2 / l2, lies far along the axis) and l2 is no noise (l2_noise), or is noise
        // that would still move the vertex by more than 1e-9 over T': the computed q has it, and the
        // faces' polynomials are the computed ones. Generate_pairs7.py "spike_grid" 9835: a nearly
        // double line along an edge of T' (l2 = 1.3e-12 within its rounding, b2 = -3.7e-10), dropped
        // whole it moved the vertex 1.2e-3 and a chord ran out to it: d^2 stepped by 6e-7.
        {
            const double Ylo = std::min(0.0, e2.x) + std::min(0.0, e2.y), Yhi = std::max(0.0, e2.x) + std::max(0.0, e2.y);
            const double Ya0 = -(l1 * Xa * Xa + 2 * b1 * Xa + f) / (2 * b2);
            const double Yr = std::isfinite(Ya0) ? std::min(std::max(Ya0, Ylo), Yhi) : 0.5 * (Ylo + Yhi);
            const double ymax = std::max(std::fabs(Ylo), std::fabs(Yhi));
            if ((!l2_noise || std::fabs(l2) * ymax * ymax > 2e-9 * std::fabs(b2)) && 2 * std::fabs(l2 * Yr) <= std::fabs(b2)) {
                b2 += l2 * Yr;
                f -= l2 * Yr * Yr;
            }
        }
        double Ya = -(l1 * Xa * Xa + 2 * b1 * Xa + f) / (2 * b2);
        CurveComponent cc;
        cc.kind = CurveKind::Parabola;
        cc.u = e1;
        if (!(std::fabs(Xa) + std::fabs(Ya) <= 8)) {
            // The curve's points at Y = Ym (the target's middle): the roots of
            // l1 X^2 + 2 b1 X + (f + 2 b2 Ym) = 0, taken without cancellation. Far from its vertex
            // a parabola runs nearly along its axis, so X hardly changes along the target: each
            // arm there is nearly a line, and each is a component of its own, anchored at its
            // root (t rescaled so that |u| = 1). Both arms may cross T': the difference of two
            // sources' edge quadratics is often nearly two parallel lines (degenerate seed 2463,
            // perpendicular sources: one arm only, and the face was not cut along the other).
            const Vec2 m{0.5, 0.25};
            const double Xm = dot(m, e1), Ym = dot(m, e2), C = f + 2 * b2 * Ym;
            const double disc = b1 * b1 - l1 * C;
            if (disc >= 0) {
                const double h = -(b1 + std::copysign(std::sqrt(disc), b1));
                double r1 = h / l1, r2 = h != 0 ? C / h : r1;
                if (std::fabs(r2 - Xm) < std::fabs(r1 - Xm)) std::swap(r1, r2);  // the arm nearer T' first
                for (int arm = 0; arm < (r1 == r2 ? 1 : 2); ++arm) {
                    const double X = arm ? r2 : r1;
                    const Vec2 u = e1 + (-(l1 * X + b1) / b2) * e2;
                    const double k = 1 / norm(u);
                    cc.u = u * k;
                    cc.c = X * e1 + Ym * e2;
                    cc.v = (-l1 / (2 * b2) * k * k) * e2;
                    out.components.push_back(cc);
                }
                out.type = ConicType::Parabola;
                return;
            }
        }
        cc.c = Xa * e1 + Ya * e2;
        cc.v = (-l1 / (2 * b2)) * e2;
        out.components.push_back(cc);
        out.type = ConicType::Parabola;
        return;
    }
    if (disc <= eps_k) {
        out.type = disc >= -eps_k ? ConicType::DoubleLine : ConicType::Empty;
        return;
    }
    double r = std::sqrt(disc);
    add_line(out, ((-b1 + r) / l1) * e1, e2);
    add_line(out, ((-b1 - r) / l1) * e1, e2);
    out.type = ConicType::ParallelLines;
}

}  // namespace

void decompose_conic(const Quadratic2& q0, ConicDecomposition& out, double l2_rounding) {
    out.type = ConicType::Empty;
    out.components.clear();
    double s = q0.scale();
    if (s == 0 || !std::isfinite(s)) { out.type = ConicType::Everything; return; }
    Quadratic2 q = q0 * (1.0 / s);

    // Eigen-decomposition of the quadratic part [[a b][b c]]; none for a linear q (a region
    // boundary, the most common case), whose eigenvalues are exactly 0.
    double l1 = 0, l2 = 0;
    Vec2 e1{1, 0}, e2{-0.0, 1};
    if (!q.is_linear()) q.principal_axes(l1, l2, e1, e2);
    Vec2 B{q.d, q.e};

    // Linear: 2 B.x + f = 0, also where the quadratic part moves the line by less than 1e-10 over
    // T' (|x| < 1.5): its terms, below 2.25 |l1|, over |grad| = 2 |B|. (Degenerate pair 112: a
    // difference with a quadratic part of 1e-11 taken as a hyperbola centred 6e10 away, whose
    // points near T' were cancellation noise, and a face was given whole to the farther source.)
    if (std::fabs(l1) <= eps_quad || 2.25 * std::fabs(l1) <= 1e-10 * 2 * norm(B)) {
        double nb = norm(B);
        if (nb <= eps_lin) { out.type = std::fabs(q.f) <= eps_lin ? ConicType::Everything : ConicType::Empty; return; }
        Vec2 n = B / nb;
        add_line(out, n * (-q.f / (2 * nb)), perp(n));
        out.type = ConicType::Line;
        return;
    }
    double b1 = dot(B, e1), b2 = dot(B, e2);
    // Nearly parabolic (l2 small) is still central where l2 is well above its rounding (~1e-16
    // of l1), the centre lies near T', and the parabolic forms (which drop l2 Y^2, and b2 Y for
    // parallel lines) would move the curve by more than 1e-9 over T' (|Y| < 2): a thin ellipse
    // of T''s size, as the difference of a source's edge quadratic and a nearly parallel source's
    // plane quadratic is (degenerate pair "mirror" 11642: an ellipse 3.5e-6 wide and ~1 long; as
    // parallel lines, 1.4e-6 off, it lost the sliver where the edge was nearer, and with it the
    // maximum; "mirror" 250: a hyperbola whose parallel-line form had roots 6e-7 apart, where
    // the dropped terms, 1e-11, widen it to 7e-6 across T').
    // And l2 is rounding noise wherever it is below ~1e-14: q's coefficients (scaled to at most 1)
    // are exact to ~1e-16 whatever l1 is. Where the quadratic part itself is small (l1 1.5e-8 of
    // the scale: two nearly parallel planes' quadratics), l2 = 1e-16 passed the relative test, and
    // the "ellipse" it made had semi-axes 7e7 and 9e11, its points near T' 1.7e-4 off the curve
    // (generate_pairs.py "perp" 5811: no chord found, a face kept a source 0.035 farther).
    // So is an l2 within the rounding the caller knows q's quadratic part to (l2_rounding, in q0's
    // units): a difference of two quadratics whose parts nearly cancel is exact only to an ulp of
    // the operands, and scaled by its own small size that can be far above 1e-14. Generate_pairs11.py
    // "combo" 363, side B, target 0, the paper's order: a sliver's nearly vertical edge's part
    // (1 - 9e-11 on the diagonal) less a vertex's, rank one but for l2 = -1.35e-14 (scaled by
    // 1/1.2e-3; an ulp of the operands is 1.8e-13 there), taken as an ellipse 1e10 long whose
    // points near T' crossed no arc: a face went whole to the farther source, a step of d^2 4e-6.
    const bool l2_noise = !(std::fabs(l2) > std::max(1e-14, l2_rounding / s));
    const double disc = b1 * b1 - l1 * q.f;
    bool central = !l2_noise && std::fabs(l2) > eps_par * std::fabs(l1);
    // Only where the central form is the more precise near T': l2 is known to ~4 ulps of the
    // quadratic part (rounding_l2), and its curve near T', about R = |b2 / l2| from the centre,
    // turns with sqrt(l2 / l1), so it moves by R sqrt(l2 / l1) rounding_l2 / (2 l2) there.
    // Generate_pairs4.py "thin_shell" 14534, nearest first: two lines 2.8e-4 apart across T' taken
    // as a line pair crossing 600 away (l2 = -5.2e-14), each 4.2e-7 off the curve near T', where
    // the parallel lines are off by 7e-10; a sliver 2e-6 wide kept a source 0.5% farther in d^2.
    // So too where l2 is within the rounding the caller knows (l2_noise), if the parabolic form,
    // which drops l2 (Y - Yr)^2, would move the curve by more than kVertexTolerance (1e-7) near T'
    // and the central form is a hundred times as precise there: a split's vertices on the face's
    // boundary are roots of q as computed, noise and all, and its chords must reach them.
    // Generate_pairs5.py "cone_fan" 60335, nearest first: two edges from one corner to points
    // 1.3e-8 apart (a flat double cone's apex and its base's centre), their quadratics 1.8e-11
    // apart; the difference's l2, 1.4e-7 of l1, is below the operands' rounding, and its parabolic
    // form lay 5e-6 off the crossings on a face's boundary: no chord, and the face went whole to
    // the farther edge. Its hyperbola, centred 5 from T', is known there to 2e-11.
    if (!central && std::fabs(l2) > 1e-14 * std::fabs(l1) && std::fabs(b2) <= 1e4 * std::fabs(l2)) {
        const double moved = roots_moved(l1, disc, 4 * std::fabs(l2) + (l2_noise ? 0.0 : 4 * std::fabs(b2)));
        const double rounding_l2 = 4 * 0x1p-52 * (std::fabs(q.a) + 2 * std::fabs(q.b) + std::fabs(q.c));
        const double R = std::fabs(b2 / l2) + 2;
        const double err = R * std::sqrt(std::fabs(l2 / l1)) * rounding_l2 / (2 * std::fabs(l2));
        central = l2_noise ? moved > 1e-7 && 100 * err < moved : moved > 1e-9 && err < moved;
    }
    // A centre 1e8 away or more (|b2 / l2|, l1 being ~1): central points near T' are differences of
    // terms that large, off by 1e-8 or more, where the parabola, which drops l2 Y^2, is off by
    // 2 / |b2 / l2| (independent pair "soup" 3055: a hyperbola centred 2e10 away, its points near
    // T' 2e-6 off the crossings, no chord found, the face kept whole; a line pair centred that far
    // becomes the parabola's arms, the near one as accurate).
    if (central && std::fabs(b2) > 1e8 * std::fabs(l2)) central = false;
    if (central) decompose_central(q, l1, l2, e1, e2, b1, b2, out);
    // A point within k's rounding, where l2 is only central by the roots it moves (below eps_par):
    // that rounding grows as b2^2 / l2^2, the centre's distance squared, and near T' the parabolic
    // form, which drops l2 (Y - Yr)^2, is the more precise. Generate_pairs4.py "thin_shell" 16846,
    // nearest first: an ellipse 1782 by 1.8e-4 centred 1781 away, its arc crossing a strip of T'
    // 1.8e-4 wide, taken as a point (|k| 3.3e-8 against a tolerance of 4.5e-8): the strip was not
    // cut, and a sliver along it kept a source 3.7e-11 farther in d^2.
    if (central && out.type == ConicType::Point && !(std::fabs(l2) > eps_par * std::fabs(l1))) {
        out.type = ConicType::Empty;
        decompose_parabolic(q, l1, l2, e1, e2, b1, b2, disc, l2_noise, out);
    }
    // So is a line pair whose k, zeroed within its rounding there, moves the roots near T' by more
    // than 1e-9 and more than the parabolic form's dropped term, l2 (Y - Yr)^2 <= 4 |l2|, does: k
    // and l2 Y0^2 nearly cancel at T' (both are about b2^2 / l2), and with k dropped the lines were
    // 8 times as far apart as the curve's branches. Generate_pairs9.py "tinydiff_coinc_far" 2315,
    // side A, target 2: an edge's quadratic less a nearly parallel plane's (l2 = -1.6e-14, centre
    // 70 away, k = 7.5e-11), branches 1.05e-6 either side of the edge's line taken as lines 8.1e-6
    // from it: no chord, and the strip where the edge is nearer kept the plane, d^2 1.1e-12 where
    // it is 2.4e-18. (A centre near T', as "mirror" 11642's, has |k| far below 4 |l2|: there the
    // line pair is the more precise, and the parabola would drop 1e-10.)
    if (central && out.type == ConicType::LinePair && !(std::fabs(l2) > eps_par * std::fabs(l1))) {
        const double k = std::fabs(q.f - b1 * b1 / l1 - b2 * b2 / l2);
        if (k > 4 * std::fabs(l2) && roots_moved(l1, disc, k) > 1e-9) {
            out.type = ConicType::Empty;
            out.components.clear();
            decompose_parabolic(q, l1, l2, e1, e2, b1, b2, disc, l2_noise, out);
        }
    }
    if (!central) decompose_parabolic(q, l1, l2, e1, e2, b1, b2, disc, l2_noise, out);
}

}  // namespace hlens
