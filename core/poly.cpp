#include "poly.h"

#include <algorithm>
#include <cassert>
#include <cmath>

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

// The one root of p in [a, b] given p(a), p(b) of opposite signs.
double bisect(const Poly& p, double a, double b, double fa) {
    for (int it = 0; it < 200; ++it) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;  // interval can no longer shrink
        double fm = p(m);
        if (fm == 0.0) return m;
        if ((fm < 0) == (fa < 0)) { a = m; fa = fm; } else { b = m; }
    }
    return 0.5 * (a + b);
}

void roots_rec(const Poly& p, double lo, double hi, std::vector<double>& out) {
    if (p.deg == 0) return;
    if (p.deg == 1) {
        double flo = p(lo), fhi = p(hi);
        if ((flo < 0 && fhi > 0) || (flo > 0 && fhi < 0)) out.push_back(bisect(p, lo, hi, flo));
        else if (flo == 0.0 && fhi != 0.0) out.push_back(lo);
        else if (fhi == 0.0 && flo != 0.0) out.push_back(hi);
        return;
    }
    Poly d = p.derivative();
    d.trim();
    std::vector<double> crit;
    roots_rec(d, lo, hi, crit);
    // Breakpoints lo < crit... < hi; p is monotone between consecutive ones.
    std::vector<double> pts;
    pts.reserve(crit.size() + 2);
    pts.push_back(lo);
    for (double x : crit)
        if (x > pts.back() && x < hi) pts.push_back(x);
    pts.push_back(hi);
    double fa = p(pts[0]);
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
        double fb = p(pts[i + 1]);
        if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out.push_back(bisect(p, pts[i], pts[i + 1], fa));
        else if (fa == 0.0 && (out.empty() || out.back() != pts[i])) {
            // An exact zero at a breakpoint counts as a sign change only if the sign really changes.
            double l = i == 0 ? fa : p(0.5 * (pts[i - 1] + pts[i]));
            double r = p(0.5 * (pts[i] + pts[i + 1]));
            if (i == 0 || (l < 0) != (r < 0)) out.push_back(pts[i]);
        }
        fa = fb;
    }
    if (fa == 0.0 && pts.size() >= 2 && (out.empty() || out.back() != hi)) out.push_back(hi);
}

}  // namespace

std::vector<double> sign_change_roots(const Poly& p0, double lo, double hi) {
    std::vector<double> out;
    if (!(lo < hi)) return out;
    Poly p = p0;
    p.trim();
    roots_rec(p, lo, hi, out);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace hlens
