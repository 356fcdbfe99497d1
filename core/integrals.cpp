// Integrals over the domains of a domain mesh by Green's theorem along their arcs (Straub 2007,
// §5 "future work"; quadrature bound: Trefethen, SIAM Review 50 (2008), Theorem 4.5). See
// integrals.h for what is exact and what is estimated.
#include "integrals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <memory>

namespace hlens {

void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(n, 0);
    w.assign(n, 0);
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = z;  // P_0, P_1, then the recurrence up to P_n
            for (int k = 2; k <= n; ++k) {
                double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) { p1 = z; p0 = 1; }
            dp = n * (z * p1 - p0) / (z * z - 1);
            double dz = p1 / dp;
            z -= dz;
            if (std::fabs(dz) < 1e-16) break;
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * dp * dp);
    }
}

namespace {

constexpr int kGaussN = 16;
// rho^(2 kGaussN) by squaring (std::pow was 7% of the level areas' time).
inline double pow32(double rho) {
    static_assert(2 * kGaussN == 32, "pow32 squares five times");
    double r = rho * rho;
    r *= r; r *= r; r *= r;
    return r * r;
}

struct GaussTable {
    std::vector<double> x16, w16, x3, w3;
    GaussTable() {
        gauss_legendre(kGaussN, x16, w16);
        gauss_legendre(3, x3, w3);
    }
};
const GaussTable& gauss() {
    static const GaussTable t;
    return t;
}

// ---------------------------------------------------------------- the polynomial case

// Q = x-antiderivative of P: a/3 x^3 + b x^2 y + c x y^2 + d x^2 + 2e x y + f x, so dQ/dx = P.
struct Antiderivative {
    Quadratic2 P;
    double operator()(Vec2 p) const {
        const double x = p.x, y = p.y;
        return x * (P.a / 3 * x * x + P.b * x * y + P.c * y * y + P.d * x + 2 * P.e * y + P.f);
    }
    // |Q| over complex points with |x| <= X, |y| <= Y.
    double bound(double X, double Y) const {
        return X * (std::fabs(P.a) / 3 * X * X + std::fabs(P.b) * X * Y + std::fabs(P.c) * Y * Y + std::fabs(P.d) * X +
                    2 * std::fabs(P.e) * Y + std::fabs(P.f));
    }
};

// Integral of Q dy along the segment a -> b (Q of degree <= 3 along it: 3 Gauss points are exact).
template <class Q>
double segment_integral(const Q& q, Vec2 a, Vec2 b) {
    const GaussTable& g = gauss();
    double s = 0;
    for (int i = 0; i < 3; ++i) s += g.w3[i] * q(a + (0.5 * (1 + g.x3[i])) * (b - a));
    return 0.5 * s * (b.y - a.y);
}

// p(z) = p0 + p1 z + p2 z^2 with z = m + h s, as coefficients in s.
std::array<double, 3> in_s(double p0, double p1, double p2, double m, double h) {
    return {p0 + m * (p1 + m * p2), (p1 + 2 * p2 * m) * h, p2 * h * h};
}
double abs_bound(const std::array<double, 3>& c, double r) { return std::fabs(c[0]) + r * (std::fabs(c[1]) + r * std::fabs(c[2])); }

// The Bernstein-ellipse parameter of a point: E_rho passes through it.
double rho_of(std::complex<double> r) {
    std::complex<double> q = std::sqrt(r * r - 1.0);
    return std::max(std::abs(r + q), std::abs(r - q));
}

// A lower bound of |W(s)| on E_rho for W = W0 + W1 s + W2 s^2 with roots of parameters rho_i:
// s - r = (zeta - eta)(1 - 1/(zeta eta))/2 (Joukowski), so |s - r| >= (rho_r - rho)(1 - 1/(rho rho_r))/2.
struct WeightBound {
    std::array<double, 3> W;
    int nroots = 0;
    double rho_root[2] = {HUGE_VAL, HUGE_VAL};
    explicit WeightBound(const std::array<double, 3>& w) : W(w) {
        if (W[2] != 0) {
            std::complex<double> disc = std::sqrt(std::complex<double>(W[1] * W[1] - 4 * W[0] * W[2]));
            // The root formula without cancellation: q = -(b + sign(b) sqrt(disc)) / 2.
            std::complex<double> q = -0.5 * (W[1] + (W[1] >= 0 ? 1.0 : -1.0) * disc);
            std::complex<double> r1 = q / W[2], r2 = q != 0.0 ? std::complex<double>(W[0]) / q : r1;
            rho_root[0] = rho_of(r1);
            rho_root[1] = rho_of(r2);
            nroots = 2;
        } else if (W[1] != 0) {
            rho_root[0] = rho_of(-W[0] / W[1]);
            nroots = 1;
        }
    }
    double rho_limit() const { return std::min(rho_root[0], rho_root[1]); }
    double lower(double rho) const {
        double l = nroots == 2 ? std::fabs(W[2]) : nroots == 1 ? std::fabs(W[1]) : std::fabs(W[0]);
        for (int i = 0; i < nroots; ++i) l *= (rho_root[i] - rho) * (1 - 1 / (rho * rho_root[i])) / 2;
        return l;
    }
};

// Integral of Q dy along c(z), z in [z0, z1], with a certified bound; halves the interval while
// the bound exceeds the tolerance (relative to the integrand's own L1 mass).
Integral arc_integral(const Antiderivative& Q, const RationalCurve& c, double z0, double z1, int depth = 0) {
    const double m = 0.5 * (z0 + z1), h = 0.5 * (z1 - z0);
    const auto X = in_s(c.n0.x, c.n1.x, c.n2.x, m, h), Y = in_s(c.n0.y, c.n1.y, c.n2.y, m, h),
               W = in_s(c.w0, c.w1, c.w2, m, h);
    // dy/ds = D / W^2 with D = Y' W - Y W' (degree <= 2: the s^3 terms cancel).
    const std::array<double, 3> D{Y[1] * W[0] - Y[0] * W[1], 2 * (Y[2] * W[0] - Y[0] * W[2]), Y[2] * W[1] - Y[1] * W[2]};
    const GaussTable& g = gauss();
    double sum = 0, mass = 0;
    for (int i = 0; i < kGaussN; ++i) {
        const double s = g.x16[i], w = W[0] + s * (W[1] + s * W[2]);
        const Vec2 p{(X[0] + s * (X[1] + s * X[2])) / w, (Y[0] + s * (Y[1] + s * Y[2])) / w};
        const double f = Q(p) * (D[0] + s * (D[1] + s * D[2])) / (w * w);
        sum += g.w16[i] * f;
        mass += g.w16[i] * std::fabs(f);
    }
    const WeightBound wb(W);
    if (wb.nroots == 0) return {sum, 0};  // a polynomial of degree <= 8 in s: 16 points are exact
    const double limit = std::min(wb.rho_limit(), 64.0);
    double best = HUGE_VAL;
    for (int k = 1; k < 16 && limit > 1; ++k) {
        const double rho = 1 + (limit - 1) * k / 16, r = 0.5 * (rho + 1 / rho);
        const double wl = wb.lower(rho);
        if (!(wl > 0)) continue;
        const double M = Q.bound(abs_bound(X, r) / wl, abs_bound(Y, r) / wl) * abs_bound(D, r) / (wl * wl);
        best = std::min(best, 64.0 / 15 * M / ((rho * rho - 1) * pow32(rho)));
    }
    const double tol = 1e-14 * mass + 1e-300;
    if (best <= tol || depth >= 40 || !(h > 0)) return {sum, best};
    Integral r = arc_integral(Q, c, z0, m, depth + 1);
    r += arc_integral(Q, c, m, z1, depth + 1);
    return r;
}

// ---------------------------------------------------------------- the square root case

const double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                        0.207784955007898467600689403773245, 0.0};
const double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
const double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// Adaptive Gauss-Kronrod 7/15 of f on [a, b]: the Kronrod value, the sum of |K15 - G7| as error.
Integral adaptive_gk(const std::function<double(double)>& f, double a, double b, double tol, int depth = 0) {
    const double m = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = f(m);
    double k = kWgk[7] * fc, gs = kWg[3] * fc, mag = kWgk[7] * std::fabs(fc);
    for (int j = 0; j < 7; ++j) {
        const double fl = f(m - h * kXgk[j]), fr = f(m + h * kXgk[j]);
        k += kWgk[j] * (fl + fr);
        mag += kWgk[j] * (std::fabs(fl) + std::fabs(fr));
        if (j % 2 == 1) gs += kWg[j / 2] * (fl + fr);
    }
    const double err = std::fabs(k - gs) * std::fabs(h);
    // K15 - G7 within the rounding of the values themselves: halving cannot make it smaller (the
    // integrand is an antiderivative evaluated far from where it is small, bunny pair's nefertiti
    // target 20 halved to depth 30 for 200 s). The estimate is kept as the error.
    const bool noise = err <= 1e3 * std::numeric_limits<double>::epsilon() * mag * std::fabs(h);
    if (err <= tol || noise || depth >= 30 || !(std::fabs(h) > 1e-300)) return {k * h, err};
    Integral r = adaptive_gk(f, a, m, 0.5 * tol, depth + 1);
    r += adaptive_gk(f, m, b, 0.5 * tol, depth + 1);
    return r;
}

