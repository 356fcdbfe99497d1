// Real roots of small univariate polynomials on an interval.
//
// Every maximum on an arc and every crossing of a curve with an arc ends in the real roots of a
// polynomial of degree <= 5 on an interval (design notes, "Where the maximum is"). We isolate them
// by recursion on the derivative: the roots of p' split [lo, hi] into pieces on which p is
// monotone, so each sign change on a piece holds exactly one root, found by safeguarded bisection.
// No sampling is involved, so no root between samples can be missed.
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

}  // namespace hlens
