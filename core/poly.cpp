#include "poly.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hlens {

Poly Poly::derivative() const {
    Poly d;
    d.deg = deg > 0 ? deg - 1 : 0;
    for (int i = 1; i <= deg; ++i) d.c[i - 1] = c[i] * i;
    return d;
}

void Poly::trim() {
    while (deg > 0 && c[deg] == 0.0) --deg;
}

Poly operator*(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = a.deg + b.deg;
    assert(r.deg < 8);
    for (int i = 0; i <= a.deg; ++i)
        for (int j = 0; j <= b.deg; ++j) r.c[i + j] += a.c[i] * b.c[j];
    return r;
}

Poly operator+(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = std::max(a.deg, b.deg);
    for (int i = 0; i <= r.deg; ++i) r.c[i] = (i <= a.deg ? a.c[i] : 0.0) + (i <= b.deg ? b.c[i] : 0.0);
    return r;
}

Poly operator*(double s, const Poly& a) {
    Poly r = a;
    for (int i = 0; i <= r.deg; ++i) r.c[i] *= s;
    return r;
}

namespace {

// A list with room for every point the recursion can report (at most 2 deg - 1 for deg >= 1: each
// level adds at most one per piece between its breakpoints, plus one at the upper end).
struct RootList {
    double x[kMaxSignChangeRoots];
    int n = 0;
    void push(double v) {
        assert(n < kMaxSignChangeRoots);
        x[n++] = v;
    }
    bool empty() const { return n == 0; }
    double back() const { return x[n - 1]; }
};

// Where bisection of p on [a, b] (p(a) = fa and p(b) of opposite signs) may skip evaluating p:
// at every x <= x1 the computed p(x) is certain to have fa's sign, at every x >= x2 the other
// sign, neither zero. Proved, not guessed:
//  - p is strictly monotone on [a, b] (deg 1, or p' of one strict sign there), in the direction
//    that takes fa's sign towards the other one;
//  - E >= |computed p(x) - p(x)| on [a, b] (Horner's error is below 2 deg eps sum |c_i| M^i);
//  - the computed p(x1) has fa's sign and |p(x1)| > 2E, so the exact p has that sign and size > E
//    at x1 and, being monotone, everywhere left of it; likewise at x2 and right of it.
// x1, x2 are taken a little either side of a root estimate (Newton from the secant); when a check
// fails that side stays empty (x1 = -inf, x2 = +inf) and bisection evaluates as usual.
void sure_sides(const Poly& p, double a, double b, double fa, double& x1, double& x2) {
    x1 = -HUGE_VAL;
    x2 = HUGE_VAL;
    const int n = p.deg;
    if (n < 1 || !(fa != 0)) return;
    const double sigma = fa < 0 ? -1.0 : 1.0;
    Poly d = p.derivative();
    double slope_sign;
    if (n == 1) {
        slope_sign = p.c[1] > 0 ? 1.0 : (p.c[1] < 0 ? -1.0 : 0.0);
    } else {
        if (!one_sign_on(d, a, b)) return;
        slope_sign = d(0.5 * (a + b)) > 0 ? 1.0 : -1.0;
    }
    if (!(sigma * slope_sign < 0)) return;  // fa's sign must shrink towards b
    const double M = std::max(std::fabs(a), std::fabs(b));
    double size = 0;
    for (int i = n; i >= 0; --i) size = size * M + std::fabs(p.c[i]);
    const double E = 4 * n * 0x1p-53 * size;  // twice gamma_2n * size
    if (!(E < HUGE_VAL)) return;
    // Root estimate.
    double r;
    if (n == 1) {
        r = -p.c[0] / p.c[1];
    } else {
        const double fb = p(b);
        r = a - fa * (b - a) / (fb - fa);
        for (int it = 0; it < 4; ++it) {
            const double dr = d(r);
            if (!(dr != 0)) break;
            r -= p(r) / dr;
        }
    }
    if (!(r > a && r < b)) return;
    const double slope = std::fabs(d(r));
    if (!(slope > 0)) return;
    const double delta = 4 * E / slope + 0x1p-50 * M;
    const double l = r - delta, h = r + delta;
    if (l > a && l < b && sigma * p(l) > 2 * E) x1 = l;
    if (h > a && h < b && sigma * p(h) < -2 * E) x2 = h;
}

}  // namespace

