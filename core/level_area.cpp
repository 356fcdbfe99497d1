// The area of a domain where d > t, without splitting the domain (issue 9, item 1: "the area where
// d > t for any t ... the same kind of integral"; Straub 2007 §5).
//
// Inside a domain F, d^2 is one convex quadratic P, so g = P - t^2 is negative on a convex set E
// (an ellipse's inside, a strip, a half-plane) and its zero set C is a conic (decompose_conic). By
// Green's theorem the area of F \ E is the integral of x dy along its boundary, loops oriented
// with the set on their left, and that boundary is made of
//  - the pieces of F's own arcs where g > 0: g composed with an arc is a polynomial of degree <= 4
//    (RationalCurve::compose), its sign changes (poly.h, no sampling) cut the arc, and g at each
//    piece's middle says whether it counts;
//  - the pieces of C inside F, with g > 0 on their left. C is cut where the classification of F's
//    boundary changes (walking each loop, also across vertices), so the ends of the pieces of
//    both kinds are the same points. At each such point C passes into or out of F, so its pieces
//    alternate, inside and outside: an open curve's first piece is inside, a closed curve's phase
//    is read at the middle of a piece clearly inside or outside (point_in_face). A piece of C
//    that runs along F's boundary, a rounding error off it, is so decided by its neighbours,
//    never by a test at its middle that cannot tell.
// Ellipses and lines are integrated in closed form, F's curved arcs and other conic pieces by
// integrals.cpp's certified quadrature (curve_x_dy). The gaps between where a piece of C starts and
// the crossing it stands for (rounding, or a vertex a snap moved off the curve) are closed by chords,
// as face_integral closes its arcs, so the loops close exactly and no origin leaks in.
//
// Where C runs along F's boundary (d constant along a target edge parallel to a source plane, and
// t exactly that distance), g there is rounding noise: such a piece of F's boundary counts as above
// when g > 0 just inside F. Where g has one sign over the whole plane but for a double line or a
// point (t the least d, T' crossing a source's plane) the face is all above; and where C is two
// parallel lines (d^2 of one variable), each side of the strip between them is taken alone as a
// half-plane, so that lines closer than the crossings' rounding need no telling apart.
//
// split_face (the construction's clipping, which the debugger's tolerance view still uses) gives
// the same areas; tests/test_integrals.cpp compares both on real, random and degenerate targets.
#include <algorithm>
#include <cmath>
#include <vector>

#include "integrals.h"
#include "poly.h"

namespace hlens {

namespace {

double seg_x_dy(Vec2 a, Vec2 b) { return 0.5 * (a.x + b.x) * (b.y - a.y); }

// Integral of x dy along component c from parameter t0 to t1 (either order).
double component_x_dy(const CurveComponent& c, double t0, double t1) {
    if (c.kind == CurveKind::Line) return seg_x_dy(c.at(t0), c.at(t1));
    if (c.kind == CurveKind::Ellipse) {
        // x = cx + ux cos t + vx sin t, y = cy + uy cos t + vy sin t: a closed form.
        auto F = [&](double t) {
            const double s = std::sin(t), co = std::cos(t);
            return c.c.x * (c.u.y * co + c.v.y * s) + (c.v.x * c.v.y - c.u.x * c.u.y) * 0.5 * s * s +
                   c.u.x * c.v.y * (0.5 * t + 0.5 * s * co) - c.v.x * c.u.y * (0.5 * t - 0.5 * s * co);
        };
        return F(t1) - F(t0);
    }
    const double lo = std::min(t0, t1), hi = std::max(t0, t1);
    double sum = 0;
    for (const CurveComponent::Piece& p : c.pieces(lo, hi)) sum += curve_x_dy(p.curve, p.z0, p.z1).value;
    return t1 >= t0 ? sum : -sum;
}

// A point where F's boundary changes from counted to not (or back): where C crosses it.
struct Crossing { Vec2 p; int comp = 0; double t = 0; };

}  // namespace

// What a face's arcs are for every level alike (area_above_levels clips one face at many): per
// half-edge of its loops, in their order, the arc in the shifted coordinates and P and w^2 composed
// with it, so that P - t^2 along it is p - t^2 w2 (compose is linear in the quadratic).
struct FaceArcs {
    std::vector<RationalCurve> curve;
    std::vector<Poly> p, w2;
};

namespace {

// The area of face f where g > 0, g in coordinates shifted by -o (so are all points below but
// those handed to the mesh's queries). Two parts: F's own arcs where g > 0 (boundary()), which
// also finds the crossings, then the pieces of C = {g = 0} between them inside F (conic()).
struct AreaAbove {
    const DomainMesh& m;
    int f;
    const Quadratic2& g;
    Vec2 o;
    double size, gtol;
    const FaceArcs* arcs;   // the face's arcs precomputed for g = P - t2, or null
    double t2;
    std::vector<Crossing> cross;

