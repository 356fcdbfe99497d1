// Independent QA generator + checker for Hausdorff Lens on random degenerate mesh pairs (issue 8).
// Written by a second author who did not read tests/degenerate_pairs.h: its own kinds, its own
// long-double brute force (distances, branch-and-bound bounds of the one-sided distance). CI runs
// its first 1000 seeds (ctest independent_pairs, with --every-target) and some that once failed;
// every check passes on seeds 0..39999 (README, "Tolerances and degenerate input"): run by hand
// for more seeds, e.g.
// `build/bin/hlens_check_pairs 0 28000`. DUMP=prefix writes each pair as prefix_a.obj and prefix_b.obj.
// Usage: hlens_check_pairs SEED_FROM SEED_TO [KIND_FILTER] [--no-fork] [--verbose] [--every-target]
//        [--thorough] (--every-target with validate(true) after every insertion) [--max-width REL]
//        (check 6 on every pair: both modes' certified intervals at most REL of the diagonal;
//        without it, paper mode's at most 1e-9 on near-coincident pairs far from the origin only)
//        hlens_check_pairs --pairs DIR [...]: every DIR/NAME_a.obj, DIR/NAME_b.obj (another
//        generator's pairs, e.g. generate_pairs.py), numbered in name order as "seed"
//   kind of seed = kinds[seed % NKINDS]; the RNG is std::mt19937(seed).
// Output: one line per failure: "FAIL seed=<s> kind=<k> check=<c> | <message>"
//         one line per seed:    "SEED <s> <k> nA=.. nB=.. ok|fail time=.."
#include <hlens/hausdorff.h>
#include <hlens/mesh_io.h>
#include <hlens/label_check.h>
#include <hlens/mesh.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <queue>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hlens;
typedef long double LD;

// ------------------------------------------------------------------------------------------------
// Generator (local coordinates, size ~1), then a global similarity transform.
// ------------------------------------------------------------------------------------------------
struct P3 { double x, y, z; };
struct LM {
    std::vector<P3> p;
    std::vector<std::array<uint32_t, 3>> t;
    uint32_t v(double x, double y, double z) { p.push_back({x, y, z}); return (uint32_t)p.size() - 1; }
    uint32_t v(P3 q) { p.push_back(q); return (uint32_t)p.size() - 1; }
    void tri(uint32_t a, uint32_t b, uint32_t c) { t.push_back({a, b, c}); }
    void tri(P3 a, P3 b, P3 c) { uint32_t i = v(a), j = v(b), k = v(c); tri(i, j, k); }
};

struct Rng {
    std::mt19937 g;
    explicit Rng(unsigned s) : g(s) {}
    double u(double a = 0, double b = 1) { return std::uniform_real_distribution<double>(a, b)(g); }
    int i(int a, int b) { return std::uniform_int_distribution<int>(a, b)(g); }  // inclusive
    bool p(double prob) { return u() < prob; }
    double e10(double a, double b) { return std::pow(10.0, u(a, b)); }
    double sgn() { return p(0.5) ? 1.0 : -1.0; }
};