// The one root of p in [a, b] given p(a) = fa and p(b) of opposite signs. When sure_sides proves
// both sides of a narrow bracket, its middle; otherwise by bisection, whose result is that of
// evaluating p at every midpoint; the midpoints whose sign is certain are decided without the
// evaluation: far from the root the steps no longer wait for p.
namespace {
thread_local int plain_bisection = 0;  // PlainBisection scopes alive on this thread
}  // namespace

PlainBisection::PlainBisection() { ++plain_bisection; }
PlainBisection::~PlainBisection() { --plain_bisection; }

double bisect_root(const Poly& p, double a, double b, double fa) {
    const bool short_cuts = plain_bisection == 0;
    if (short_cuts && p.deg == 1 && p.c[1] != 0) {  // a line: its root, to the rounding of one division
        const double r = -p.c[0] / p.c[1];
        if (r > a && r < b) return r;
    }
    double x1, x2;
    sure_sides(p, a, b, fa, x1, x2);
    // Both sides proved: the root lies in [x1, x2], an interval as narrow as the evaluation's
    // noise allows, where bisection could only follow the rounding's signs. Its middle will do.
    if (short_cuts && x1 > a && x2 < b) return 0.5 * (x1 + x2);
    int it = 0;
    // While the midpoints fall where the sign is certain, the steps are a chain of additions and
    // comparisons; the choice of half is made without a branch (it is as unpredictable as the
    // root's binary digits).
#if defined(__SSE2__)
    {
        __m128d A = _mm_set_sd(a), B = _mm_set_sd(b);
        const __m128d X1 = _mm_set_sd(x1), X2 = _mm_set_sd(x2), half = _mm_set_sd(0.5);
        for (; it < 200; ++it) {
            const __m128d M = _mm_mul_sd(half, _mm_add_sd(A, B));
            // Leave when the interval cannot shrink or m is not certain (one predictable branch).
            const __m128d stop = _mm_or_pd(_mm_or_pd(_mm_cmple_sd(M, A), _mm_cmpge_sd(M, B)),
                                           _mm_and_pd(_mm_cmpgt_sd(M, X1), _mm_cmplt_sd(M, X2)));
            if (_mm_movemask_pd(stop) & 1) break;
            const __m128d left = _mm_cmple_sd(M, X1);  // p(m) has fa's sign: m is the new a, else the new b
            A = _mm_or_pd(_mm_and_pd(left, M), _mm_andnot_pd(left, A));
            B = _mm_or_pd(_mm_andnot_pd(left, M), _mm_and_pd(left, B));
        }
        a = _mm_cvtsd_f64(A);
        b = _mm_cvtsd_f64(B);
    }
#endif
    for (; it < 200; ++it) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;  // interval can no longer shrink
        if (m <= x1 || m >= x2) {     // p(m) has fa's sign left of x1, the other right of x2
            const bool left = m <= x1;
            a = left ? m : a;
            b = left ? b : m;
            continue;
        }
        double fm = p(m);
        if (fm == 0.0) return m;
        if ((fm < 0) == (fa < 0)) { a = m; fa = fm; } else { b = m; }
    }
    return 0.5 * (a + b);
}