    // The loops' arcs, piece by piece; a change of "counted" along a loop is a crossing of C.
    double boundary() {
        double sum = 0;
        size_t walk = 0;  // the half-edge's index in the walk (arcs)
        for (int loop : m.faces()[f].loops) {
            int first = -1, state = -1;
            Vec2 first_point{0, 0};
            int h = loop;
            do {
                sum += half_edge(h, walk++, first, state, first_point);
                h = m.half_edges()[h].next;
            } while (h != loop);
            if (state >= 0 && state != first) cross.push_back({first_point});
        }
        if (cross.size() % 2) cross.pop_back();  // cannot happen on a closed loop; defensive
        return sum;
    }

    // Half-edge h's pieces between the sign changes of g along it, in its direction.
    double half_edge(int h, size_t walk, int& first, int& state, Vec2& first_point) {
        const int e = h >> 1;
        const bool fwd = !(h & 1);
        const DomainMesh::Edge& E = m.edges()[e];
        const RationalCurve c = arcs ? arcs->curve[walk] : shifted(E.curve, o);
        Poly along;
        if (arcs) {
            const Poly& w2 = arcs->w2[walk];
            along = arcs->p[walk];
            for (int i = 0; i <= w2.deg; ++i) along.c[i] -= t2 * w2.c[i];
            along.deg = std::max(along.deg, w2.deg);
        } else {
            along = c.compose(g);
        }
        const auto& V = m.vertices();
        const auto& H = m.half_edges();
        const Vec2 va = V[H[2 * e].origin].p - o, vb = V[H[2 * e + 1].origin].p - o;
        double z[kMaxSignChangeRoots + 2], roots[kMaxSignChangeRoots];
        int n = 0;
        z[n++] = E.z0;
        const int nr = sign_change_roots(along, std::min(E.z0, E.z1), std::max(E.z0, E.z1), roots);
        if (E.z0 <= E.z1) for (int k = 0; k < nr; ++k) z[n++] = roots[k];
        else for (int k = nr - 1; k >= 0; --k) z[n++] = roots[k];
        z[n++] = E.z1;
        auto point = [&](int k) { return k == 0 ? va : k == n - 1 ? vb : c(z[k]); };
        double sum = 0;
        for (int j = 0; j < n - 1; ++j) {
            const int k0 = fwd ? j : n - 1 - j, k1 = fwd ? j + 1 : n - 2 - j;  // from z[k0] to z[k1]
            const int now = counted(c, 0.5 * (z[k0] + z[k1]), fwd);
            const Vec2 from = point(k0);
            if (state < 0) first = now, first_point = from;
            else if (now != state) cross.push_back({from});
            state = now;
            if (!now) continue;
            if (c.straight()) { sum += seg_x_dy(from, point(k1)); continue; }
            const double lo = std::min(z[k0], z[k1]), hi = std::max(z[k0], z[k1]);
            double I = curve_x_dy(c, lo, hi).value;
            if (lo == std::min(E.z0, E.z1)) I += seg_x_dy(E.z0 <= E.z1 ? va : vb, c(lo));  // to the vertex
            if (hi == std::max(E.z0, E.z1)) I += seg_x_dy(c(hi), E.z0 <= E.z1 ? vb : va);
            sum += z[k1] < z[k0] ? -I : I;
        }
        return sum;
    }

    // Is the piece of arc c around parameter zm above t (g > 0)? Where g is noise there (C along
    // the arc), its sign just inside F, on the half-edge's left.
    int counted(const RationalCurve& c, double zm, bool fwd) const {
        const Vec2 pm = c(zm);
        double gv = g(pm);
        if (std::fabs(gv) <= gtol) {
            const Vec2 tan = c.derivative(zm) * (fwd ? 1.0 : -1.0);
            const double tn = norm(tan);
            gv = tn > 0 ? g(pm + (1e-6 * size / tn) * perp(tan)) : 0;
            if (std::fabs(gv) <= gtol) gv = 0;
        }
        return gv > 0;
    }

    // Inside F at the middle of the piece ta..tb of component k: 1 or 0, or -1 where that point is
    // along F's boundary (C running along an arc, a few ulps off it) and cannot tell.
    int inside(const CurveComponent& k, double ta, double tb) const {
        const Vec2 p = k.at(0.5 * (ta + tb)) + o;
        return m.near_boundary(f, p, 1e-9 * size) ? -1 : (int)m.point_in_face(f, p);
    }

