// Root isolation (core/poly.h) and the composition of a quadratic with an arc (core/conic.h)
// against independent oracles: polynomials built from known roots, a textbook bisection written
// out here, dense evaluation, and direct evaluation of q along the curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include <hlens/conic.h>
#include <hlens/poly.h>

using namespace hlens;

namespace {

// a * prod (x - r_i), expanded.
Poly from_roots(double a, const std::vector<double>& roots) {
    Poly p;
    p.deg = 0;
    p.c[0] = a;
    for (double r : roots) {
        Poly f;
        f.deg = 1;
        f.c[0] = -r;
        f.c[1] = 1;
        p = p * f;
    }
    return p;
}

// The textbook bisection the library's must match bit for bit: evaluate p at every midpoint.
double plain_bisection(const Poly& p, double a, double b, double fa) {
    for (int it = 0; it < 200; ++it) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        double fm = p(m);
        if (fm == 0.0) return m;
        if ((fm < 0) == (fa < 0)) { a = m; fa = fm; } else { b = m; }
    }
    return 0.5 * (a + b);
}

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

}  // namespace

TEST(Poly, RootsOfProductsOfKnownRoots) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double lo = -0.7 + 0.2 * U(rng), hi = 0.8 + 0.2 * U(rng);
        std::vector<double> simple, doubled;
        const int ns = 1 + trial % 5, nd = trial % 3 == 0 ? 1 : 0;
        for (int k = 0; k < ns; ++k) simple.push_back(1.2 * U(rng));
        for (int k = 0; k < nd && ns + 2 * nd <= 7; ++k) doubled.push_back(0.9 * U(rng));
        std::vector<double> all = simple;
        for (double r : doubled) all.insert(all.end(), {r, r});
        const double scale = std::pow(10.0, 6 * U(rng));
        Poly p = from_roots(scale, all);
        // Separated roots only: the oracle is the roots themselves, up to a tolerance.
        std::vector<double> sorted = all;
        std::sort(sorted.begin(), sorted.end());
        bool separated = true;
        for (size_t i = 0; i + 1 < sorted.size(); ++i)
            if (sorted[i + 1] - sorted[i] < 1e-3 && !(std::count(doubled.begin(), doubled.end(), sorted[i]) > 0)) separated = false;
        for (double r : all)
            if (std::fabs(r - lo) < 1e-3 || std::fabs(r - hi) < 1e-3) separated = false;
        for (double r : doubled)
            for (double s : simple) separated &= std::fabs(r - s) > 1e-3;
        if (!separated) continue;
        std::vector<double> expect;
        for (double r : simple)
            if (r > lo && r < hi) expect.push_back(r);
        std::sort(expect.begin(), expect.end());
        std::vector<double> got = sign_change_roots(p, lo, hi);
        // A double root is a touch, not a sign change; as evaluated it may dip across zero, and
        // then shows as two points right beside it (the documented behaviour): drop those.
        for (double r : doubled) {
            auto near = [&](double x) { return std::fabs(x - r) < 1e-5; };
            const long k = std::count_if(got.begin(), got.end(), near);
            EXPECT_TRUE(k == 0 || k == 2) << "trial " << trial;
            got.erase(std::remove_if(got.begin(), got.end(), near), got.end());
        }
        ASSERT_EQ(got.size(), expect.size()) << "trial " << trial;
        for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expect[i], 1e-7) << "trial " << trial;
        // The allocation-free form gives the same points.
        double arr[kMaxSignChangeRoots];
        const int n = sign_change_roots(p, lo, hi, arr);
        const std::vector<double> all_got = sign_change_roots(p, lo, hi);
        ASSERT_EQ(n, (int)all_got.size());
        for (int i = 0; i < n; ++i) EXPECT_TRUE(same_bits(arr[i], all_got[i]));
        ++checked;
    }
    EXPECT_GT(checked, 1000);
}