// An antiderivative of sqrt(P) along P's principal axis u (largest eigenvalue l1), as a function
// of the point: with xi = u.p, eta = v.p, P = l1 (xi + gu/l1)^2 + l1 K(eta), and the integral of
// sqrt(U^2 + K) dU is (U sqrt(U^2 + K) + K asinh(U / sqrt K)) / 2. Green's theorem then runs along
// eta = v.p. Where P is nearly constant over the face (l1 tiny) the closed form cancels badly, and
// the inner integral is taken by Gauss-Legendre instead (sqrt(P) is then very smooth).
struct SqrtAntiderivative {
    Quadratic2 P;
    Vec2 u, v;
    double l1 = 0, l2 = 0, gu = 0, gv = 0;
    bool closed_form = true;
    SqrtAntiderivative(const Quadratic2& q, double diam2, double pmin) : P(q) {
        const double tr = q.a + q.c, det = q.a * q.c - q.b * q.b;
        const double disc = std::sqrt(std::max(0.0, 0.25 * (q.a - q.c) * (q.a - q.c) + q.b * q.b));
        l1 = 0.5 * tr + disc;
        l2 = l1 > 0 ? det / l1 : 0;  // the smaller root without cancellation
        Vec2 e = std::fabs(q.a - l1) + std::fabs(q.b) > std::fabs(q.c - l1) + std::fabs(q.b) ? Vec2{-q.b, q.a - l1}
                                                                                              : Vec2{q.c - l1, -q.b};
        const double n = norm(e);
        u = n > 0 ? e / n : Vec2{1, 0};
        v = {-u.y, u.x};
        gu = q.d * u.x + q.e * u.y;
        gv = q.d * v.x + q.e * v.y;
        closed_form = l1 > 0 && !(pmin > 0 && l1 * diam2 < 1e-3 * pmin);
    }
    double operator()(Vec2 p) const {
        const double xi = dot(u, p), eta = dot(v, p);
        if (!closed_form) {  // integral of sqrt(P) from xi = 0 to xi at this eta
            const GaussTable& g = gauss();
            double s = 0;
            for (int i = 0; i < kGaussN; ++i) s += g.w16[i] * std::sqrt(std::max(0.0, P((0.5 * (1 + g.x16[i]) * xi) * u + eta * v)));
            return 0.5 * xi * s;
        }
        const double U = xi + gu / l1;
        const double K = std::max(0.0, (l2 * eta * eta + 2 * gv * eta + P.f) / l1 - (gu / l1) * (gu / l1));
        const double r = std::sqrt(U * U + K);
        const double tail = K > 0 ? K * std::asinh(U / std::sqrt(K)) : 0.0;
        return 0.5 * std::sqrt(l1) * (U * r + tail);
    }
};