    // x dy along component k from ta to tb (with the chords from and to the crossings xa, xb),
    // oriented with g > 0 on its left.
    double piece(const CurveComponent& k, double ta, double tb, const Vec2* xa, const Vec2* xb) const {
        const double tm = 0.5 * (ta + tb), eps = 1e-7 * std::max(1.0, std::fabs(tb - ta));
        const Vec2 tan = k.at(tm + eps) - k.at(tm - eps);
        const bool forward = dot(g.gradient(k.at(tm)), perp(tan)) > 0;
        double I = component_x_dy(k, ta, tb);
        if (xa) I += seg_x_dy(*xa, k.at(ta));
        if (xb) I += seg_x_dy(k.at(tb), *xb);
        return forward ? I : -I;
    }

    // The pieces of C inside F. Each crossing is where C passes into or out of F (the
    // classification of F's boundary changes sign there), so the pieces between them alternate,
    // inside and outside. An open curve comes from outside: its first piece is inside. A closed
    // one: the first piece whose middle is clearly inside or outside sets the phase. Where the
    // count is odd (a crossing put on the wrong component), each piece is judged by its middle.
    double conic(const ConicDecomposition& dec) {
        for (Crossing& x : cross) {  // each crossing on its nearest component
            double best = HUGE_VAL;
            for (size_t k = 0; k < dec.components.size(); ++k) {
                const double t = dec.components[k].param_of(x.p), d = norm(dec.components[k].at(t) - x.p);
                if (d < best) { best = d; x.comp = (int)k; x.t = t; }
            }
        }
        double sum = 0;
        std::vector<const Crossing*> on;
        for (size_t k = 0; k < dec.components.size(); ++k) {
            const CurveComponent& comp = dec.components[k];
            on.clear();
            for (const Crossing& x : cross)
                if (x.comp == (int)k) on.push_back(&x);
            std::sort(on.begin(), on.end(), [](const Crossing* a, const Crossing* b) { return a->t < b->t; });
            const size_t n = on.size();
            if (n == 0) {  // a closed curve that never meets F's boundary: wholly inside F or not at all
                if (comp.closed() && inside(comp, 0, 2 * M_PI) == 1) sum += piece(comp, 0, 2 * M_PI, nullptr, nullptr);
                continue;
            }
            // Piece i runs from crossing i to the next (around a closed curve, the last to the first).
            const size_t pieces = comp.closed() ? n : n - 1;
            auto ta = [&](size_t i) { return on[i]->t; };
            auto tb = [&](size_t i) { return i + 1 < n ? on[i + 1]->t : on[0]->t + 2 * M_PI; };
            int phase = -1;  // the parity of the inside pieces
            if (n % 2 == 0) {
                if (!comp.closed()) phase = 0;
                for (size_t i = 0; i < pieces && phase < 0; ++i) {
                    const int in = inside(comp, ta(i), tb(i));
                    if (in >= 0) phase = (int)((i + (in ? 0 : 1)) % 2);
                }
            }
            for (size_t i = 0; i < pieces; ++i) {
                const bool in = phase >= 0 ? (int)(i % 2) == phase : inside(comp, ta(i), tb(i)) == 1;
                if (in) sum += piece(comp, ta(i), tb(i), &on[i]->p, &on[(i + 1) % n]->p);
            }
        }
        return sum;
    }
};

// Area of face f where g > 0 (g in coordinates shifted by -o; its zero set decomposed in `dec`).
double area_where_positive(const DomainMesh& m, int f, const Quadratic2& g, const ConicDecomposition& dec, Vec2 o,
                           double size, double gtol, const FaceArcs* arcs = nullptr, double t2 = 0) {
    AreaAbove a{m, f, g, o, size, gtol, arcs, t2, {}};
    const double sum = a.boundary();
    return std::max(0.0, sum + a.conic(dec));
}

}  // namespace

// The arcs of face f for area_above, in the coordinates shifted by -o.
static void face_arcs(const DomainMesh& m, int f, Vec2 o, FaceArcs& out) {
    const Quadratic2 P = shifted(m.faces()[f].poly, o);
    Quadratic2 one;
    one.f = 1;
    for (int loop : m.faces()[f].loops) {
        int h = loop;
        do {
            out.curve.push_back(shifted(m.edges()[h >> 1].curve, o));
            out.p.push_back(out.curve.back().compose(P));
            out.w2.push_back(out.curve.back().compose(one));
            h = m.half_edges()[h].next;
        } while (h != loop);
    }
}

// face_area_above with the face's box and its range of d^2 there (convex_range) given, and its
// arcs if known (face_arcs, with o the box's centre).
static double area_above(const DomainMesh& m, int f, double t2, const Box2& box, const Interval& r,
                         const FaceArcs* arcs = nullptr) {
    const DomainMesh::Face& face = m.faces()[f];
    const Vec2 o = 0.5 * (box.lo + box.hi);  // shifted coordinates: smaller rounding
    const double size = norm(box.hi - box.lo);
    Quadratic2 g = shifted(face.poly, o);    // g(x + o) as a quadratic in x, minus t^2
    g.f -= t2;
    // How well g is known over the face: the rounding of its evaluation (a few ulps of its
    // terms' magnitude) and of d^2 itself, whose quadratic the construction derived from the
    // sources' coordinates (1e-12 of its values: parallel planes give a constant d^2 with a
    // gradient of rounding noise, which must not decide which part of F is above t).
    const double gtol = 1e-13 * g.scale() * (1 + size) * (1 + size) + 1e-12 * (std::fabs(r.hi) + t2);
    if (r.lo > t2) return face_area_exact(m, f).value;
    if (r.hi <= t2 + gtol) return 0;  // also d = t all over F, within rounding: nothing above
    const ConicDecomposition dec = decompose_conic(g);
    if (dec.components.empty()) {
        // g does not change sign: d = t on a line or a point at most (the least d over F, where
        // T' crosses a source's plane), or nowhere. The boundary's classification would only
        // see rounding noise around that zero set.
        if (dec.type == ConicType::DoubleLine || dec.type == ConicType::Point) return face_area_exact(m, f).value;
        return dec.type == ConicType::Empty && g({0, 0}) > 0 ? face_area_exact(m, f).value : 0;
    }
    if (dec.type == ConicType::ParallelLines && dec.components.size() == 2) {
        // d^2 of one variable (a source's plane, an edge parallel to T'): g < 0 on the strip between
        // the lines, which may be closer than the crossings' rounding (t near the least d over F).
        // Which line a crossing is on is then unclear, so each side of the strip is taken alone,
        // as the half-plane beyond its line: one line each, nothing to pair.
        const Vec2 n = perp(dec.components[0].u);
        const double s0 = dot(dec.components[0].c, n), s1 = dot(dec.components[1].c, n);
        const double hi = std::max(s0, s1), lo = std::min(s0, s1);
        if (g(0.5 * (hi + lo) * n) <= 0) {
            double sum = 0;
            for (int side : {1, -1}) {
                Quadratic2 h;  // side * (n.x - edge) > 0: beyond that line
                h.d = 0.5 * side * n.x;
                h.e = 0.5 * side * n.y;
                h.f = -side * (side > 0 ? hi : lo);
                sum += area_where_positive(m, f, h, decompose_conic(h), o, size, 1e-15 * (1 + size));
            }
            return sum;
        }
    }
    return area_where_positive(m, f, g, dec, o, size, gtol, arcs, t2);
}

double face_area_above(const DomainMesh& m, int f, double t2) {
    const Box2 box = m.face_box(f);
    return area_above(m, f, t2, box, convex_range(m.faces()[f].poly, box));
}

std::vector<double> area_above_levels(const DomainMesh& m, const std::vector<double>& levels) {
    // Each face's box, range and area once; a level inside a face's range costs one area_above.
    struct FaceRange { int f; Box2 box; Interval r; double area; FaceArcs arcs; };
    std::vector<FaceRange> faces;
    const auto& F = m.faces();
    for (size_t f = 1; f < F.size(); ++f)
        if (F[f].alive && !F[f].infinite) {
            const Box2 box = m.face_box((int)f);
            faces.push_back({(int)f, box, convex_range(F[f].poly, box), -1, {}});
        }
    std::vector<double> out(levels.size(), 0.0);
    for (size_t j = 0; j < levels.size(); ++j)
        for (FaceRange& fr : faces) {
            if (fr.r.hi <= levels[j]) continue;
            if (fr.r.lo > levels[j]) {
                if (fr.area < 0) fr.area = face_area_exact(m, fr.f).value;
                out[j] += fr.area;
            } else {
                if (fr.arcs.curve.empty()) face_arcs(m, fr.f, 0.5 * (fr.box.lo + fr.box.hi), fr.arcs);
                out[j] += area_above(m, fr.f, levels[j], fr.box, fr.r, &fr.arcs);
            }
        }
    return out;
}

}  // namespace hlens