// bisect_root against plain bisection (every midpoint evaluated): the same root up to the noise
// of evaluating p, which no method can see through. Horner's error bound (Higham, Accuracy and
// Stability, eq. 5.3): |computed p(x) - p(x)| <= gamma_2n sum |c_i| |x|^i =: E, so where |p'| is
// the slope, a root is only defined to within about E / |p'|. Allowed: 16 times that, plus 2^-46
// of the interval's magnitude (bisect_root may stop at the middle of a bracket that wide).
TEST(Poly, BisectionAgreesWithThePlainOneToTheEvaluationsNoise) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> U(-1, 1);
    long compared = 0, exact = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const int deg = 1 + trial % 5;
        Poly p;
        p.deg = deg;
        const int kind = trial % 7;
        for (int i = 0; i <= deg; ++i) p.c[i] = U(rng) * std::pow(10.0, kind == 3 ? 8 * U(rng) : U(rng));
        if (kind == 4) p.c[1] *= 1e-12;                            // nearly flat
        if (kind == 5) p.c[0] = -(p.c[1] * 0.25 + p.c[2] * 0.0625);  // a root near 0.25 (exactly, for a line)
        double a = U(rng), b = a + std::pow(10.0, -6 * std::fabs(U(rng)));  // wide to tiny intervals
        if (kind == 6) { a = 1e6 + U(rng); b = a + 1; }                       // far from 0
        if (trial % 2 == 0) {  // a root inside [a, b] by construction, the others anywhere
            std::vector<double> roots{a + (b - a) * (0.5 + 0.499 * U(rng))};
            for (int i = 1; i < deg; ++i) roots.push_back(3 * U(rng));
            p = from_roots(std::pow(10.0, 3 * U(rng)), roots);
        }
        const double fa = p(a), fb = p(b);
        if (!((fa < 0 && fb > 0) || (fa > 0 && fb < 0))) continue;
        const double want = plain_bisection(p, a, b, fa), got = bisect_root(p, a, b, fa);
        const double M = std::max(std::fabs(a), std::fabs(b));
        double size = 0;
        for (int i = p.deg; i >= 0; --i) size = size * M + std::fabs(p.c[i]);
        const double E = 2 * p.deg * 0x1p-53 / (1 - 2 * p.deg * 0x1p-53) * size;
        const double slope = std::fabs(p.derivative()(want));
        const double tol = (slope > 0 ? 16 * E / slope : HUGE_VAL) + 0x1p-46 * M;
        ASSERT_GE(got, a) << "trial " << trial;
        ASSERT_LE(got, b) << "trial " << trial;
        ASSERT_LE(std::fabs(got - want), tol) << "trial " << trial << ": " << want << " vs " << got;
        exact += same_bits(want, got);
        {
            PlainBisection plain;  // the debugger's mode: plain bisection's root, bit for bit
            ASSERT_TRUE(same_bits(want, bisect_root(p, a, b, fa))) << "trial " << trial;
        }
        ++compared;
    }
    EXPECT_GT(compared, 3000);
    std::printf("[ info ] %ld of %ld roots equal to plain bisection's bit for bit\n", exact, compared);
    // A line's root, exactly representable.
    Poly line;
    line.deg = 1;
    line.c[0] = -0.5;
    line.c[1] = 1;
    EXPECT_NEAR(bisect_root(line, 0, 1, line(0)), 0.5, 1e-15);
}

TEST(Poly, OneSignOnIsNeverWrong) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> U(-1, 1);
    int said_yes = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const int deg = trial % 6;
        Poly p;
        p.deg = deg;
        for (int i = 0; i <= deg; ++i) p.c[i] = U(rng) * std::pow(10.0, 2 * U(rng));
        if (trial % 3 == 0) p.c[0] += 3 * std::fabs(p.c[0]) + 0.5;  // often no root nearby
        const double lo = 2 * U(rng), hi = lo + std::pow(10.0, -3 * std::fabs(U(rng))) * 2;
        if (!one_sign_on(p, lo, hi)) continue;
        ++said_yes;
        const double ref = p(lo);
        ASSERT_NE(ref, 0.0) << "trial " << trial;
        // Dense evaluation, the ends and the points next to them: all of one strict sign.
        for (int k = 0; k <= 400; ++k) {
            const double x = k == 400 ? hi : lo + (hi - lo) * k / 400.0;
            const double v = p(x);
            ASSERT_TRUE((v > 0) == (ref > 0) && v != 0) << "trial " << trial << " x " << x;
        }
        for (double x : {std::nextafter(lo, hi), std::nextafter(hi, lo)}) ASSERT_TRUE((p(x) > 0) == (ref > 0) && p(x) != 0);
        // And sign_change_roots agrees that there is nothing to find, as does no_sign_change.
        EXPECT_TRUE(sign_change_roots(p, lo, hi).empty());
        EXPECT_TRUE(no_sign_change(p, lo, hi));
    }
    EXPECT_GT(said_yes, 500);  // the test is useless if the bound never succeeds
    // Obvious cases.
    Poly bowl = from_roots(1, {});
    bowl.deg = 2;
    bowl.c[0] = 2;
    bowl.c[2] = 1;  // 2 + x^2
    EXPECT_TRUE(one_sign_on(bowl, -1, 1));
    EXPECT_FALSE(one_sign_on(from_roots(1, {0.3}), 0, 1));
}

