#include "regions.h"

#include <cmath>

#include "point_triangle.h"

namespace hlens {

namespace {

// Cross product in extended precision: the normal of a sliver is the difference of two nearly
// equal products, and its direction decides the face region and the face polynomial.
Vec3 precise_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    long double ux = (long double)b.x - a.x, uy = (long double)b.y - a.y, uz = (long double)b.z - a.z;
    long double vx = (long double)c.x - a.x, vy = (long double)c.y - a.y, vz = (long double)c.z - a.z;
    long double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    long double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (len == 0) return {0, 0, 0};
    return {(double)(nx / len), (double)(ny / len), (double)(nz / len)};
}

bool lex_less(const Vec3& p, const Vec3& q) {
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
}

}  // namespace

TargetFrame TargetFrame::make(const std::array<Vec3, 3>& c) {
    TargetFrame f;
    int i = 0;  // the longest edge runs from corner i to corner i+1
    double best = -1;
    for (int k = 0; k < 3; ++k) {
        double l = norm2(c[(k + 1) % 3] - c[k]);
        if (l > best) { best = l; i = k; }
    }
    int j = (i + 1) % 3, k = (i + 2) % 3;
    f.origin = c[i];
    f.scale = std::sqrt(best);
    if (f.scale == 0) {  // all three corners coincide
        f.scale = 1;
        f.degenerate = true;
        f.e1 = {1, 0, 0}; f.e2 = {0, 1, 0}; f.normal = {0, 0, 1};
        f.corners = {Vec2{0, 0}, Vec2{0, 0}, Vec2{0, 0}};
        f.ccw_order = {0, 1, 2};
        return f;
    }
    f.e1 = (c[j] - c[i]) / f.scale;
    f.normal = precise_normal(c[i], c[j], c[k]);
    if (norm2(f.normal) == 0) {
        // Collinear: any e2 perpendicular to e1 serves; the target is a segment.
        Vec3 t = std::fabs(f.e1.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        f.normal = cross(f.e1, t);
        f.normal = f.normal / norm(f.normal);
    }
    f.e2 = cross(f.normal, f.e1);
    f.e2 = f.e2 / norm(f.e2);
    f.corners[i] = {0, 0};
    f.corners[j] = {1, 0};
    f.corners[k] = f.to_frame(c[k]);
    f.ccw_order = {i, j, k};
    // Height of the third corner over the longest edge, relative to it: below 1e-7 the domain
    // mesh's own tolerances are no longer small against the target, so it is handled as edges.
    f.degenerate = !(f.corners[k].y > 1e-7);
    return f;
}

const char* region_name(Region r) {
    static const char* names[] = {"R_abc", "R_ab", "R_bc", "R_ca", "R_a", "R_b", "R_c"};
    return names[(int)r];
}

namespace {

struct Projector {
    const TargetFrame& F;
    // The rounding of the source's frame coordinates (SourceProjection::delta): with the tilt of a
    // boundary plane taken as parallel to T', how far T' may lie outside it and still count as
    // inside (halfspace).
    double delta;
    // A 3D point into frame-scaled coordinates relative to the origin.
    Vec3 rel(const Vec3& p) const { return (p - F.origin) / F.scale; }

    Quadratic2 vertex(const Vec3& a) const {
        Vec3 r = rel(a);
        Quadratic2 q;
        q.a = 1; q.c = 1;
        q.d = -dot(F.e1, r); q.e = -dot(F.e2, r);
        q.f = norm2(r);
        return q;
    }
    // Squared distance to the line through p0 and p1.
    Quadratic2 edge(Vec3 p0, Vec3 p1) const {
        if (lex_less(p1, p0)) std::swap(p0, p1);  // shared edges give bit-identical polynomials
        Vec3 u = p1 - p0;
        u = u / norm(u);
        Vec3 r = rel(p0);
        // M r, with M = I - u u^T; again where r is long: r may be 1e7 frame units (a target 1e-7
        // of the source's size), and one pass leaves M r off orthogonal to u by 1e-16 of |r|. Then
        // d^2 has a linear term along the edge and does not vanish on it: 6.9e-10 where a coplanar
        // face's region meets the edge's ("mixed_scale" pairs of a third generator, a target 2e-10
        // long on the edge of a source 7e-3 long; a jump across the region line that validate()
        // reports). Where |r| < 1e3 that term is below the quadratics' rounding: one pass.
        Vec3 perp_r = r - dot(u, r) * u;
        if (norm2(r) > 1e6) perp_r = perp_r - dot(u, perp_r) * u;
        double u1 = dot(F.e1, u), u2 = dot(F.e2, u);
        Quadratic2 q;
        q.a = 1 - u1 * u1; q.b = -u1 * u2; q.c = 1 - u2 * u2;
        q.d = -dot(F.e1, perp_r); q.e = -dot(F.e2, perp_r);
        q.f = norm2(perp_r);
        return q;
    }
    // Squared distance to the plane through the point r (frame-scaled, relative to the origin)
    // with normal n.
    Quadratic2 plane(const Vec3& r, const Vec3& n) const {
        double h = dot(n, r);
        double n1 = dot(F.e1, n), n2 = dot(F.e2, n);
        Quadratic2 q;
        q.a = n1 * n1; q.b = n1 * n2; q.c = n2 * n2;
        q.d = -h * n1; q.e = -h * n2;
        q.f = h * h;
        return q;
    }
    // {p : (p - a).m >= 0} within the frame's plane.
    HalfPlane halfspace(const Vec3& a, Vec3 m) const {
        m = m / norm(m);
        HalfPlane h;
        Vec2 n{dot(F.e1, m), dot(F.e2, m)};
        double off = dot(rel(a), m);
        double ln = norm(n);
        if (ln <= 1e-12) {
            // Boundary plane parallel to the target: all or nothing, by the side the plane is on.
            // T' counts as inside it up to 1e-12 of T''s size, but no farther than the plane, at
            // its tilt, may still reach T' (T' lies within 1 of the frame's origin) or the corners'
            // rounding may put it: a box 1.2e-12 thin whose side walls stand under a target 2.4e-12
            // up, the top edge of one 0.8e-12 below T' and parallel to it, had that edge's plane
            // taken as holding T', and the wall's face region, empty on T', a strip of it
            // (generate_pairs10.py "thin_box" 2884, side A, target 42, the paper's order: a step of
            // 0.089 in d^2). A plane 4e-13 from parallel that crosses T' 0.2 from a corner stays
            // inside as before ("zero_area_in_closed_far" 2321, bound_sliver_face_region).
            h.kind = off <= std::min(1e-12, ln + delta) ? HalfPlane::All : HalfPlane::None;
            return h;
        }
        h.n = n / ln;
        h.offset = off / ln;
        return h;
    }
};

// A region's corner X where its lines i and j meet at less than kBevelAngle: the tip of a sliver's
// face region, or a corner region of an angle near pi. Cut by those two lines alone, the tip runs
// on past X as far as the lines stay within the domain mesh's tolerances of each other, which is
// those over the angle: generate_pairs5.py "seam_strip" 211 (side B, target 17, the paper's
// order): a sliver source's face region, a wedge of 6e-6 rad, kept its plane's quadratic 1.5e-4 of
// T' past its tip, inside both lines to 9e-9, where the corner's quadratic is 2.3e-8 higher
// (d^2 3.2e-7). Its bevel, the line through X across the wedge's bisector, leaves the region as it
// is (the wedge lies on its inner side) and ends the tip at X, whatever the tolerances.
// Where the lines meet at less than 1e-13 rad, their normals' sum is too much rounding to give
// the bisector: `into`, a direction into the wedge from the source's corners, if the caller has
// one. Without it a face region's tip 3.4e-15 rad wide had no bevel, and the crack rule, whose
// margins over the region's lines alone reach that far, gave it the opposite wedge beyond the
// tip: d^2 0 where it is 1 (generate_pairs12.py "flat_kite_diagonals" 1338, side B, target 6).
constexpr double kBevelAngle = 0.1;
void bevel(SourceRegion& r, size_t i, size_t j, Vec2 X, Vec2 into = {0, 0}) {
    const HalfPlane &p = r.planes[i], &q = r.planes[j];
    if (p.kind != HalfPlane::Line || q.kind != HalfPlane::Line) return;
    Vec2 s = p.n + q.n;  // along the wedge's bisector, into it; 2 sin(angle / 2) long
    double ls = norm(s);
    if (!(ls < 2 * std::sin(0.5 * kBevelAngle))) return;
    if (!(ls > 1e-13)) s = into, ls = norm(into);
    if (!(ls > 0)) return;
    HalfPlane h;
    h.n = s / ls;
    h.offset = dot(h.n, X);
    h.bevel = true;
    r.planes.push_back(h);
}

// Two sides of the face region taken as parallel to T' (halfspace: All or None) leave it unbounded
// along them: the source is a sliver seen edge-on, its sides' planes within 1e-12 of T''s though
// one may still cross T' within reach. Every point of a triangle projects onto its longest edge
// within the edge (the angles at its ends are acute), so the face region lies between the planes
// across that edge's ends: added, they end the region where the vertex regions begin. (Generate_
// pairs7.py "zero_area_in_closed_far" 2321: a source 80 long and 3e-11 wide, perpendicular to T'
// and straddling its plane; one long side's plane crosses T' 0.2 of T' from a corner, 4e-13 from
// parallel to it, and the region ran on past the source's end, where the fast insertion, which
// skips a vertex region that cannot be nearer, gave the plane's quadratic a domain of 0.02 of T'
// nearest to that vertex: d^2 0.0017 where the truth is 0.0662.)
void bound_sliver_face_region(const Projector& P, const std::array<Vec3, 3>& s, SourceRegion& face) {
    int lost = 0;
    for (const HalfPlane& h : face.planes) lost += h.kind != HalfPlane::Line;
    if (lost < 2) return;
    int i = 0;
    for (int k = 1; k < 3; ++k)
        if (norm2(s[(k + 1) % 3] - s[k]) > norm2(s[(i + 1) % 3] - s[i])) i = k;
    const Vec3 &p = s[i], &q = s[(i + 1) % 3];
    face.planes.push_back(P.halfspace(p, q - p));
    face.planes.push_back(P.halfspace(q, p - q));
}

}  // namespace

SourceProjection project_source(const TargetFrame& F, const std::array<Vec3, 3>& s, uint32_t index) {
    SourceProjection out;
    project_source(F, s, index, out);
    return out;
}

void project_source(const TargetFrame& F, const std::array<Vec3, 3>& s, uint32_t index, SourceProjection& out) {
    // Region k is written over out.regions[k], reusing its storage (the solver projects one source
    // per insertion into the same object: no allocation once it has held seven regions).
    size_t count = 0;
    auto add = [&](Region kind, std::initializer_list<HalfPlane> planes, const Quadratic2& poly) {
        if (out.regions.size() <= count) out.regions.emplace_back();
        SourceRegion& r = out.regions[count++];
        r.kind = kind;
        r.planes.assign(planes);
        r.poly = poly;
    };
    out.source = index;
    out.degenerate = false;
    double reach = 0;
    for (const Vec3& c : s) reach = std::max(reach, norm(c - F.origin) / F.scale);
    out.delta = 64 * 0x1p-52 * (1 + reach);
    Projector P{F, out.delta};
    const Vec3 &a = s[0], &b = s[1], &c = s[2];
    double longest2 = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
    Vec3 n = precise_normal(a, b, c);
    long double area2 = norm2(cross(b - a, c - a));
    bool degenerate = norm2(n) == 0 || area2 <= 1e-28L * longest2 * longest2;
    if (degenerate) {
        out.degenerate = true;
        // The farthest pair of corners spans the segment; a point if they coincide.
        int i = 0;
        double best = -1;
        for (int k = 0; k < 3; ++k) {
            double l = norm2(s[(k + 1) % 3] - s[k]);
            if (l > best) { best = l; i = k; }
        }
        int j = (i + 1) % 3;
        static const Region vreg[3] = {Region::a, Region::b, Region::c};
        static const Region ereg[3] = {Region::ab, Region::bc, Region::ca};
        if (best == 0) {
            add(Region::a, {}, P.vertex(a));
            out.regions.resize(count);
            return;
        }
        const Vec3 &p = s[i], &q = s[j];
        add(vreg[i], {P.halfspace(p, p - q)}, P.vertex(p));
        add(vreg[j], {P.halfspace(q, q - p)}, P.vertex(q));
        add(ereg[i], {P.halfspace(p, q - p), P.halfspace(q, p - q)}, P.edge(p, q));
        out.regions.resize(count);
        return;
    }
    // Outward in-plane normals of the edges.
    auto outward = [&](const Vec3& p, const Vec3& q, const Vec3& opp) {
        Vec3 m = cross(q - p, n);
        if (dot(opp - p, m) > 0) m = -m;
        return m;
    };
    Vec3 mab = outward(a, b, c), mbc = outward(b, c, a), mca = outward(c, a, b);
    add(Region::a, {P.halfspace(a, a - b), P.halfspace(a, a - c)}, P.vertex(a));
    add(Region::b, {P.halfspace(b, b - a), P.halfspace(b, b - c)}, P.vertex(b));
    add(Region::c, {P.halfspace(c, c - a), P.halfspace(c, c - b)}, P.vertex(c));
    // A plane along an edge (across the source's plane) taken through the edge's other end where
    // its own is more than 1024 times as far from T''s origin: the line it leaves on T' is off by
    // the rounding of that end's frame coordinates over the plane's tilt from T'. A sliver fan's
    // apex at a target 1e-9 across, its far ends 5e10 frame units away, a side plane within 7e-6 of
    // T''s: through the far end the face region's line was 0.3 of T' off (generate_pairs9.py
    // "sliver_fan_tiny" 2287: a face region holding points whose foot is outside the source).
    const double ra = norm(P.rel(a)), rb = norm(P.rel(b)), rc = norm(P.rel(c));
    auto along = [](const Vec3& own, double r_own, const Vec3& other, double r_other) -> const Vec3& {
        return r_own > 1024 * std::max(1.0, r_other) ? other : own;
    };
    const Vec3 &pab = along(a, ra, b, rb), &pbc = along(b, rb, c, rc), &pca = along(c, rc, a, ra);
    add(Region::ab, {P.halfspace(pab, mab), P.halfspace(a, b - a), P.halfspace(b, a - b)}, P.edge(a, b));
    add(Region::bc, {P.halfspace(pbc, mbc), P.halfspace(b, c - b), P.halfspace(c, b - c)}, P.edge(b, c));
    add(Region::ca, {P.halfspace(pca, mca), P.halfspace(c, a - c), P.halfspace(a, c - a)}, P.edge(c, a));
    // The plane's height over T' is off by the normal's rounding times the distance of the point
    // it is taken through. Through a corner that rounding grows as the source thins, to 1e-7 on a
    // sliver 1e-12 thin (the cross product's rounding over its area, even in long double), and a
    // corner 1e12 frame units away (a target 1e-12 of the source's size) put the plane 1e5 off
    // (generate_pairs8.py "mixed_scale_sim" 702: d^2 2696 where it is 2.5e-5). Through the source's
    // point nearest T''s origin that distance is the target's, but the point is off the plane by
    // its own rounding, an ulp of the corners' distances: worth it only on a source thinner than
    // 1 in 2048, where the normal's rounding outgrows that (an ordinary face keeps its corner).
    Vec3 through = P.rel(a);
    if (longest2 > 2048.0 * std::sqrt((double)area2))
        through = closest_point_on_triangle(Vec3{0, 0, 0}, a - F.origin, b - F.origin, c - F.origin).point / F.scale;
    add(Region::abc, {P.halfspace(pab, -mab), P.halfspace(pbc, -mbc), P.halfspace(pca, -mca)}, P.plane(through, n));
    out.regions.resize(count);
    bound_sliver_face_region(P, s, out.regions.back());
    // Every region's corners are the corners of the source carried along its normal n onto T''s
    // plane (each line through a corner contains that normal): taken so, in 3D, not where two
    // nearly parallel lines cross. A source seen nearly edge-on from T' has them far off: none.
    const double nN = dot(n, F.normal);
    if (!(std::fabs(nN) > 1e-6)) return;
    auto corner = [&](const Vec3& v) {
        Vec3 r = P.rel(v);
        r = r - n * (dot(r, F.normal) / nN);
        return Vec2{dot(F.e1, r), dot(F.e2, r)};
    };
    const Vec2 A = corner(a), B = corner(b), C = corner(c);
    std::vector<SourceRegion>& R = out.regions;  // a, b, c, ab, bc, ca, abc
    bevel(R[0], 0, 1, A), bevel(R[1], 0, 1, B), bevel(R[2], 0, 1, C);
    bevel(R[3], 0, 1, A), bevel(R[3], 0, 2, B);
    bevel(R[4], 0, 1, B), bevel(R[4], 0, 2, C);
    bevel(R[5], 0, 1, C), bevel(R[5], 0, 2, A);
    // The face region is the triangle A B C: at a tip, into it along its two sides.
    auto unit = [](Vec2 v) { const double l = norm(v); return l > 0 ? v / l : Vec2{0, 0}; };
    bevel(R[6], 0, 2, A, unit(B - A) + unit(C - A)), bevel(R[6], 0, 1, B, unit(A - B) + unit(C - B));
    bevel(R[6], 1, 2, C, unit(A - C) + unit(B - C));
}

double source_distance2(const TargetFrame& F, const std::array<Vec3, 3>& s, Vec2 p) {
    // Relative to the frame's origin, so that the rounding is that of the distances between the
    // target and the source, not of their coordinates' magnitude (meshes far from the origin).
    const Vec3 w = (p.x * F.scale) * F.e1 + (p.y * F.scale) * F.e2;
    return closest_point_on_triangle(w, s[0] - F.origin, s[1] - F.origin, s[2] - F.origin).dist2 / (F.scale * F.scale);
}

std::vector<Vec2> clip_convex(std::vector<Vec2> poly, const std::vector<HalfPlane>& planes) {
    std::vector<Vec2> tmp;
    clip_convex_in_place(poly, planes, tmp);
    return poly;
}

void clip_convex_in_place(std::vector<Vec2>& poly, const std::vector<HalfPlane>& planes, std::vector<Vec2>& tmp) {
    for (const HalfPlane& h : planes) {
        if (h.kind == HalfPlane::All) continue;
        if (h.kind == HalfPlane::None) { poly.clear(); return; }
        std::vector<Vec2>& out = tmp;
        out.clear();
        size_t n = poly.size();
        for (size_t i = 0; i < n; ++i) {
            Vec2 p = poly[i], q = poly[(i + 1) % n];
            double fp = dot(h.n, p) - h.offset, fq = dot(h.n, q) - h.offset;
            if (fp >= 0) out.push_back(p);
            if ((fp >= 0) != (fq >= 0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
        }
        poly.swap(out);
        if (poly.empty()) break;
    }
}

}  // namespace hlens