// ---------------------------------------------------------------- along the loops of a face

// Sum over the face's half-edges of the edge's line integral (forward along the edge, negated for
// the reverse half-edge). `edge_fn(e)` integrates edge e from its first vertex to its second.
template <class EdgeFn>
Integral sum_over_face(const DomainMesh& m, int f, EdgeFn&& edge_fn) {
    Integral total;
    for (int h : m.face_half_edges(f)) {
        Integral e = edge_fn(h >> 1);
        if (h & 1) e.value = -e.value;
        total += e;
    }
    return total;
}

Vec2 face_origin(const DomainMesh& m, int f) {
    const auto& F = m.faces()[f];
    return m.vertices()[m.half_edges()[F.loops[0]].origin].p;
}

// The ends of edge e (its vertices) and of its curve, shifted by -o.
struct EdgeEnds { Vec2 va, vb, ca, cb; };
EdgeEnds edge_ends(const DomainMesh& m, int e, Vec2 o) {
    const auto& E = m.edges()[e];
    const auto& H = m.half_edges();
    return {m.vertices()[H[2 * e].origin].p - o, m.vertices()[H[2 * e + 1].origin].p - o, E.curve(E.z0) - o, E.curve(E.z1) - o};
}

}  // namespace

Quadratic2 shifted(const Quadratic2& P, Vec2 o) {
    Quadratic2 r = P;
    r.d = P.a * o.x + P.b * o.y + P.d;
    r.e = P.b * o.x + P.c * o.y + P.e;
    r.f = P(o);
    return r;
}