TEST(Poly, NoSignChangeMeansNoRoots) {
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> U(-1, 1);
    int yes = 0, no = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const int deg = trial % 5;
        Poly p;
        p.deg = 4;  // with zero leading coefficients, as compose() gives for straight arcs
        for (int i = 0; i <= deg; ++i) p.c[i] = U(rng);
        const double lo = U(rng), hi = lo + std::fabs(U(rng));
        if (no_sign_change(p, lo, hi)) {
            ++yes;
            EXPECT_TRUE(sign_change_roots(p, lo, hi).empty()) << "trial " << trial;
        } else {
            ++no;
        }
    }
    EXPECT_GT(yes, 1000);
    EXPECT_GT(no, 500);
    // A line vanishing exactly at an end has a root there: not "no sign change".
    Poly line;
    line.deg = 1;
    line.c[0] = -0.25;
    line.c[1] = 1;
    EXPECT_FALSE(no_sign_change(line, 0.25, 1));
    EXPECT_EQ(sign_change_roots(line, 0.25, 1).size(), 1u);
}

TEST(Conic, ComposeIsTheQuadraticAlongTheArc) {
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        RationalCurve c;
        c.n0 = {U(rng), U(rng)};
        c.n1 = {U(rng), U(rng)};
        const int kind = trial % 3;  // a line with w = 1, a parabola, a rational (conic) arc
        if (kind >= 1) c.n2 = {U(rng), U(rng)};
        if (kind == 2) { c.w0 = 1; c.w1 = 0.3 * U(rng); c.w2 = 0.5 + 0.4 * U(rng); }
        Quadratic2 q{U(rng), U(rng), U(rng), U(rng), U(rng), U(rng)};
        Poly F = c.compose(q), W = c.weight();
        // The definition: q.a X^2 + 2 q.b X Y + q.c Y^2 + 2 q.d X W + 2 q.e Y W + q.f W^2 by Poly
        // arithmetic; the unrolled form must give the same bits (it feeds every root search).
        if (!(c.straight() && c.w0 == 1)) {
            Poly X, Y;
            X.deg = Y.deg = 2;
            X.c[0] = c.n0.x; X.c[1] = c.n1.x; X.c[2] = c.n2.x;
            Y.c[0] = c.n0.y; Y.c[1] = c.n1.y; Y.c[2] = c.n2.y;
            Poly r = q.a * (X * X) + (2 * q.b) * (X * Y) + q.c * (Y * Y) + (2 * q.d) * (X * W) + (2 * q.e) * (Y * W) + q.f * (W * W);
            ASSERT_EQ(F.deg, 4);
            for (int i = 0; i <= 4; ++i) ASSERT_TRUE(same_bits(F.c[i], r.c[i])) << "trial " << trial << " c" << i;
        }
        // And numerically: q at the curve's point, times w^2.
        for (double z : {-0.7, -0.1, 0.0, 0.4, 0.9}) {
            const double w = W(z), direct = q(c(z)) * w * w;
            EXPECT_NEAR(F(z), direct, 1e-12 * (1 + std::fabs(direct)) * 16) << "trial " << trial;
        }
    }
}