static P3 add(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
static P3 sub(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static P3 mul(P3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
static P3 crs(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static double dt(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static P3 unit(P3 a) { double n = std::sqrt(dt(a, a)); return n > 0 ? mul(a, 1 / n) : P3{1, 0, 0}; }
static P3 rand_dir(Rng& r) {
    for (;;) {
        P3 d{r.u(-1, 1), r.u(-1, 1), r.u(-1, 1)};
        double n = dt(d, d);
        if (n > 1e-4 && n <= 1) return mul(d, 1 / std::sqrt(n));
    }
}
// Rotation matrix (rows) from a unit quaternion.
struct Rot { double m[3][3]; P3 ap(P3 q) const {
    return {m[0][0] * q.x + m[0][1] * q.y + m[0][2] * q.z, m[1][0] * q.x + m[1][1] * q.y + m[1][2] * q.z,
            m[2][0] * q.x + m[2][1] * q.y + m[2][2] * q.z}; } };
static Rot rot_quat(double w, double x, double y, double z) {
    double n = std::sqrt(w * w + x * x + y * y + z * z); w /= n; x /= n; y /= n; z /= n;
    Rot R;
    R.m[0][0] = 1 - 2 * (y * y + z * z); R.m[0][1] = 2 * (x * y - w * z); R.m[0][2] = 2 * (x * z + w * y);
    R.m[1][0] = 2 * (x * y + w * z); R.m[1][1] = 1 - 2 * (x * x + z * z); R.m[1][2] = 2 * (y * z - w * x);
    R.m[2][0] = 2 * (x * z - w * y); R.m[2][1] = 2 * (y * z + w * x); R.m[2][2] = 1 - 2 * (x * x + y * y);
    return R;
}
static Rot rand_rot(Rng& r) {  // Shoemake uniform
    double u1 = r.u(), u2 = r.u(0, 2 * M_PI), u3 = r.u(0, 2 * M_PI);
    double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    return rot_quat(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3));
}
static Rot axis_rot(Rng& r) {  // signed permutation: exact
    int perm[3] = {0, 1, 2};
    std::shuffle(perm, perm + 3, r.g);
    Rot R{};
    for (int i = 0; i < 3; ++i) R.m[i][perm[i]] = r.sgn();
    return R;
}
static Rot rot_axis_angle(P3 ax, double ang) {
    ax = unit(ax);
    double s = std::sin(ang / 2);
    return rot_quat(std::cos(ang / 2), ax.x * s, ax.y * s, ax.z * s);
}

// grid over [x0,x0+w]x[y0,y0+h] at z = f(x,y); random diagonals
static void grid(LM& m, Rng& r, int nx, int ny, double x0, double y0, double w, double h,
                 std::function<double(double, double)> f = nullptr) {
    uint32_t base = (uint32_t)m.p.size();
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double x = x0 + w * i / nx, y = y0 + h * j / ny;
            m.v(x, y, f ? f(x, y) : 0.0);
        }
    auto id = [&](int i, int j) { return base + (uint32_t)(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (r.p(0.5)) { m.tri(a, b, c); m.tri(a, c, d); }
            else { m.tri(a, b, d); m.tri(b, c, d); }
        }
}
static void transform_local(LM& m, const Rot& R, P3 shift) {
    for (P3& q : m.p) q = add(R.ap(q), shift);
}
static void reverse_some(LM& m, Rng& r, double prob) {
    for (auto& t : m.t) if (r.p(prob)) std::swap(t[1], t[2]);
}
static void shuffle_tris(LM& m, Rng& r) { std::shuffle(m.t.begin(), m.t.end(), r.g); }
static void duplicate_some(LM& m, Rng& r, int k, bool new_vertices) {
    int n = (int)m.t.size();
    for (int q = 0; q < k && n > 0; ++q) {
        auto t = m.t[r.i(0, n - 1)];
        if (new_vertices || r.p(0.5)) { t = {m.v(m.p[t[0]]), m.v(m.p[t[1]]), m.v(m.p[t[2]])}; }
        if (r.p(0.3)) std::rotate(t.begin(), t.begin() + 1, t.end());
        if (r.p(0.3)) std::swap(t[1], t[2]);
        m.t.push_back(t);
    }
}
static LM copy_mesh(const LM& a) { return a; }

struct Pair {
    std::string kind;
    std::string note;  // parameters for the report
    TriangleMesh A, B;
    bool near_coincident_far = false;
};

static const char* kKinds[] = {"coplanar_overlap", "tilted_grid",  "sliver",      "perpendicular", "shared_edge",
                               "zero_area",        "near_coinc_far", "dup_faces", "t_junction",    "fan",
                               "mirror",           "jitter_grid",  "needle_threshold", "parallel_offset", "identical",
                               "soup"};
static const int NKINDS = sizeof(kKinds) / sizeof(kKinds[0]);

static std::string fmt(const char* f, ...) {
    char buf[1024];
    va_list ap; va_start(ap, f); vsnprintf(buf, sizeof buf, f, ap); va_end(ap);
    return buf;
}

static TriangleMesh to_world(const LM& m, const Rot& R, double s, const LD off[3]) {
    TriangleMesh T;
    for (const P3& q : m.p) {
        LD x = (LD)R.m[0][0] * q.x + (LD)R.m[0][1] * q.y + (LD)R.m[0][2] * q.z;
        LD y = (LD)R.m[1][0] * q.x + (LD)R.m[1][1] * q.y + (LD)R.m[1][2] * q.z;
        LD z = (LD)R.m[2][0] * q.x + (LD)R.m[2][1] * q.y + (LD)R.m[2][2] * q.z;
        T.positions.push_back(Vec3((double)(x * s + off[0]), (double)(y * s + off[1]), (double)(z * s + off[2])));
    }
    for (auto& t : m.t) T.triangles.push_back({t[0], t[1], t[2]});
    return T;
}

static Pair generate(unsigned seed) {
    Rng r(seed * 2654435761u + 12345u);
    Pair P;
    P.kind = kKinds[seed % NKINDS];
    const std::string& k = P.kind;
    LM A, B;
    std::ostringstream note;

    if (k == "coplanar_overlap") {
        int ax = r.i(1, 4), ay = r.i(1, 4);
        double h = r.u(0.3, 1.0);
        grid(A, r, ax, ay, 0, 0, 1, h);
        int mode = r.i(0, 3);
        note << "mode=" << mode;
        if (mode == 0) {  // same vertex lattice, other diagonals / sub-lattice
            grid(B, r, ax, ay, 0, 0, 1, h);
        } else if (mode == 1) {  // shifted other resolution
            grid(B, r, r.i(1, 5), r.i(1, 5), r.u(-0.5, 0.5), r.u(-0.5, 0.5), r.u(0.5, 1.5), r.u(0.3, 1.2));
        } else if (mode == 2) {  // rotated in plane
            grid(B, r, r.i(1, 4), r.i(1, 4), -0.5, -0.5, r.u(0.6, 1.4), r.u(0.6, 1.4));
            double th = r.p(0.5) ? r.u(0, 2 * M_PI) : r.e10(-9, -3);
            transform_local(B, rot_axis_angle({0, 0, 1}, th), {0.5 + r.u(-0.2, 0.2), h / 2, 0});
            note << " th=" << th;
        } else {  // B contains copies of some of A's triangles + own grid
            grid(B, r, r.i(1, 3), r.i(1, 3), r.u(-0.3, 0.3), r.u(-0.3, 0.3), 1, h);
            for (int q = 0; q < r.i(1, 3); ++q) { auto t = A.t[r.i(0, (int)A.t.size() - 1)]; B.tri(A.p[t[0]], A.p[t[1]], A.p[t[2]]); }
        }
    } else if (k == "tilted_grid") {
        grid(A, r, r.i(1, 4), r.i(1, 4), 0, 0, 1, r.u(0.4, 1));
        grid(B, r, r.i(1, 4), r.i(1, 4), r.u(-0.3, 0.3), r.u(-0.3, 0.3), r.u(0.6, 1.3), r.u(0.6, 1.3));
        double ang = r.e10(-10, -2) * r.sgn();
        double th = r.u(0, 2 * M_PI);
        double dz = r.p(0.3) ? 0.0 : r.e10(-12, -3) * r.sgn();
        transform_local(B, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {-0.5, -0.5, 0});
        transform_local(B, rot_axis_angle({std::cos(th), std::sin(th), 0}, ang), {0.5, 0.5, dz});
        if (r.p(0.3)) {  // both tilted slightly differently
            transform_local(A, rot_axis_angle({std::sin(th), std::cos(th), 0}, r.e10(-10, -4)), {0, 0, 0});
        }
        note << "ang=" << ang << " dz=" << dz;
    } else if (k == "sliver") {
        auto add_slivers = [&](LM& m, int n) {
            for (int q = 0; q < n; ++q) {
                P3 a{r.u(), r.u(), r.p(0.5) ? 0.0 : r.u(-0.05, 0.05)}, b{r.u(), r.u(), r.p(0.5) ? 0.0 : r.u(-0.05, 0.05)};
                P3 d = sub(b, a);
                double L = std::sqrt(dt(d, d));
                double h = r.e10(-14, -5) * L, t = r.u(-0.5, 1.5);
                P3 nrm = r.p(0.5) ? unit(crs(d, {0, 0, 1})) : unit(crs(d, rand_dir(r)));
                P3 c = add(add(a, mul(d, t)), mul(nrm, h));
                m.tri(a, b, c);
            }
        };
        if (r.p(0.6)) grid(A, r, r.i(1, 2), r.i(1, 2), 0, 0, 1, 1);
        add_slivers(A, r.i(1, 6));
        if (r.p(0.5)) grid(B, r, r.i(1, 3), r.i(1, 3), r.u(-0.2, 0.2), r.u(-0.2, 0.2), 1, 1, [&](double, double) { return 0.0; });
        add_slivers(B, r.i(1, 6));
        if (r.p(0.4)) duplicate_some(A, r, r.i(1, 3), false);
        if (r.p(0.4)) duplicate_some(B, r, r.i(1, 3), true);
    } else if (k == "perpendicular") {
        grid(A, r, r.i(1, 4), r.i(1, 4), 0, 0, 1, 1);
        int nb1 = r.i(1, 3), nb2 = r.i(1, 3);
        double c = r.p(0.4) ? (double)r.i(0, 4) / 4 : r.u(0, 1);
        double z0 = r.p(0.35) ? 0.0 : (r.p(0.5) ? -r.u(0.1, 0.5) : r.e10(-12, -2) * r.sgn());
        double y0 = r.u(-0.3, 0.3), y1 = r.u(0.7, 1.3), zh = r.u(0.2, 1.0);
        grid(B, r, nb1, nb2, y0, z0, y1 - y0, zh);
        for (P3& q : B.p) q = {c, q.x, q.y};  // plane x = c
        if (r.p(0.3)) transform_local(B, rot_axis_angle({0, 1, 0}, r.e10(-10, -3)), {0, 0, 0});
        note << "c=" << c << " z0=" << z0;
    } else if (k == "shared_edge") {
        uint32_t a0 = A.v(0, 0, 0), a1 = A.v(1, 0, 0);
        uint32_t b0 = B.v(0, 0, 0), b1 = B.v(1, 0, 0);
        int na = r.i(1, 3), nb = r.i(1, 3);
        std::vector<double> ths;
        for (int q = 0; q < na; ++q) {
            double th = r.u(0, 2 * M_PI), rad = r.u(0.2, 1), x = r.u(-0.3, 1.3);
            ths.push_back(th);
            A.tri(a0, a1, A.v(x, rad * std::cos(th), rad * std::sin(th)));
        }
        for (int q = 0; q < nb; ++q) {
            double th0 = ths[r.i(0, na - 1)], th;
            int m = r.i(0, 3);
            if (m == 0) th = th0;
            else if (m == 1) th = th0 + M_PI;
            else if (m == 2) th = th0 + r.e10(-9, -3) * r.sgn();
            else th = r.u(0, 2 * M_PI);
            double rad = r.u(0.2, 1), x = r.u(-0.3, 1.3);
            if (r.p(0.5)) B.tri(b0, b1, B.v(x, rad * std::cos(th), rad * std::sin(th)));
            else B.tri(b1, b0, B.v(x, rad * std::cos(th), rad * std::sin(th)));
        }
        if (r.p(0.3)) B.tri(P3{0, 0, 0}, P3{1, 0, 0}, P3{0.5, 0, 0});  // degenerate on the edge
    } else if (k == "zero_area") {
        auto add_zero = [&](LM& m, int n) {
            for (int q = 0; q < n; ++q) {
                P3 a{r.u(), r.u(), r.p(0.6) ? 0.0 : r.u(-0.2, 0.2)}, b{r.u(), r.u(), r.p(0.6) ? 0.0 : r.u(-0.2, 0.2)};
                int t = r.i(0, 4);
                if (t == 0) { double s = r.u(-0.5, 1.5); m.tri(a, b, add(a, mul(sub(b, a), s))); }
                else if (t == 1) m.tri(a, a, b);                       // two coincident vertices, distinct indices
                else if (t == 2) { uint32_t i = m.v(a), j = m.v(b); m.tri(i, i, j); }  // repeated index
                else if (t == 3) { uint32_t i = m.v(a); m.tri(i, i, i); }              // a point
                else m.tri(a, add(a, mul(sub(b, a), 0.5)), b);          // collinear, midpoint
            }
        };
        if (r.p(0.6)) grid(A, r, r.i(1, 3), r.i(1, 3), 0, 0, 1, 1);
        add_zero(A, r.i(1, 5));
        if (r.p(0.6)) grid(B, r, r.i(1, 3), r.i(1, 3), r.u(-0.2, 0.2), r.u(-0.2, 0.2), 1, 1, [&](double, double) { return 0.0; });
        add_zero(B, r.i(1, 5));
        if (r.p(0.5)) duplicate_some(B, r, 1, false);
    } else if (k == "near_coinc_far") {
        // handled after the transform (world-space offset)
        int nx = r.i(2, 4), ny = r.i(1, 2);
        grid(A, r, nx, ny, 0, 0, 1, r.u(0.3, 1), [&](double x, double y) { return 0.0 * x * y; });
        while (A.t.size() > 11) A.t.erase(A.t.begin() + r.i(0, (int)A.t.size() - 1));
        duplicate_some(A, r, r.i(1, 3), false);
        shuffle_tris(A, r);
        B = copy_mesh(A);
    } else if (k == "dup_faces") {
        bool curved = r.p(0.5);
        double c1 = r.u(-0.5, 0.5), c2 = r.u(-0.5, 0.5);
        grid(A, r, r.i(1, 4), r.i(1, 3), 0, 0, 1, 1, [&](double x, double y) { return curved ? c1 * x * x + c2 * x * y : 0.0; });
        duplicate_some(A, r, r.i(1, 5), false);
        int m = r.i(0, 2);
        B = copy_mesh(A);
        if (m == 0) {
            P3 d = mul(rand_dir(r), r.e10(-15, -6));
            for (P3& q : B.p) q = add(q, d);
            note << "shift=" << std::sqrt(dt(d, d));
        } else if (m == 1) {
            duplicate_some(B, r, r.i(1, 4), true);
            shuffle_tris(B, r);
        } else {
            reverse_some(B, r, 0.5);
        }
        note << " mode=" << m;
    } else if (k == "t_junction") {
        double hz = r.p(0.5) ? 0.0 : r.e10(-12, -3) * r.sgn();
        double mx = r.p(0.5) ? 0.5 : r.u(0.2, 0.8);  // junction position along the edge
        P3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0}, p3{1, 1, 0};
        P3 m{mx, 1 - mx, 0};  // on edge p1-p2 exactly-ish
        // A: big triangle p0 p1 p2, plus two triangles on the other side sharing m (T-junction)
        uint32_t i0 = A.v(p0), i1 = A.v(p1), i2 = A.v(p2), i3 = A.v(p3), im = A.v(m);
        A.tri(i0, i1, i2); A.tri(i1, i3, im); A.tri(im, i3, i2);
        // B: conforming triangulation, middle vertex possibly bent
        P3 mb = m; mb.z = hz;
        uint32_t j0 = B.v(p0), j1 = B.v(p1), j2 = B.v(p2), j3 = B.v(p3), jm = B.v(mb);
        B.tri(j0, j1, jm); B.tri(j0, jm, j2); B.tri(j1, j3, jm); B.tri(jm, j3, j2);
        if (r.p(0.5)) std::swap(A, B);
        note << "hz=" << hz << " mx=" << mx;
    } else if (k == "fan") {
        auto fan = [&](LM& m, P3 apex, int n, double H, double rot, bool closed) {
            uint32_t c = m.v(apex);
            std::vector<double> ang;
            for (int q = 0; q < n; ++q) ang.push_back(rot + (r.p(0.5) ? 2 * M_PI * q / n : r.u(0, 2 * M_PI)));
            std::sort(ang.begin(), ang.end());
            std::vector<uint32_t> rim;
            for (double a : ang) { double rad = r.u(0.5, 1); rim.push_back(m.v(rad * std::cos(a), rad * std::sin(a), H * r.u(-1, 1))); }
            for (int q = 0; q + 1 < n + (closed ? 1 : 0); ++q) m.tri(c, rim[q], rim[(q + 1) % n]);
        };
        double HA = r.p(0.3) ? 0.0 : (r.p(0.5) ? r.e10(-10, -4) : r.u(0.05, 0.5));
        double HB = r.p(0.3) ? 0.0 : (r.p(0.5) ? r.e10(-10, -4) : r.u(0.05, 0.5));
        fan(A, {0, 0, 0}, r.i(3, 12), HA, 0, r.p(0.7));
        P3 apexB{0, 0, 0};
        if (r.p(0.4)) apexB = mul(rand_dir(r), r.e10(-12, -4));
        fan(B, apexB, r.i(3, 12), HB, r.u(0, 1), r.p(0.7));
        note << "HA=" << HA << " HB=" << HB;
    } else if (k == "mirror") {
        int mode = r.i(0, 2);
        int n = r.i(1, 4);
        for (int q = 0; q < n; ++q) {
            P3 a{r.u(), r.u(), r.u(-0.5, 0.5)}, b{r.u(), r.u(), r.u(-0.5, 0.5)}, c{r.u(), r.u(), r.u(-0.5, 0.5)};
            if (mode == 1) { a.z = 0; b.z = 0; }                         // an edge in the mirror plane
            if (mode == 2) { double e = r.e10(-12, -4); a.z = e * r.u(-1, 1); b.z = e * r.u(-1, 1); c.z = e * r.u(-1, 1); }  // nearly in it
            A.tri(a, b, c);
            B.tri(P3{a.x, a.y, -a.z}, P3{c.x, c.y, -c.z}, P3{b.x, b.y, -b.z});
        }
        note << "mode=" << mode;
    } else if (k == "jitter_grid") {
        bool curved = r.p(0.5);
        double c1 = r.u(-0.4, 0.4);
        grid(A, r, r.i(1, 5), r.i(1, 5), 0, 0, 1, r.u(0.5, 1), [&](double x, double y) { return curved ? c1 * (x * x - y * y) : 0.0; });
        B = copy_mesh(A);
        int vi = r.i(0, (int)B.p.size() - 1);
        double eps = r.p(0.6) ? 1e-12 : r.e10(-15, -9);
        B.p[vi] = add(B.p[vi], mul(rand_dir(r), eps));
        if (r.p(0.3)) reverse_some(B, r, 1.0);
        note << "eps=" << eps << " v=" << vi;
    } else if (k == "needle_threshold") {
        // needles whose relative height straddles the 1e-7 sliver threshold
        auto needle = [&](LM& m) {
            P3 a{r.u(), r.u(), r.p(0.5) ? 0.0 : r.u(-0.1, 0.1)};
            P3 d = rand_dir(r); if (r.p(0.6)) { d.z = 0; d = unit(d); }
            double L = r.u(0.3, 1);
            double eps = r.e10(-8.5, -5.5);
            P3 side = unit(crs(d, r.p(0.5) ? P3{0, 0, 1} : rand_dir(r)));
            P3 b = add(a, mul(d, L));
            if (r.p(0.5)) m.tri(a, add(b, mul(side, eps * L)), add(b, mul(side, -eps * L)));           // needle: apex a
            else m.tri(a, b, add(add(a, mul(d, L * r.u(0.2, 0.8))), mul(side, 2 * eps * L)));        // flat sliver
        };
        for (int q = r.i(1, 4); q > 0; --q) needle(A);
        if (r.p(0.5)) grid(B, r, r.i(1, 3), r.i(1, 3), 0, 0, 1, 1);
        for (int q = r.i(1, 4); q > 0; --q) needle(B);
        if (r.p(0.3)) { auto t = A.t[0]; B.tri(A.p[t[0]], A.p[t[1]], A.p[t[2]]); }
    } else if (k == "parallel_offset") {
        bool curved = r.p(0.4);
        double c1 = r.u(-0.3, 0.3);
        grid(A, r, r.i(1, 4), r.i(1, 4), 0, 0, 1, 1, [&](double x, double y) { return curved ? c1 * x * y : 0.0; });
        double off = r.e10(-14, -4);
        if (r.p(0.5)) { B = copy_mesh(A); for (P3& q : B.p) q.z += off; }
        else grid(B, r, r.i(1, 4), r.i(1, 4), 0, 0, 1, 1, [&](double x, double y) { return (curved ? c1 * x * y : 0.0) + off; });
        note << "off=" << off;
    } else if (k == "identical") {
        int m = r.i(0, 2);
        if (m == 0) grid(A, r, r.i(1, 4), r.i(1, 4), 0, 0, 1, 1, [&](double x, double y) { return 0.3 * std::sin(3 * x + y); });
        else if (m == 1) { for (int q = r.i(1, 6); q > 0; --q) A.tri(P3{r.u(), r.u(), r.u()}, P3{r.u(), r.u(), r.u()}, P3{r.u(), r.u(), r.u()}); }
        else { grid(A, r, r.i(1, 3), r.i(1, 3), 0, 0, 1, 1); duplicate_some(A, r, 2, false); }
        B = copy_mesh(A);
        if (r.p(0.5)) shuffle_tris(B, r);
        if (r.p(0.5)) reverse_some(B, r, 0.5);
        if (r.p(0.3)) std::swap(A, B);
        note << "mode=" << m;
    } else {  // soup
        auto soup = [&](LM& m, int n, double spread) {
            for (int q = 0; q < n; ++q) {
                P3 c{r.u(0, spread), r.u(0, spread), r.u(0, spread)};
                double sz = r.u(0.1, 0.6);
                m.tri(add(c, mul(rand_dir(r), sz)), add(c, mul(rand_dir(r), sz)), add(c, mul(rand_dir(r), sz)));
            }
        };
        soup(A, r.i(2, 15), 1);
        soup(B, r.i(2, 15), 1);
        // snap some of B's vertices onto A's vertices
        for (int q = r.i(0, 3); q > 0; --q) B.p[r.i(0, (int)B.p.size() - 1)] = A.p[r.i(0, (int)A.p.size() - 1)];
    }

    // Global similarity transform
    Rot R;
    int rk = r.i(0, 99);
    if (rk < 55) R = rand_rot(r);
    else if (rk < 85) R = axis_rot(r);
    else R = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    double s;
    LD off[3] = {0, 0, 0};
    if (k == "near_coinc_far") {
        R = rand_rot(r);
        s = r.e10(-1, 3);
        P3 d = rand_dir(r);
        double mag = r.e10(4.5, 6);
        off[0] = std::round(d.x * mag); off[1] = std::round(d.y * mag); off[2] = std::round(d.z * mag);
    } else {
        s = r.e10(-6, 6);
        if (r.p(0.5)) {
            P3 d = r.p(0.3) ? P3{1, 0, 0} : rand_dir(r);
            double sizes = r.e10(0, 7);
            off[0] = (LD)d.x * sizes * s; off[1] = (LD)d.y * sizes * s; off[2] = (LD)d.z * sizes * s;
            note << " far=" << sizes << "sizes";
        }
    }
    P.A = to_world(A, R, s, off);
    P.B = to_world(B, R, s, off);
    if (k == "near_coinc_far") {
        P.near_coincident_far = true;
        int m = r.i(0, 2);
        P3 d = m == 0 ? R.ap({0, 0, 1}) : (m == 1 ? R.ap(unit({r.u(-1, 1), r.u(-1, 1), 0})) : rand_dir(r));
        double mag = 1e-3 * s * r.u(0.5, 2);
        for (Vec3& q : P.B.positions) q = Vec3(q.x + d.x * mag, q.y + d.y * mag, q.z + d.z * mag);
        if (r.p(0.3)) { auto t = P.B.triangles[0]; P.B.triangles.push_back({t[0], t[2], t[1]}); }
        note << " dirmode=" << m << " offset=" << mag;
    }
    note << " s=" << s << " off=(" << (double)off[0] << "," << (double)off[1] << "," << (double)off[2] << ")";
    P.note = note.str();
    return P;
}

// ------------------------------------------------------------------------------------------------
// Own brute force in long double (normals via __float128).
// ------------------------------------------------------------------------------------------------
struct V { LD x, y, z; };
static inline V vsub(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static inline V vadd(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
static inline V vmul(V a, LD s) { return {a.x * s, a.y * s, a.z * s}; }
static inline LD vdot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline V vcross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static inline V toV(const Vec3& p) { return {(LD)p.x, (LD)p.y, (LD)p.z}; }

struct BTri {
    V a, b, c;          // corners
    V ab, bc, ca;       // edges
    LD ab2, bc2, ca2;
    bool face = false;  // has a usable normal
    V n;                // unit normal
    V m1, m2, m3;       // inward edge normals (in plane)
    V lo, hi;           // box
};
static BTri make_btri(const Vec3& A, const Vec3& B, const Vec3& C) {
    BTri t;
    t.a = toV(A); t.b = toV(B); t.c = toV(C);
    t.ab = vsub(t.b, t.a); t.bc = vsub(t.c, t.b); t.ca = vsub(t.a, t.c);
    t.ab2 = vdot(t.ab, t.ab); t.bc2 = vdot(t.bc, t.bc); t.ca2 = vdot(t.ca, t.ca);
    typedef __float128 Q;
    Q e1[3] = {(Q)B.x - (Q)A.x, (Q)B.y - (Q)A.y, (Q)B.z - (Q)A.z};
    Q e2[3] = {(Q)C.x - (Q)A.x, (Q)C.y - (Q)A.y, (Q)C.z - (Q)A.z};
    Q n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    Q nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    LD L2 = std::max({t.ab2, t.bc2, t.ca2});
    // usable normal: |n| > 1e-24 * L^2 (height > 1e-24 * L)
    if ((LD)nn > 1e-48L * L2 * L2 && nn > 0) {
        // sqrt in long double of the float128 value, then normalise
        LD len = std::sqrt((LD)nn);
        // one Newton step in quad to refine
        Q ql = (Q)len; ql = (ql + nn / ql) / 2;
        t.n = {(LD)(n[0] / ql), (LD)(n[1] / ql), (LD)(n[2] / ql)};
        t.face = true;
        t.m1 = vcross(t.n, t.ab); t.m2 = vcross(t.n, t.bc); t.m3 = vcross(t.n, t.ca);
    }
    t.lo = {std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}), std::min({t.a.z, t.b.z, t.c.z})};
    t.hi = {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}), std::max({t.a.z, t.b.z, t.c.z})};
    return t;
}
static inline LD seg2(V p, V a, V d, LD dd) {
    V q = vsub(p, a);
    LD t = dd > 0 ? vdot(q, d) / dd : 0;
    t = std::min<LD>(1, std::max<LD>(0, t));
    V r = vsub(q, vmul(d, t));
    return vdot(r, r);
}
static LD tri_d2(V p, const BTri& t) {
    if (t.face) {
        V q = vsub(p, t.a);
        if (vdot(q, t.m1) >= 0 && vdot(vsub(p, t.b), t.m2) >= 0 && vdot(vsub(p, t.c), t.m3) >= 0) {
            LD s = vdot(q, t.n);
            return s * s;
        }
    }
    return std::min({seg2(p, t.a, t.ab, t.ab2), seg2(p, t.b, t.bc, t.bc2), seg2(p, t.c, t.ca, t.ca2)});
}
static inline LD box_d2(V p, const BTri& t) {
    LD d = 0, g;
    g = std::max<LD>({0, t.lo.x - p.x, p.x - t.hi.x}); d += g * g;
    g = std::max<LD>({0, t.lo.y - p.y, p.y - t.hi.y}); d += g * g;
    g = std::max<LD>({0, t.lo.z - p.z, p.z - t.hi.z}); d += g * g;
    return d;
}
static LD mesh_d(V p, const std::vector<BTri>& B) {
    LD best = INFINITY;
    for (const BTri& t : B) {
        if (box_d2(p, t) >= best) continue;
        best = std::min(best, tri_d2(p, t));
    }
    return std::sqrt(best);
}

struct Brute {
    LD vertex = 0;    // max over A's used vertices of d(v, B)
    LD sampled = 0;   // max over 10x10 barycentric samples (includes vertices)
    LD lb = 0, ub = 0;  // branch and bound bracket
    long nodes = 0;
    bool budget_hit = false;
};

static Brute brute(const TriangleMesh& A, const TriangleMesh& Bm, LD diag, long budget) {
    Brute out;
    std::vector<BTri> B;
    for (size_t i = 0; i < Bm.triangles.size(); ++i) {
        auto c = Bm.corners(i);
        B.push_back(make_btri(c[0], c[1], c[2]));
    }
    std::vector<char> used(A.positions.size(), 0);
    for (auto& t : A.triangles) for (uint32_t i : t) used[i] = 1;
    for (size_t i = 0; i < A.positions.size(); ++i)
        if (used[i]) out.vertex = std::max(out.vertex, mesh_d(toV(A.positions[i]), B));
    const int N = 10;
    LD samp = out.vertex;
    for (size_t ti = 0; ti < A.triangles.size(); ++ti) {
        auto c = A.corners(ti);
        V a = toV(c[0]), b = toV(c[1]), cc = toV(c[2]);
        for (int i = 0; i <= N; ++i)
            for (int j = 0; i + j <= N; ++j) {
                LD u = (LD)i / N, v = (LD)j / N, w = 1 - u - v;
                V p = vadd(vadd(vmul(a, w), vmul(b, u)), vmul(cc, v));
                samp = std::max(samp, mesh_d(p, B));
            }
    }
    out.sampled = samp;
    // Branch and bound over A: ub(node) = min( d(centroid) + R, min_T max_corner d(corner, T) )
    struct Node { V a, b, c; LD ub; bool operator<(const Node& o) const { return ub < o.ub; } };
    LD LB = samp;
    auto bound = [&](const V& a, const V& b, const V& c) -> LD {
        V m = vmul(vadd(vadd(a, b), c), 1.0L / 3);
        LD dm = mesh_d(m, B);
        LB = std::max(LB, dm);
        LD R = std::sqrt(std::max({vdot(vsub(a, m), vsub(a, m)), vdot(vsub(b, m), vsub(b, m)), vdot(vsub(c, m), vsub(c, m))}));
        LD u1 = dm + R;
        LD u2 = INFINITY;
        for (const BTri& t : B) {
            LD mx = std::max({tri_d2(a, t), tri_d2(b, t), tri_d2(c, t)});
            u2 = std::min(u2, mx);
        }
        u2 = std::sqrt(u2);
        // rounding of the bound itself (long double): tiny relative allowance
        return std::min(u1, u2) * (1 + 1e-17L);
    };
    std::priority_queue<Node> pq;
    for (size_t ti = 0; ti < A.triangles.size(); ++ti) {
        auto c = A.corners(ti);
        V a = toV(c[0]), b = toV(c[1]), cc = toV(c[2]);
        pq.push({a, b, cc, bound(a, b, cc)});
    }
    const LD tol = 1e-10L * diag;
    long nodes = 0;
    while (!pq.empty()) {
        Node n = pq.top();
        if (n.ub <= LB + tol) break;
        if (nodes >= budget) { out.budget_hit = true; break; }
        pq.pop();
        V ab = vmul(vadd(n.a, n.b), 0.5L), bc = vmul(vadd(n.b, n.c), 0.5L), ca = vmul(vadd(n.c, n.a), 0.5L);
        pq.push({n.a, ab, ca, bound(n.a, ab, ca)});
        pq.push({ab, n.b, bc, bound(ab, n.b, bc)});
        pq.push({ca, bc, n.c, bound(ca, bc, n.c)});
        pq.push({ab, bc, ca, bound(ab, bc, ca)});
        nodes += 4;
    }
    out.nodes = nodes;
    out.lb = LB;
    out.ub = pq.empty() ? LB : std::max(LB, pq.top().ub);
    return out;
}

// ------------------------------------------------------------------------------------------------
// Checks
// ------------------------------------------------------------------------------------------------
struct Ctx {
    unsigned seed;
    std::string kind;
    int fails = 0;
    bool verbose = false;
    void fail(const std::string& check, const std::string& msg) {
        ++fails;
        std::string m = msg;
        for (char& c : m) if (c == '\n') c = ' ';
        std::printf("FAIL seed=%u kind=%s check=%s | %s\n", seed, kind.c_str(), check.c_str(), m.c_str());
        std::fflush(stdout);
    }
};

static std::vector<std::array<Vec3, 3>> inserted_corners(const TargetSolver& ts) {
    std::vector<std::array<Vec3, 3>> c;
    for (uint32_t s : ts.inserted_sources()) c.push_back(ts.source_corners(s));
    return c;
}

struct Stats { long targets = 0, no_domain = 0, label_samples = 0, label_ties = 0; };

static void check_targets(Ctx& C, const VoxelGrid& grid, int side, Stats& st) {
    const TriangleMesh& M = grid.mesh(side);
    size_t n = M.num_triangles();
    if (n == 0) return;
    std::vector<uint32_t> ts_list = {0, (uint32_t)(n / 2), (uint32_t)(n - 1)};
    std::sort(ts_list.begin(), ts_list.end());
    ts_list.erase(std::unique(ts_list.begin(), ts_list.end()), ts_list.end());
    const char* sname = side == 0 ? "A" : "B";
    for (uint32_t t : ts_list) {
        std::string where = fmt("side %s target %u", sname, t);
        // Check 1: the debugger path (paper's insertion, watched), at the end.
        try {
            TargetSolver ts(grid, side, t);
            long events = 0;
            ts.on_event([&](const Event&) { ++events; });
            while (ts.step()) {}
            ++st.targets;
            if (ts.insertions() > 0 && events == 0) C.fail("1_debugger_events", where + ": no event reported");
            const DomainMesh* dm = ts.domain_mesh();
            if (!dm) { ++st.no_domain; }
            else {
                std::string v = ts.validate(true);
                if (!v.empty()) C.fail("1_debugger_validate", where + fmt(" (%d insertions): ", ts.insertions()) + v);
                LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources());
                st.label_samples += L.samples; st.label_ties += L.ties;
                if (L.disagree) C.fail("1_debugger_labels", where + fmt(" (%d insertions, %ld of %ld samples disagree): ", ts.insertions(), L.disagree, L.samples) + L.first);
            }
        } catch (const std::exception& e) {
            C.fail("1_debugger_exception", where + ": " + e.what());
        }
        // Check 2: the distance path (nearest first), validated after every insertion.
        try {
            TargetSolver ts(grid, side, t);
            ts.validate_each_insertion(true);
            ts.nearest_first();
            bool failed = false;
            try {
                while (ts.step()) {
                    const DomainMesh* dm = ts.domain_mesh();
                    if (!dm) continue;
                    LabelCheckOptions opt;
                    opt.resolution = 48;
                    LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources(), opt);
                    if (L.disagree) {
                        C.fail("2_nearest_labels_step", where + fmt(" after %d insertions (%ld of %ld samples disagree): ", ts.insertions(), L.disagree, L.samples) + L.first);
                        failed = true;
                        break;
                    }
                }
            } catch (const std::logic_error& e) {
                C.fail("2_nearest_validate_step", where + ": " + e.what());
                failed = true;
            }
            if (!failed) {
                const DomainMesh* dm = ts.domain_mesh();
                if (dm) {
                    LabelCheck L = check_labels(*dm, ts.frame(), inserted_corners(ts), ts.inserted_sources());
                    if (L.disagree) C.fail("2_nearest_labels_end", where + fmt(" (%d insertions, %ld of %ld samples disagree): ", ts.insertions(), L.disagree, L.samples) + L.first);
                }
            }
        } catch (const std::exception& e) {
            C.fail("2_nearest_exception", where + ": " + e.what());
        }
    }
}