RationalCurve shifted(const RationalCurve& c, Vec2 o) {
    RationalCurve r = c;
    r.n0 = c.n0 - c.w0 * o;
    r.n1 = c.n1 - c.w1 * o;
    r.n2 = c.n2 - c.w2 * o;
    return r;
}

// The arc's integral is corrected by the chord between its vertices against the chord between
// its curve's ends, which may differ by a snap: as in DomainMesh::loop_area, every loop is then
// closed exactly, so the faces' integrals add up to the target's.
Integral face_integral(const DomainMesh& m, int f, const Quadratic2& P) {
    const Vec2 o = face_origin(m, f);
    const Antiderivative Q{shifted(P, o)};
    return sum_over_face(m, f, [&](int e) {
        const auto& E = m.edges()[e];
        const EdgeEnds k = edge_ends(m, e, o);
        Integral r{segment_integral(Q, k.va, k.vb), 0};
        if (!E.curve.straight()) {
            r += arc_integral(Q, shifted(E.curve, o), E.z0, E.z1);
            r.value -= segment_integral(Q, k.ca, k.cb);
        }
        return r;
    });
}

Integral face_sqrt_integral(const DomainMesh& m, int f, const Quadratic2& P) {
    const Vec2 o = face_origin(m, f);
    const Box2 b = m.face_box(f);
    const Quadratic2 Ps = shifted(P, o);
    const double pmin = P.range(b.lo, b.hi).lo;
    const SqrtAntiderivative F(Ps, dot(b.hi - b.lo, b.hi - b.lo), pmin);
    // Tolerance per edge: 1e-12 of (box area x sqrt(max P)) / 16, far below 1e-9 of the face.
    const double pmax = std::max(0.0, P.range(b.lo, b.hi).hi);
    const double tol = 1e-12 * std::max(1e-300, (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * std::sqrt(pmax)) / 16;
    auto along_segment = [&](Vec2 a, Vec2 c) {
        const double deta = dot(F.v, c - a);
        return adaptive_gk([&](double s) { return F(a + s * (c - a)) * deta; }, 0, 1, tol);
    };
    return sum_over_face(m, f, [&](int e) {
        const auto& E = m.edges()[e];
        const EdgeEnds k = edge_ends(m, e, o);
        Integral r = along_segment(k.va, k.vb);
        if (!E.curve.straight()) {
            const RationalCurve c = shifted(E.curve, o);
            r += adaptive_gk([&](double z) { return F(c(z)) * dot(F.v, c.derivative(z)); }, E.z0, E.z1, tol);
            Integral chord = along_segment(k.ca, k.cb);
            r.value -= chord.value;
            r.error += chord.error;
        }
        return r;
    });
}

Interval convex_range(const Quadratic2& P, const Box2& b) {
    // The largest value of a convex function over a box is at a corner.
    const Vec2 c[4] = {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}};
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Vec2& p : c) hi = std::max(hi, P(p));
    // The smallest: at the interior critical point if there is one inside, else on an edge (where
    // the critical points form a line, that line also meets the boundary at the same value).
    if (Vec2 m; P.centre(m) && m.x >= b.lo.x && m.x <= b.hi.x && m.y >= b.lo.y && m.y <= b.hi.y) lo = P(m);
    for (int k = 0; k < 4; ++k) {  // P along an edge p + s u, s in [0, 1]: a 1D convex quadratic
        const Vec2 p = c[k], u = c[(k + 1) % 4] - c[k];
        const double qa = P.a * u.x * u.x + 2 * P.b * u.x * u.y + P.c * u.y * u.y;
        const double qb = dot(P.gradient(p), u);  // the derivative at s = 0
        double s = qa > 0 ? -qb / (2 * qa) : 0;
        s = std::min(1.0, std::max(0.0, s));
        lo = std::min({lo, P(p), P(p + s * u)});
    }
    const double m = 1e-13 * (P.scale() * (1 + norm2(b.lo) + norm2(b.hi)));  // rounding of the evaluations
    return {lo - m, hi + m};
}