namespace {

// q at (x, y) in long double; the root of q on the segment p0 -> p1, where q changes sign, by
// bisection; and the distance from a point to the nearest of a decomposition's components
// (through its feet). The oracles of the conic tests below.
long double q_at(const Quadratic2& q, long double x, long double y) {
    return q.a * x * x + 2 * q.b * x * y + q.c * y * y + 2 * q.d * x + 2 * q.e * y + (long double)q.f;
}
Vec2 root_between(const Quadratic2& q, Vec2 p0, Vec2 p1) {
    const bool neg0 = q_at(q, p0.x, p0.y) < 0;
    long double lo = 0, hi = 1;
    for (int it = 0; it < 80; ++it) {
        const long double m = (lo + hi) / 2;
        ((q_at(q, p0.x + m * (p1.x - p0.x), p0.y + m * (p1.y - p0.y)) < 0) == neg0 ? lo : hi) = m;
    }
    return {(double)(p0.x + lo * (p1.x - p0.x)), (double)(p0.y + lo * (p1.y - p0.y))};
}
double distance_to_components(const ConicDecomposition& d, Vec2 p) {
    double best = HUGE_VAL;
    for (const CurveComponent& c : d.components) {
        double feet[3];
        const int n = c.feet(p, feet);
        for (int k = 0; k < n; ++k) best = std::min(best, norm(c.at(feet[k]) - p));
    }
    return best;
}

}  // namespace

// The difference of two nearly parallel vertical planes' quadratics (generate_pairs.py "perp"
// 5811, these coefficients): a quadratic part 1.5e-8 of the linear part, whose smaller eigenvalue
// (1e-16) is rounding noise. Taken as an ellipse (semi-axes 7e7 and 9e11), its points near T' were
// 1.7e-4 off the curve and the split found no chord. The zero set must pass within 1e-9 of the
// crossings of q = 0 with two segments across T', found by bisection on q itself in long double.
TEST(Conic, NoiseEigenvalueOfASmallQuadraticPartMakesNoEllipse) {
    Quadratic2 q;
    q.a = -2.2120096270346488e-09; q.b = 5.3088229797980289e-09; q.c = -1.2741175526770654e-08;
    q.d = -0.41666666666666646; q.e = 0.99999999999999989; q.f = 0.41666666666666646;
    const ConicDecomposition d = decompose_conic(q);
    ASSERT_FALSE(d.components.empty());
    EXPECT_NE(d.type, ConicType::Ellipse);
    for (auto [p0, p1] : {std::pair<Vec2, Vec2>{{0.5, 0.1}, {1, 0}}, {{0.2, 0.3}, {0.9, -0.2}}}) {
        ASSERT_GT(q_at(q, p0.x, p0.y), 0);  // q(p0) > 0 > q(p1)
        ASSERT_LT(q_at(q, p1.x, p1.y), 0);
        const Vec2 root = root_between(q, p0, p1);
        double best = HUGE_VAL;
        for (const CurveComponent& c : d.components) best = std::min(best, norm(c.at(c.param_of(root)) - root));
        EXPECT_LT(best, 1e-9) << "root (" << root.x << ", " << root.y << ")";
    }
}


// A thin ellipse far from T' whose centre's rounding swallows it (generate_pairs4.py "thin_shell"
// 16846, nearest first, these coefficients): semi-axes 1782 and 1.8e-4, centred 1781 away along
// the axis whose eigenvalue (1e-14) is only central by the roots it moves. Its k (3.3e-8) lay
// within the rounding the central form allows it (4.5e-8, growing as the centre's distance
// squared), so it was taken as a point, and a strip of T' 1.8e-4 wide that it crosses was not
// cut. Near T' the zero set must pass within 1e-9 of the crossings of q = 0 with segments across
// the strip, found by bisection on q itself in long double.
TEST(Conic, FarThinEllipseWithinItsCentresRoundingIsNoPoint) {
    Quadratic2 q;
    q.a = 3.2970841246185888e-08; q.b = 0.00018157871777516884; q.c = 1;
    q.d = -3.2967103715339834e-08; q.e = -0.00018166117580304598; q.f = 3.2963364646851036e-08;
    const ConicDecomposition d = decompose_conic(q);
    ASSERT_FALSE(d.components.empty()) << conic_type_name(d.type);
    for (double x : {0.2, 0.5, 0.9}) {
        const double top = 1.81661e-4 - 1.81579e-4 * x;  // the strip's upper side
        const Vec2 p0{x, 0}, p1{x, 0.99 * top};          // q(p0) > 0 > q(p1)
        ASSERT_GT(q_at(q, p0.x, p0.y), 0) << x;
        ASSERT_LT(q_at(q, p1.x, p1.y), 0) << x;
        const Vec2 root = root_between(q, p0, p1);
        EXPECT_LT(distance_to_components(d, root), 1e-9) << "x " << x << " root y " << root.y;
    }
}