static double max_coord(const Pair& P) {
    double c = 0;
    for (const TriangleMesh* m : {&P.A, &P.B})
        for (auto& t : m->triangles)
            for (uint32_t i : t) {
                const Vec3& q = m->positions[i];
                c = std::max({c, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
            }
    return c;
}

// Check 0 (--every-target): checks 1 and 2 open the first, middle and last targets; this runs
// every target of both sides to the end in the three orders, with the domain mesh's half-edges
// checked after every insertion, and that no domain is left without a source. A construction
// that never ends shows as the child's timeout (generate_pairs4.py "f32_export" 15711: target 21
// of 48, none of the three, looped for ever; 19111: target 31 left a sliver to no source).
// --thorough adds TargetSolver::validate(true) after every insertion of every target (domain
// polynomials against brute force, d^2 continuous across edges): the transient states that checks
// 1 and 2 see on three targets only (generate_pairs4.py "quantized" 19453: target 10 of 48).
// After its first failure a target runs to the end, which is checked once more
// ("0_every_target_end"): a failure that lasts to the end, not one after an insertion only.
static bool g_every_target = false, g_thorough = false;
static double g_max_width = 0;  // --max-width REL: check 6 on every pair, both modes' intervals at most REL of the diagonal
static void check_every_target(Ctx& C, const VoxelGrid& grid) {
    for (int side = 0; side < 2; ++side)
        for (uint32_t t = 0; t < grid.mesh(side).num_triangles(); ++t)
            for (int order = 0; order < 3; ++order) {
                const std::string where = fmt("side %s target %u order %d", side ? "B" : "A", t, order);
                try {
                    TargetSolver ts(grid, side, t);
                    if (order == 1) ts.nearest_first();
                    if (order == 2) ts.on_event([](const Event&) {});
                    while (ts.step()) {
                        const DomainMesh* m = ts.domain_mesh();
                        const std::string v = m ? m->validate(1e9) : "";
                        if (v.rfind("half-edge", 0) == 0) {
                            C.fail("0_every_target_topology", where + fmt(" (%d insertions): ", ts.insertions()) + v);
                            break;
                        }
                        // A source's regions tile the plane: after an insertion every domain has a source.
                        bool uncovered = false;
                        for (size_t f = 1; m && f < m->faces().size(); ++f)
                            uncovered = uncovered || (m->faces()[f].alive && m->faces()[f].infinite);
                        if (uncovered) {
                            C.fail("0_every_target_uncovered", where + fmt(" (%d insertions): a domain of no source", ts.insertions()));
                            break;
                        }
                        const std::string full = g_thorough ? ts.validate(true) : "";
                        if (!full.empty()) {
                            C.fail("0_every_target_validate", where + fmt(" (%d insertions): ", ts.insertions()) + full);
                            // Whether the end is right too: a failure after an insertion may last
                            // (generate_pairs5.py "coinc_noise_far" 58438 and "coinc_retess_far"
                            // 15407, the debugger's order, were taken for transient until this).
                            while (ts.step()) {}
                            const std::string end = ts.validate(true);
                            if (!end.empty())
                                C.fail("0_every_target_end", where + fmt(" (the end, %d insertions): ", ts.insertions()) + end);
                            break;
                        }
                    }
                } catch (const std::exception& e) {
                    C.fail("0_every_target_exception", where + ": " + e.what());
                }
            }
}

static void run_pair(unsigned seed, const Pair& P, bool verbose, long budget) {
    auto t0 = std::chrono::steady_clock::now();
    Ctx C{seed, P.kind, 0, verbose};
    Box3 box = P.A.bounds(); box.add(P.B.bounds());
    const double diag = box.diagonal();
    const double mc = max_coord(P);
    const double slack = 1e-15 * std::max(mc, diag);
    if (verbose) std::printf("NOTE seed=%u kind=%s nA=%zu nB=%zu diag=%.3g maxcoord=%.3g %s\n", seed, P.kind.c_str(),
                             P.A.num_triangles(), P.B.num_triangles(), diag, mc, P.note.c_str());
    if (std::getenv("DUMP")) { save_obj(P.A, std::string(std::getenv("DUMP")) + "_a.obj"); save_obj(P.B, std::string(std::getenv("DUMP")) + "_b.obj"); }
    Stats st;
    // Checks 1 and 2
    try {
        VoxelGrid grid(P.A, P.B, 1.0, 1);
        check_targets(C, grid, 0, st);
        check_targets(C, grid, 1, st);
        if (g_every_target) check_every_target(C, grid);
    } catch (const std::exception& e) {
        C.fail("grid_exception", e.what());
    }
    // Check 3: paper vs fast
    HausdorffResult rp, rf;
    bool have = false;
    try {
        HausdorffOptions paper, fast;
        paper.mode = Mode::Paper; paper.threads = 1;
        fast.mode = Mode::Fast; fast.threads = 1;
        rp = hausdorff(P.A, P.B, paper);
        rf = hausdorff(P.A, P.B, fast);
        have = true;
    } catch (const std::exception& e) {
        C.fail("hausdorff_exception", e.what());
    }
    if (have) {
        for (int dir = 0; dir < 2; ++dir) {
            const OneSidedResult& p = dir ? rp.b_to_a : rp.a_to_b;
            const OneSidedResult& f = dir ? rf.b_to_a : rf.a_to_b;
            const char* dn = dir ? "B->A" : "A->B";
            if (p.distance != f.distance || p.lower != f.lower || p.upper != f.upper)
                C.fail("3_paper_vs_fast", fmt("%s paper d=%.17g [%.17g, %.17g] fast d=%.17g [%.17g, %.17g]", dn, p.distance,
                                              p.lower, p.upper, f.distance, f.lower, f.upper));
            if (!(p.lower <= p.distance && p.distance <= p.upper))
                C.fail("5b_interval_order", fmt("%s paper lower %.17g distance %.17g upper %.17g", dn, p.lower, p.distance, p.upper));
            if (!(f.lower <= f.distance && f.distance <= f.upper))
                C.fail("5b_interval_order", fmt("%s fast lower %.17g distance %.17g upper %.17g", dn, f.lower, f.distance, f.upper));
            // Checks 4 and 5 against own brute force (on both modes' results)
            const TriangleMesh& from = dir ? P.B : P.A;
            const TriangleMesh& to = dir ? P.A : P.B;
            Brute b = brute(from, to, diag, budget);
            for (int mode = 0; mode < 2; ++mode) {
                const OneSidedResult& r = mode ? f : p;
                const char* mn = mode ? "fast" : "paper";
                if ((LD)r.upper < b.vertex - slack)
                    C.fail("4a_upper_ge_vertex", fmt("%s %s upper %.17g < farthest vertex %.17Lg (by %.3Lg, slack %.3g, diag %.3g, maxcoord %.3g)", dn, mn,
                                                     r.upper, b.vertex, b.vertex - r.upper, slack, diag, mc));
                if ((LD)r.distance < b.vertex - slack)
                    C.fail("4b_distance_ge_vertex", fmt("%s %s distance %.17g < farthest vertex %.17Lg (by %.3Lg, slack %.3g)", dn, mn, r.distance,
                                                        b.vertex, b.vertex - r.distance, slack));
                if ((LD)r.upper < b.sampled - slack)
                    C.fail("4c_upper_ge_sampled", fmt("%s %s upper %.17g < sampled %.17Lg (by %.3Lg, slack %.3g, diag %.3g)", dn, mn, r.upper,
                                                      b.sampled, b.sampled - r.upper, slack, diag));
                if ((LD)r.upper < b.lb - slack)
                    C.fail("5_upper_ge_ownLB", fmt("%s %s upper %.17g < own lower bound %.17Lg (by %.3Lg, slack %.3g, diag %.3g)", dn, mn, r.upper,
                                                   b.lb, b.lb - r.upper, slack, diag));
                if ((LD)r.lower > b.ub + slack)
                    C.fail("5_lower_le_ownUB", fmt("%s %s lower %.17g > own upper bound %.17Lg (by %.3Lg, slack %.3g, diag %.3g, own LB %.17Lg, nodes %ld%s)",
                                                   dn, mn, r.lower, b.ub, r.lower - b.ub, slack, diag, b.lb, b.nodes, b.budget_hit ? " budget hit" : ""));
            }
            if (verbose)
                std::printf("INFO seed=%u %s d=%.17g [%.17g, %.17g] width/diag=%.3g own [%.17Lg, %.17Lg]%s vertex=%.17Lg nodes=%ld\n", seed, dn, p.distance,
                            p.lower, p.upper, diag > 0 ? (p.upper - p.lower) / diag : 0.0, b.lb, b.ub, b.budget_hit ? " (budget)" : "",
                            b.vertex, b.nodes);
            // Width information (all pairs) and check 6 (near-coincident far from the origin)
            double w = p.upper - p.lower;
            std::printf("WIDTH seed=%u kind=%s dir=%s width=%.3g diag=%.3g rel=%.3g maxcoord=%.3g ulps=%.3g d=%.3g"
                        " up_minus_ownLB=%.3Lg ownUB_minus_low=%.3Lg own_gap=%.3Lg budget=%d slack=%.3g\n", seed, P.kind.c_str(), dn, w, diag,
                        diag > 0 ? w / diag : 0.0, mc, mc > 0 ? w / (mc * 2.220446049250313e-16) : 0.0, p.distance,
                        (LD)p.upper - b.lb, b.ub - (LD)p.lower, b.ub - b.lb, (int)b.budget_hit, slack);
            const double max_width = g_max_width > 0 ? g_max_width : P.near_coincident_far ? 1e-9 : HUGE_VAL;
            if (w > max_width * diag)
                C.fail("6_width", fmt("%s width %.3g > %.3g*diag = %.3g (lower %.17g upper %.17g distance %.17g; diag %.3g, maxcoord %.3g, width = %.3g ulps of maxcoord)", dn, w,
                                      max_width, max_width * diag, p.lower, p.upper, p.distance, diag, mc, w / (mc * 2.220446049250313e-16)));
            if (g_max_width > 0 && f.upper - f.lower > max_width * diag)  // fast mode's too, where asked
                C.fail("6_width", fmt("%s fast width %.3g > %.3g*diag = %.3g (lower %.17g upper %.17g distance %.17g)", dn, f.upper - f.lower, max_width,
                                      max_width * diag, f.lower, f.upper, f.distance));
        }
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("SEED %u %s nA=%zu nB=%zu targets=%ld nodomain=%ld %s time=%.3f | %s\n", seed, P.kind.c_str(), P.A.num_triangles(), P.B.num_triangles(),
                st.targets, st.no_domain, C.fails ? "fail" : "ok", secs, P.note.c_str());
    std::fflush(stdout);
}

// A pair written by another generator: DIR/NAME_a.obj and DIR/NAME_b.obj; NAME ending in "_far"
// marks a near-coincident pair far from the origin (check 6).
static Pair load_pair(const std::string& dir, const std::string& name) {
    Pair P;
    P.kind = name;
    P.note = dir + "/" + name;
    P.A = load_mesh(dir + "/" + name + "_a.obj");
    P.B = load_mesh(dir + "/" + name + "_b.obj");
    P.near_coincident_far = name.size() >= 4 && name.compare(name.size() - 4, 4, "_far") == 0;
    return P;
}

static std::vector<std::string> pair_names(const std::string& dir) {
    std::vector<std::string> names;
    DIR* d = opendir(dir.c_str());
    if (!d) throw std::runtime_error(dir + ": cannot open the directory");
    while (dirent* e = readdir(d)) {
        const std::string f = e->d_name;
        if (f.size() > 6 && f.compare(f.size() - 6, 6, "_a.obj") == 0) names.push_back(f.substr(0, f.size() - 6));
    }
    closedir(d);
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
        return std::atol(a.c_str()) != std::atol(b.c_str()) ? std::atol(a.c_str()) < std::atol(b.c_str()) : a < b;
    });
    return names;
}

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s SEED_FROM SEED_TO [KIND] [--no-fork] [--verbose] [--budget N] [--timeout S] [--every-target] [--thorough] [--max-width REL]\n"
                             "       %s --pairs DIR [same options]  (DIR/NAME_a.obj, DIR/NAME_b.obj)\n kinds:", argv[0], argv[0]);
        for (int i = 0; i < NKINDS; ++i) std::fprintf(stderr, " %s", kKinds[i]);
        std::fprintf(stderr, "\n");
        return 2;
    }
    const bool files = std::string(argv[1]) == "--pairs";
    const std::string dir = files ? argv[2] : "";
    const std::vector<std::string> names = files ? pair_names(dir) : std::vector<std::string>();
    unsigned from = files ? 0 : (unsigned)std::strtoul(argv[1], nullptr, 10);
    unsigned to = files ? (unsigned)names.size() : (unsigned)std::strtoul(argv[2], nullptr, 10);
    std::string filter;
    bool fork_each = true, verbose = false;
    long budget = 4000;
    int timeout = 300;
    for (int i = 3; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--no-fork") fork_each = false;
        else if (a == "--verbose") verbose = true;
        else if (a == "--budget" && i + 1 < argc) budget = std::atol(argv[++i]);
        else if (a == "--timeout" && i + 1 < argc) timeout = std::atoi(argv[++i]);
        else if (a == "--every-target") g_every_target = true;
        else if (a == "--thorough") g_every_target = g_thorough = true;
        else if (a == "--max-width" && i + 1 < argc) g_max_width = std::atof(argv[++i]);
        else filter = a;
    }
    for (unsigned seed = from; seed < to; ++seed) {
        std::string kind = files ? names[seed] : kKinds[seed % NKINDS];
        if (!filter.empty() && filter != "all" && kind != filter) continue;
        auto run = [&] {
            try {
                run_pair(seed, files ? load_pair(dir, names[seed]) : generate(seed), verbose, budget);
            } catch (const std::exception& e) {  // a pair that does not load
                std::printf("FAIL seed=%u kind=%s check=load | %s\n", seed, kind.c_str(), e.what());
            }
        };
        if (!fork_each) { run(); continue; }
        std::fflush(stdout);
        pid_t pid = fork();
        if (pid == 0) {
            alarm(timeout);
            run();
            std::fflush(stdout);
            _exit(0);
        }
        int status = 0;
        waitpid(pid, &status, 0);
        if (WIFSIGNALED(status)) {
            int sig = WTERMSIG(status);
            std::printf("FAIL seed=%u kind=%s check=crash | child died with signal %d (%s)%s\n", seed, kind.c_str(), sig, strsignal(sig),
                        sig == SIGALRM ? " [timeout]" : "");
            std::printf("SEED %u %s crash\n", seed, kind.c_str());
            std::fflush(stdout);
        } else if (WEXITSTATUS(status) != 0) {
            std::printf("FAIL seed=%u kind=%s check=crash | child exit status %d\n", seed, kind.c_str(), WEXITSTATUS(status));
            std::fflush(stdout);
        }
    }
    return 0;
}