DomainIntegrals domain_integrals(const DomainMesh& m, std::vector<FaceMoments>* faces) {
    DomainIntegrals r;
    r.min_d2_lower = HUGE_VAL;
    const auto& F = m.faces();
    for (size_t f = 1; f < F.size(); ++f) {
        if (!F[f].alive || F[f].infinite) continue;
        const Integral a = face_area_exact(m, (int)f), q = face_integral(m, (int)f, F[f].poly),
                       s = face_sqrt_integral(m, (int)f, F[f].poly);
        r.area += a.value; r.err_area += a.error;
        r.int_d2 += q.value; r.err_d2 += q.error;
        r.int_d += s.value; r.err_d += s.error;
        const Box2 b = m.face_box((int)f);
        const double lo = std::max(0.0, convex_range(F[f].poly, b).lo);
        r.min_d2_lower = std::min(r.min_d2_lower, lo);
        r.max_d2 = std::max(r.max_d2, F[f].max_value);
        if (faces) faces->push_back({a.value, s.value, q.value, lo, F[f].max_value});
    }
    if (r.min_d2_lower == HUGE_VAL) r.min_d2_lower = 0;
    return r;
}

void split_at_level(DomainMesh& m, double t2, const std::function<void(int face, bool above, bool split)>& visit) {
    const size_t nfaces = m.faces().size();
    for (size_t f = 1; f < nfaces; ++f) {
        const DomainMesh::Face& F = m.faces()[f];
        if (!F.alive || F.infinite) continue;
        const Interval r = convex_range(F.poly, m.face_box((int)f));
        if (r.hi <= t2) continue;                                   // wholly at or below t
        if (r.lo > t2) { visit((int)f, true, false); continue; }
        Quadratic2 g = F.poly;
        g.f -= t2;
        // The mesh's cache of face boxes can be left stale by an edit (the construction's and
        // split_face's own: found by cached_face_box's debug check, by about 1e-7 here), and
        // split_face trusts it: each split starts from freshly computed boxes.
        m.forget_face_boxes();
        for (const DomainMesh::SplitPiece& piece : m.split_face((int)f, g)) visit(piece.face, piece.sign > 0, true);
    }
}

Integral curve_x_dy(const RationalCurve& c, double z0, double z1) {
    Quadratic2 one;
    one.f = 1;
    return arc_integral(Antiderivative{one}, c, z0, z1);
}

}  // namespace hlens