// An edge's quadratic less a nearly parallel plane's (generate_pairs9.py "tinydiff_coinc_far" 2315,
// side A, target 2, these coefficients): l2 = -1.6e-14 of l1, the centre 70 away, branches 1.05e-6
// either side of the edge's line across T'. The central form's k (7.5e-11) is within its rounding
// (8e-11, k and l2 Y0^2 nearly cancelling), and zeroed it made a line pair 8.1e-6 either side:
// the strip where the edge is nearer was not cut. The zero set must pass near the crossings of
// q = 0 with segments across both branches, found by bisection on q in long double: within what
// the parabolic form drops, l2 (Y - Yr)^2 <= 4 |l2| = 6.4e-14, which moves roots 2.1e-6 apart by
// at most 6.4e-14 / (2 sqrt(disc) + sqrt(6.4e-14 l1)) = 2.4e-8 (disc = 1.5e-12, l1 = 1.17 scaled;
// 1.3e-9 measured).
TEST(Conic, LinePairOfAZeroedKIsTakenAsItsBranchesNearT) {
    Quadratic2 q;
    q.a = 0.85501461607865792; q.b = 0.35208610079096087; q.c = 0.14498538392092755;
    q.d = -0.59792380573416914; q.e = -0.24621878664182661; q.f = 0.41813656835809498;
    const ConicDecomposition d = decompose_conic(q);
    ASSERT_FALSE(d.components.empty()) << conic_type_name(d.type);
    const Vec2 c{0.579355342689, 0.291310902648}, e{0.602287098052, 0.235622859401};  // on the edge's line
    const Vec2 n{0.924670004, 0.380769463};                                               // its normal
    for (double t : {-0.5, 0.0, 0.5, 1.0, 4.0})
        for (double side : {1.0, -1.0}) {
            const Vec2 p0 = c + t * (e - c), p1 = p0 + (side * 3e-6) * n;
            ASSERT_LT(q_at(q, p0.x, p0.y), 0) << t;
            ASSERT_GT(q_at(q, p1.x, p1.y), 0) << t << " " << side;
            EXPECT_LT(distance_to_components(d, root_between(q, p0, p1)), 2.5e-8) << "t " << t << " side " << side;
        }
}

// Two nearly parallel lines whose quadratic part has a small eigenvalue just above its rounding
// (generate_pairs4.py "thin_shell" 14534, nearest first, these coefficients: l2 = -5.2e-14 of
// l1). As a line pair crossing 600 away each line lay 4.2e-7 off the curve near T' (their angle
// is l2's rounding magnified), and a sliver 2e-6 wide between a line and its chord kept a source
// 0.5% farther in d^2. The zero set must pass within 1e-9 of the crossings of q = 0 with
// segments across both lines, found by bisection on q itself in long double.
TEST(Conic, NearlyParallelLinesCrossingFarAwayStayOnTheirCurveNearT) {
    Quadratic2 q;
    q.a = 0.03999999999995231; q.b = 0.20000000000001589; q.c = 1;
    q.d = -0.080000000027284537; q.e = -0.39999999997276908; q.f = 0.15999998028375473;
    const ConicDecomposition d = decompose_conic(q);
    ASSERT_FALSE(d.components.empty()) << conic_type_name(d.type);
    for (double x : {0.34, 0.45, 0.54})
        for (double side : {1.0, -1.0}) {
            const double y0 = 0.4 - 0.2 * x;                  // between the lines: q < 0
            const Vec2 p0{x, y0}, p1{x, y0 + side * 3e-4};     // beyond one of them: q > 0
            ASSERT_LT(q_at(q, p0.x, p0.y), 0) << x;
            ASSERT_GT(q_at(q, p1.x, p1.y), 0) << x << " " << side;
            EXPECT_LT(distance_to_components(d, root_between(q, p0, p1)), 1e-9) << "x " << x << " side " << side;
        }
}