namespace {

double bisect(const Poly& p, double a, double b, double fa) { return bisect_root(p, a, b, fa); }

void roots_rec(const Poly& p, double lo, double hi, RootList& out) {
    if (p.deg == 0) return;
    if (p.deg == 1) {
        double flo = p(lo), fhi = p(hi);
        if ((flo < 0 && fhi > 0) || (flo > 0 && fhi < 0)) out.push(bisect(p, lo, hi, flo));
        else if (flo == 0.0 && fhi != 0.0) out.push(lo);
        else if (fhi == 0.0 && flo != 0.0) out.push(hi);
        return;
    }
    // Every evaluation below would have the same strict sign: nothing would be reported.
    if (one_sign_on(p, lo, hi)) return;
    Poly d = p.derivative();
    d.trim();
    RootList crit;
    roots_rec(d, lo, hi, crit);
    // Breakpoints lo < crit... < hi; p is monotone between consecutive ones.
    double pts[kMaxSignChangeRoots + 2];
    int np = 0;
    pts[np++] = lo;
    for (int k = 0; k < crit.n; ++k)
        if (crit.x[k] > pts[np - 1] && crit.x[k] < hi) pts[np++] = crit.x[k];
    pts[np++] = hi;
    double fa = p(pts[0]);
    for (int i = 0; i + 1 < np; ++i) {
        double fb = p(pts[i + 1]);
        if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out.push(bisect(p, pts[i], pts[i + 1], fa));
        else if (fa == 0.0 && (out.empty() || out.back() != pts[i])) {
            // An exact zero at a breakpoint counts as a sign change only if the sign really changes.
            double l = i == 0 ? fa : p(0.5 * (pts[i - 1] + pts[i]));
            double r = p(0.5 * (pts[i] + pts[i + 1]));
            if (i == 0 || (l < 0) != (r < 0)) out.push(pts[i]);
        }
        fa = fb;
    }
    if (fa == 0.0 && (out.empty() || out.back() != hi)) out.push(hi);
}

}  // namespace

bool one_sign_on(const Poly& p, double lo, double hi) {
    const int n = p.deg;
    assert(n >= 0 && n < 8);
    if (n == 0) return p.c[0] != 0.0;
    // p(m + t) = sum b_k t^k around the middle m, for |t| <= r.
    const double m = 0.5 * (lo + hi), M = std::max(std::fabs(lo), std::fabs(hi));
    const double r = 0.5 * (hi - lo) + 0x1p-50 * M;  // covers the rounding of m
    double b[8];
    for (int i = 0; i <= n; ++i) b[i] = p.c[i];
    for (int k = 0; k < n; ++k)
        for (int i = n - 1; i >= k; --i) b[i] += m * b[i + 1];
    double spread = 0, size = 0;  // sum_k>=1 |b_k| r^k, and sum_i |c_i| M^i
    for (int i = n; i >= 1; --i) spread = (spread + std::fabs(b[i])) * r;
    for (int i = n; i >= 0; --i) size = size * M + std::fabs(p.c[i]);
    // |p(x) - b_0| <= spread for the exact coefficients; the rounding of the shift, of `spread`
    // and of Horner's evaluation of p(x) are each below 2 n eps * size (and far below 1e-13).
    return std::fabs(b[0]) > spread * (1 + 1e-12) + 1e-13 * size;
}

bool no_sign_change(const Poly& p0, double lo, double hi) {
    if (!(lo < hi)) return true;
    Poly p = p0;
    p.trim();
    if (p.deg == 0) return true;
    if (p.deg == 1) {  // what roots_rec evaluates for a line: a root needs a sign change or a zero
        const double flo = p(lo), fhi = p(hi);
        return (flo > 0 && fhi > 0) || (flo < 0 && fhi < 0);
    }
    return one_sign_on(p, lo, hi);  // roots_rec's own first test
}

int sign_change_roots(const Poly& p0, double lo, double hi, double (&out)[kMaxSignChangeRoots]) {
    if (!(lo < hi)) return 0;
    Poly p = p0;
    p.trim();
    RootList roots;
    roots_rec(p, lo, hi, roots);
    std::sort(roots.x, roots.x + roots.n);
    int n = (int)(std::unique(roots.x, roots.x + roots.n) - roots.x);
    std::copy(roots.x, roots.x + n, out);
    return n;
}

std::vector<double> sign_change_roots(const Poly& p, double lo, double hi) {
    double roots[kMaxSignChangeRoots];
    int n = sign_change_roots(p, lo, hi, roots);
    return std::vector<double>(roots, roots + n);
}

}  // namespace hlens
