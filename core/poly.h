// Real roots of small univariate polynomials on an interval.
//
// Every maximum on an arc and every crossing of a curve with an arc ends in the real roots of a
// polynomial of degree <= 5 on an interval (design notes, "Where the maximum is"). We isolate them
// by recursion on the derivative: the roots of p' split [lo, hi] into pieces on which p is
// monotone, so each sign change on a piece holds exactly one root, found by safeguarded bisection.
// No sampling is involved, so no root between samples can be missed. Before recursing, a bound of
// p over the interval (its Taylor expansion at the middle) shows most polynomials have one strict
// sign there, even as evaluated in floating point: then there is nothing to find, and the
// recursion is skipped (the answer is the same, empty, either way).
#pragma once
#include <vector>

namespace hlens {

// Polynomial c[0] + c[1] x + ... + c[deg] x^deg.
struct Poly {
    double c[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    int deg = 0;
    double operator()(double x) const {
        double r = c[deg];
        for (int i = deg - 1; i >= 0; --i) r = r * x + c[i];
        return r;
    }
    Poly derivative() const;
    void trim();  // drop exactly-zero leading coefficients
};

Poly operator*(const Poly& a, const Poly& b);
Poly operator+(const Poly& a, const Poly& b);
Poly operator*(double s, const Poly& a);

// Points in [lo, hi] where p changes sign, ascending. A root of even multiplicity (a touch without
// a sign change) is not reported: callers that care handle tangency through their own tolerances.
std::vector<double> sign_change_roots(const Poly& p, double lo, double hi);

// The same points without allocating: written to `out`, their number returned.
constexpr int kMaxSignChangeRoots = 16;  // > 2 deg - 1, the most the recursion can report
int sign_change_roots(const Poly& p, double lo, double hi, double (&out)[kMaxSignChangeRoots]);

// The root of p in [a, b], given fa = p(a) and p(b) of opposite signs. A line's by one division;
// where p is monotone there
// with a slope that makes the root's position certain to within the evaluation's rounding (most
// calls), the middle of that proved bracket; otherwise by bisection: the midpoint where p
// evaluates to exactly 0, or the last midpoint once the interval cannot shrink, with the
// evaluations whose sign is certain skipped.
double bisect_root(const Poly& p, double a, double b, double fa);

// While one of these lives, bisect_root on this thread always bisects (no short cut): the roots,
// and so every vertex of a domain mesh, are those of the plain bisection to the bit. The paper's
// insertion takes one while someone watches its events (the debugger, `trace`), so that its event
// stream does not move with the short cuts.
struct PlainBisection {
    PlainBisection();
    ~PlainBisection();
    PlainBisection(const PlainBisection&) = delete;
    PlainBisection& operator=(const PlainBisection&) = delete;
};

// True if sign_change_roots(p, lo, hi) certainly finds nothing, by a cheap test (the two ends of a
// line, one_sign_on otherwise); false when unsure.
bool no_sign_change(const Poly& p, double lo, double hi);

// True if every value of p on [lo, hi], also as computed by operator(), is nonzero and has one
// sign: a conservative test (false when unsure), for skipping root searches that find nothing.
bool one_sign_on(const Poly& p, double lo, double hi);

}  // namespace hlens