// A sliver's nearly vertical edge's quadratic less a vertex's (generate_pairs11.py "combo" 363,
// side B, target 0, the paper's order, these coefficients of the difference): both parts have
// coefficients at most 1, the edge's 1 - 9e-11 on the diagonal, so the difference's part is rank
// one, -9.2e-11 (x - y)^2, but for rounding. Its smaller eigenvalue came out -1.65e-17 (1.35e-14
// scaled by 1/1.2e-3, above the fixed 1e-14 floor, below an ulp of the operands) and it was taken
// as an ellipse 1e10 long, whose points near T' were 1e-6 off the curve: no chord, and a face went
// whole to the farther source. Given the operands' rounding, the zero set must pass within 1e-9
// of the crossings of q = 0 with segments across it, by bisection on q itself in long double.
TEST(Conic, RankOneDifferenceWithinItsOperandsRoundingIsNoEllipse) {
    Quadratic2 q;
    q.a = -9.2042595767338753e-11; q.b = 9.204257929276412e-11; q.c = -9.2042595767338753e-11;
    q.d = -0.00089620925521105566; q.e = 0.00089620925521100014; q.f = 0.001218863009219473;
    ConicDecomposition d;
    decompose_conic(q, d, 8 * 0x1p-52 * 1.0);  // the operands' parts are at most 1
    ASSERT_FALSE(d.components.empty()) << conic_type_name(d.type);
    EXPECT_NE(d.type, ConicType::Ellipse);
    for (double y : {0.0, 0.1, 0.25}) {
        const Vec2 p0{y + 0.66, y}, p1{y + 0.70, y};  // either side of x - y = 0.68, near the curve
        ASSERT_GT(q_at(q, p0.x, p0.y), 0) << y;
        ASSERT_LT(q_at(q, p1.x, p1.y), 0) << y;
        EXPECT_LT(distance_to_components(d, root_between(q, p0, p1)), 1e-9) << "y " << y;
    }
}

// A line pair centred far from T' whose second line's foot of the origin is the centre
// (generate_pairs13.py "ties_cube_center" 4384, side A, target 7, the paper's order: an edge's
// quadratic less a face's, both 1.3e8 from a target at a cube's centre, y (16384 - x) but for
// 3e-16 of noise in x^2 and y^2). Each line through a centre that far is moved onto q = 0 along its
// normal at its foot of the origin, which for x = 16384 is the centre: along y = 0, where q is that
// noise alone, whose root is x = 0. The line came out as x = 0, across T'. Now only lines that pass
// near T' are moved. Oracle: q's sign, in long double: q > 0 over T' above y = 0, and its zero
// across y = 0 on a component.
TEST(Conic, FarLinePairsOtherLineStaysFarFromT) {
    Quadratic2 q;
    q.a = 3.3306690738754696e-16; q.b = -1; q.c = -3.3306690738754696e-16;
    q.d = 0; q.e = 16384; q.f = 0;
    ConicDecomposition d;
    decompose_conic(q, d, 8 * 0x1p-52 * 0.5);  // the operands' parts are at most 0.5
    ASSERT_FALSE(d.components.empty()) << conic_type_name(d.type);
    for (double x : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        ASSERT_GT(q_at(q, x, 1e-3), 0) << x;
        EXPECT_GT(distance_to_components(d, {x, 0.5}), 0.4) << "x " << x;  // nothing crosses T' above y = 0
        const Vec2 p0{x, -1e-3}, p1{x, 1e-3};
        ASSERT_LT(q_at(q, p0.x, p0.y), 0) << x;
        EXPECT_LT(distance_to_components(d, root_between(q, p0, p1)), 1e-9) << "x " << x;
    }
}
