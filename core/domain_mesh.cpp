// Straub 2007, "Exact Computation of the Hausdorff Distance between Triangular Meshes", §3.1:
// the attributed half-edge structure holding d^2 over one target triangle, and the insertion of a
// source triangle into it. See domain_mesh.h and ../shared/design/algorithm.md.
#include "domain_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace hlens {

namespace {
constexpr double kSnap = 1e-8;      // crossing points closer than this to a vertex become that vertex
constexpr double kZero = 1e-12;     // |g| below this (g scaled to unit size) counts as on the curve
// Crossing points this close along a curve are one point: where several curves meet (the shadow of
// a vertex shared by many sources), nearly double roots are only accurate to about sqrt(epsilon).
constexpr double kCluster = 1e-7;
constexpr double kOnCurve = 1e-8;   // a vertex this close to a curve is on it
constexpr double kTwoPi = 6.283185307179586;

double wrap2pi(double a) {
    a = std::fmod(a, kTwoPi);
    return a < 0 ? a + kTwoPi : a;
}
Quadratic2 normalized(const Quadratic2& q) {
    double s = q.scale();
    return s > 0 ? q * (1.0 / s) : q;
}
Quadratic2 line_through(Vec2 a, Vec2 b) {
    Vec2 n = perp(b - a);
    double l = norm(n);
    if (l > 0) n = n / l;
    return half_plane(n, dot(n, a));
}
// 10-point Gauss-Legendre on [-1, 1].
const double kGx[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717};
const double kGw[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806, 0.0666713443086881};
}  // namespace

const char* arc_kind_name(ArcKind k) {
    switch (k) {
        case ArcKind::TargetBoundary: return "target boundary";
        case ArcKind::RegionBoundary: return "region boundary";
        case ArcKind::Conic: return "conic";
    }
    return "?";
}

double arc_interior_max(const RationalCurve& c, double z0, double z1, const Quadratic2& q, double* zmax) {
    if (c.straight()) return -HUGE_VAL;  // a convex quadratic along a line peaks at an end
    Poly F = c.compose(q), W = c.weight();
    Poly D = F.derivative() * W + (-2.0) * (F * W.derivative());
    double best = -HUGE_VAL;
    double roots[kMaxSignChangeRoots];
    const int n = sign_change_roots(D, z0, z1, roots);
    for (int i = 0; i < n; ++i) {
        const double z = roots[i];
        if (z <= z0 || z >= z1) continue;
        double v = q(c(z));
        if (v > best) { best = v; if (zmax) *zmax = z; }
    }
    return best;
}


// ---------------------------------------------------------------- construction

DomainMesh::DomainMesh(const std::array<Vec2, 3>& P) {
    faces_.resize(2);
    faces_[0].infinite = true;  // outside T': never a domain
    for (int i = 0; i < 3; ++i) add_vertex(P[i]);
    for (int i = 0; i < 3; ++i) {
        RationalCurve c;
        c.n0 = P[i];
        c.n1 = P[(i + 1) % 3] - P[i];
        int e = add_edge(c, 0, 1, line_through(P[i], P[(i + 1) % 3]), ArcKind::TargetBoundary, CurveKind::Line);
        half_[2 * e].origin = i;
        half_[2 * e + 1].origin = (i + 1) % 3;
        half_[2 * e].face = 1;
        half_[2 * e + 1].face = 0;
    }
    for (int i = 0; i < 3; ++i) {
        int h = 2 * i, hn = 2 * ((i + 1) % 3);
        half_[h].next = hn; half_[hn].prev = h;
        int t = 2 * i + 1, tn = 2 * ((i + 2) % 3) + 1;  // the outside loop runs clockwise
        half_[t].next = tn; half_[tn].prev = t;
    }
    faces_[1].loops = {0};
    faces_[0].loops = {1};
    live_faces_ = {1};
}

int DomainMesh::add_vertex(Vec2 p) {  // no face has it yet: no box changes
    vertices_.push_back({p, true});
    live_vertices_.push_back((int)vertices_.size() - 1);
    return (int)vertices_.size() - 1;
}

int DomainMesh::add_edge(const RationalCurve& c, double z0, double z1, const Quadratic2& eq, ArcKind kind, CurveKind ck) {
    Edge e;  // in no face's loop yet: no box changes
    e.curve = c; e.z0 = z0; e.z1 = z1; e.equation = normalized(eq); e.kind = kind; e.curve_kind = ck;
    edges_.push_back(e);
    edge_alive_.push_back(1);
    live_edges_.push_back((int)edges_.size() - 1);
    curved_of_.push_back(-1);
    set_arc_geometry((int)edges_.size() - 1);
    half_.resize(half_.size() + 2);
    return (int)edges_.size() - 1;
}

const std::vector<int>& DomainMesh::live_face_ids() {
    live_faces_.erase(std::remove_if(live_faces_.begin(), live_faces_.end(), [&](int f) { return !faces_[f].alive; }),
                      live_faces_.end());
    return live_faces_;
}

const std::vector<int>& DomainMesh::live_vertex_ids() {
    live_vertices_.erase(std::remove_if(live_vertices_.begin(), live_vertices_.end(), [&](int v) { return !vertices_[v].alive; }),
                         live_vertices_.end());
    return live_vertices_;
}

const std::vector<int>& DomainMesh::live_edge_ids() {
    live_edges_.erase(std::remove_if(live_edges_.begin(), live_edges_.end(), [&](int e) { return !edge_alive_[e]; }),
                      live_edges_.end());
    return live_edges_;
}

void DomainMesh::set_arc_geometry(int e) {
    const Edge& E = edges_[e];
    if (E.curve.straight()) {
        curved_of_[e] = -1;
        return;
    }
    if (curved_of_[e] < 0) {
        curved_of_[e] = (int)curved_.size();
        curved_.emplace_back();
    }
    ArcGeometry& G = curved_[curved_of_[e]].geo;
    G = ArcGeometry{};
    // The area between the arc and its chord, by quadrature on the parameter.
    double zm = 0.5 * (E.z0 + E.z1), zr = 0.5 * (E.z1 - E.z0), seg = 0;
    for (int i = 0; i < 5; ++i)
        for (int s : {-1, 1}) {
            double z = zm + s * kGx[i] * zr;
            seg += kGw[i] * 0.5 * cross(E.curve(z), E.curve.derivative(z));
        }
    seg *= zr;
    seg -= 0.5 * cross(E.curve(E.z0), E.curve(E.z1));
    G.segment = seg;
    // The arc may bulge past its ends: its extreme points in x and in y.
    Poly W = E.curve.weight();
    for (int axis = 0; axis < 2; ++axis) {
        Poly N;
        N.deg = 2;
        N.c[0] = axis ? E.curve.n0.y : E.curve.n0.x;
        N.c[1] = axis ? E.curve.n1.y : E.curve.n1.x;
        N.c[2] = axis ? E.curve.n2.y : E.curve.n2.x;
        Poly d = N.derivative() * W + (-1.0) * (N * W.derivative());
        double roots[kMaxSignChangeRoots];
        const int n = sign_change_roots(d, E.z0, E.z1, roots);
        for (int k = 0; k < n; ++k) G.bulge.add(E.curve(roots[k]));
    }
    // Where y turns: between these the arc is y-monotone.
    Poly Y;
    Y.deg = 2; Y.c[0] = E.curve.n0.y; Y.c[1] = E.curve.n1.y; Y.c[2] = E.curve.n2.y;
    Poly dY = Y.derivative() * W + (-1.0) * (Y * W.derivative());
    double roots[kMaxSignChangeRoots];
    const int nr = sign_change_roots(dY, E.z0, E.z1, roots);
    for (int k = 0; k < nr; ++k)
        if (roots[k] > E.z0 && roots[k] < E.z1) {
            assert(G.nturns < 8);  // dY has degree <= 3: at most 5 reported
            G.turns[G.nturns++] = roots[k];
        }
}

int DomainMesh::num_live_faces() const {
    int n = 0;
    for (size_t f = 1; f < faces_.size(); ++f) n += faces_[f].alive;
    return n;
}
int DomainMesh::num_live_edges() const {
    int n = 0;
    for (const Edge& e : edges_) n += e.alive;
    return n;
}
int DomainMesh::num_live_vertices() const {
    int n = 0;
    for (const Vertex& v : vertices_) n += v.alive;
    return n;
}

template <class Fn>
void DomainMesh::for_each_half_edge(int f, Fn&& fn) const {
    for (int start : faces_[f].loops) {
        int h = start, guard = 0;
        do {
            fn(h);
            h = half_[h].next;
            if (++guard > 1000000) break;
        } while (h != start);
    }
}

void DomainMesh::collect_half_edges(int f, std::vector<int>& out) const {
    out.clear();
    for_each_half_edge(f, [&](int h) { out.push_back(h); });
}

std::vector<int> DomainMesh::face_half_edges(int f) const {
    std::vector<int> out;
    collect_half_edges(f, out);
    return out;
}

void DomainMesh::touch_face(int f) {
    if (f < 0) return;
    if (face_stamp_.size() < faces_.size()) face_stamp_.resize(faces_.size(), 0);
    face_stamp_[f] = ++clock_;
}

void DomainMesh::touch_edge_faces(int e) {
    touch_face(half_[2 * e].face);
    touch_face(half_[2 * e + 1].face);
}

uint64_t DomainMesh::Scratch::next_stamp(std::vector<uint64_t>& marks, size_t n) {
    if (marks.size() < n) marks.resize(n, 0);
    return ++stamp;
}

// ---------------------------------------------------------------- geometry of arcs

Vec2 DomainMesh::edge_point(int e, double s) const {
    const Edge& E = edges_[e];
    if (s <= 0) return vertices_[half_[2 * e].origin].p;
    if (s >= 1) return vertices_[half_[2 * e + 1].origin].p;
    return E.curve(E.z0 + s * (E.z1 - E.z0));
}

Vec2 DomainMesh::he_point(int h, double s) const { return edge_point(h >> 1, (h & 1) ? 1 - s : s); }

Vec2 DomainMesh::out_tangent(int h) const {
    const Edge& E = edges_[h >> 1];
    Vec2 d = (h & 1) ? -1.0 * E.curve.derivative(E.z1) : E.curve.derivative(E.z0);
    double l = norm(d);
    return l > 0 ? d / l : d;
}

std::vector<Vec2> DomainMesh::sample_loop(int start, int per_arc) const {
    std::vector<Vec2> out;
    int h = start;
    do {
        int n = edges_[h >> 1].curve.straight() ? 1 : per_arc;
        for (int i = 0; i < n; ++i) out.push_back(he_point(h, (double)i / n));
        h = half_[h].next;
    } while (h != start);
    return out;
}

double DomainMesh::loop_area(int start) const {
    double area = 0;
    int h = start;
    do {
        const Edge& E = edges_[h >> 1];
        Vec2 a = vertices_[half_[h].origin].p, b = vertices_[target(h)].p;
        area += 0.5 * cross(a, b);
        if (!E.curve.straight()) {
            const double seg = arc_geometry(h >> 1).segment;  // between the arc and its chord
            area += (h & 1) ? -seg : seg;
        }
        h = half_[h].next;
    } while (h != start);
    return area;
}

double DomainMesh::face_area(int f) const {
    double a = 0;
    for (int l : faces_[f].loops) a += loop_area(l);
    return a;
}

namespace {
// Number of crossings of the ray {(x, p.y) : x > p.x} with the arc, by y-monotone pieces (split
// where y turns, at `turns`).
int ray_crossings(const RationalCurve& c, double z0, double z1, const double* turns, int nturns, Vec2 A, Vec2 B, Vec2 p) {
    double zs[10];
    size_t nz = 0;
    zs[nz++] = z0;
    for (int k = 0; k < nturns; ++k) zs[nz++] = turns[k];
    zs[nz++] = z1;
    int n = 0;
    auto pt = [&](size_t i) { return i == 0 ? A : (i + 1 == nz ? B : c(zs[i])); };
    for (size_t i = 0; i + 1 < nz; ++i) {
        Vec2 a = pt(i), b = pt(i + 1);
        if ((a.y > p.y) == (b.y > p.y)) continue;
        double x;
        if (c.straight()) {
            x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
        } else {  // y is monotone on this piece: bisect for the crossing
            double lo = zs[i], hi = zs[i + 1];
            bool up = b.y > a.y;
            for (int it = 0; it < 80; ++it) {
                double m = 0.5 * (lo + hi);
                if ((c(m).y > p.y) == up) hi = m; else lo = m;
            }
            x = c(0.5 * (lo + hi)).x;
        }
        if (x > p.x) ++n;
    }
    return n;
}
}  // namespace

int DomainMesh::loop_crossings(int start, Vec2 p) const {
    int n = 0, h = start;
    do {
        const Edge& E = edges_[h >> 1];
        const bool curved = !E.curve.straight();
        n += ray_crossings(E.curve, E.z0, E.z1, curved ? arc_geometry(h >> 1).turns : nullptr,
                           curved ? arc_geometry(h >> 1).nturns : 0, vertices_[half_[h & ~1].origin].p,
                           vertices_[half_[h | 1].origin].p, p);
        h = half_[h].next;
    } while (h != start);
    return n;
}

bool DomainMesh::point_in_face(int f, Vec2 p) const {
    int n = 0;
    for (int l : faces_[f].loops) n += loop_crossings(l, p);
    return n & 1;
}

Box2 DomainMesh::face_box(int f) const {
    Box2 b;
    for_each_half_edge(f, [&](int h) {
        b.add(vertices_[half_[h].origin].p);
        if (edges_[h >> 1].curve.straight()) return;
        const Box2& bulge = arc_geometry(h >> 1).bulge;  // a curved arc may bulge past its ends
        b.lo = {std::min(b.lo.x, bulge.lo.x), std::min(b.lo.y, bulge.lo.y)};
        b.hi = {std::max(b.hi.x, bulge.hi.x), std::max(b.hi.y, bulge.hi.y)};
    });
    return b;
}

Box2 DomainMesh::cached_face_box(int f) {
    if (box_stamp_.size() < faces_.size()) {
        box_stamp_.resize(faces_.size(), 0);
        box_cache_.resize(faces_.size());
    }
    if (face_stamp_.size() < faces_.size()) face_stamp_.resize(faces_.size(), 0);
    if (box_stamp_[f] == 0 || box_stamp_[f] < face_stamp_[f]) {
        box_cache_[f] = face_box(f);
        box_stamp_[f] = ++clock_;
    }
#ifndef NDEBUG
    // The invalidation is the delicate part: check it where it is cheap to (debug builds).
    const Box2 fresh = face_box(f), &kept = box_cache_[f];
    assert(fresh.lo == kept.lo && fresh.hi == kept.hi);
#endif
    return box_cache_[f];
}

bool DomainMesh::near_boundary(int f, Vec2 p, double tol) const {
    bool near = false;
    for_each_half_edge(f, [&](int h) {
        if (!near) near = near_arc(h, p, tol);
    });
    return near;
}

bool DomainMesh::near_arc(int h, Vec2 p, double tol) const {
    const Edge& E = edges_[h >> 1];
    Vec2 a = vertices_[half_[h].origin].p, b = vertices_[target(h)].p;
    if (E.curve.straight()) {
        // Farther than tol from the segment's box (with room for rounding): not near.
        const double room = tol * (1 + 1e-9) + 1e-12 * (std::fabs(a.x) + std::fabs(a.y) + std::fabs(b.x) + std::fabs(b.y));
        if (p.x < std::min(a.x, b.x) - room || p.x > std::max(a.x, b.x) + room || p.y < std::min(a.y, b.y) - room ||
            p.y > std::max(a.y, b.y) + room)
            return false;
        Vec2 d = b - a;
        double t = norm2(d) > 0 ? std::clamp(dot(p - a, d) / norm2(d), 0.0, 1.0) : 0.0;
        return norm(a + t * d - p) <= tol;
    }
    const Vec2 gr = E.equation.gradient(p);
    const double ev = std::fabs(E.equation(p));
    // |grad| <= |gx| + |gy|: far off the conic without taking the root.
    if (ev > tol * ((std::fabs(gr.x) + std::fabs(gr.y)) * (1 + 1e-12))) return false;
    double gn = norm(gr);
    if (gn == 0 || ev > tol * gn) return false;
    // On the conic; on this arc if the foot lies within the arc's parameter range.
    double lo = std::min(E.z0, E.z1), hi = std::max(E.z0, E.z1);
    for (int i = 0; i <= 16; ++i) {
        double z0 = lo + (hi - lo) * i / 16.0;
        if (norm(E.curve(z0) - p) <= tol + norm(E.curve(lo + (hi - lo) / 16.0) - E.curve(lo))) {
            // refine by golden-section on |curve(z) - p| over the neighbouring cells
            double l = std::max(lo, z0 - (hi - lo) / 16.0), r = std::min(hi, z0 + (hi - lo) / 16.0);
            for (int it = 0; it < 60; ++it) {
                double m1 = l + (r - l) * 0.382, m2 = l + (r - l) * 0.618;
                if (norm(E.curve(m1) - p) < norm(E.curve(m2) - p)) r = m2; else l = m1;
            }
            if (norm(E.curve(0.5 * (l + r)) - p) <= tol) return true;
        }
    }
    return false;
}

bool DomainMesh::interior_point(int f, Vec2& out) const {
    std::vector<int> hes = face_half_edges(f);
    // Longest arcs first: their middles are farthest from other boundary pieces.
    std::vector<std::pair<double, int>> order;
    for (int h : hes) order.push_back({-norm(vertices_[target(h)].p - vertices_[half_[h].origin].p), h});
    std::sort(order.begin(), order.end());
    for (double step : {1e-3, 1e-5, 1e-2, 1e-7, 1e-9})
        for (size_t i = 0; i < order.size() && i < 8; ++i) {
            int h = order[i].second;
            const Edge& E = edges_[h >> 1];
            double z = 0.5 * (E.z0 + E.z1);
            Vec2 m = E.curve(z), d = E.curve.derivative(z);
            if (h & 1) d = -1.0 * d;
            double l = norm(d);
            if (l == 0) continue;
            Vec2 cand = m + (step * std::min(1.0, -order[i].first + 1e-300) / l) * perp(d);
            if (point_in_face(f, cand)) { out = cand; return true; }
        }
    return false;
}

int DomainMesh::face_at(Vec2 p) const {
    for (size_t f = 1; f < faces_.size(); ++f)
        if (faces_[f].alive && point_in_face((int)f, p)) return (int)f;
    return -1;
}

// ---------------------------------------------------------------- topology edits

int DomainMesh::split_edge(int e, double z) {
    Vec2 p = edges_[e].curve(z);
    int v = add_vertex(p);
    Edge copy = edges_[e];
    int e2 = add_edge(copy.curve, z, copy.z1, copy.equation, copy.kind, copy.curve_kind);
    edges_[e].z1 = z;
    set_arc_geometry(e);
    int h = 2 * e, t = 2 * e + 1, g = 2 * e2, gt = 2 * e2 + 1;
    // forward: h a->v, g v->b
    half_[g].origin = v;
    half_[g].face = half_[h].face;
    half_[g].next = half_[h].next;
    half_[half_[h].next].prev = g;
    half_[h].next = g;
    half_[g].prev = h;
    // backward: gt b->v, t v->a
    half_[gt].origin = half_[t].origin;
    half_[t].origin = v;
    half_[gt].face = half_[t].face;
    half_[gt].prev = half_[t].prev;
    half_[half_[t].prev].next = gt;
    half_[gt].next = t;
    half_[t].prev = gt;
    touch_edge_faces(e);  // a curved arc's pieces bulge no farther, but their boxes round differently
    return v;
}

int DomainMesh::find_wedge(const std::vector<int>& hes, int face, int v, Vec2 dir, Vec2 dir2) {
    std::vector<int>& cands = tmp_.wedge_cands;
    cands.clear();
    for (int h : hes)
        if (half_[h].face == face && half_[h].next >= 0 && edges_[h >> 1].alive && target(h) == v) cands.push_back(h);
    if (cands.size() == 1) return cands[0];
    if (cands.empty()) return -1;
    double ad = std::atan2(dir.y, dir.x);
    for (int pass = 0; pass < 2; ++pass) {
        for (int hin : cands) {
            int hout = half_[hin].next;
            Vec2 dout = out_tangent(hout), dback = out_tangent(hin ^ 1);
            if (pass == 1) {  // tangential ties: compare short secants instead of tangents
                dout = he_point(hout, 1e-3) - vertices_[v].p;
                dback = he_point(hin ^ 1, 1e-3) - vertices_[v].p;
                ad = std::atan2(dir2.y, dir2.x);
            }
            double ao = std::atan2(dout.y, dout.x), ab = std::atan2(dback.y, dback.x);
            double rd = wrap2pi(ad - ao), rb = wrap2pi(ab - ao);
            if (rb == 0) rb = kTwoPi;
            if (rd > 1e-12 && rd < rb - 1e-12) return hin;
        }
    }
    return cands[0];
}

void DomainMesh::insert_path(int face, const std::vector<int>& hes, const std::vector<int>& verts, const std::vector<int>& es, bool closed_new) {
    assert(verts.size() == es.size() + 1);
    touch_face(face);
    size_t n = es.size();
    for (size_t k = 0; k < n; ++k) {
        int h = 2 * es[k];
        half_[h].origin = verts[k];
        half_[h + 1].origin = verts[k + 1];
        half_[h].face = half_[h + 1].face = face;
        if (k + 1 < n) {
            int hn = 2 * es[k + 1];
            half_[h].next = hn; half_[hn].prev = h;
            half_[hn + 1].next = h + 1; half_[h + 1].prev = hn + 1;
        }
    }
    int first = 2 * es.front(), last = 2 * es.back();
    if (closed_new) {  // a loop through a new vertex: close it on itself
        half_[last].next = first; half_[first].prev = last;
        half_[first + 1].next = last + 1; half_[last + 1].prev = first + 1;
        return;
    }
    // Hook the ends into the wedges of `face` at the end vertices.
    auto dir_out = [&](int h) { return out_tangent(h); };
    auto sec_out = [&](int h) { return he_point(h, 1e-3) - vertices_[half_[h].origin].p; };
    int a = verts.front(), b = verts.back();
    // An end at a vertex with no edge yet (the centre of a line pair) becomes the tip of a
    // dangling path, which later paths to the same vertex attach to.
    int hin = find_wedge(hes, face, a, dir_out(first), sec_out(first));
    if (hin < 0) {
        half_[first + 1].next = first; half_[first].prev = first + 1;
    } else {
        int hout = half_[hin].next;
        half_[hin].next = first; half_[first].prev = hin;
        half_[first + 1].next = hout; half_[hout].prev = first + 1;
    }
    int hin2 = find_wedge(hes, face, b, dir_out(last + 1), sec_out(last + 1));
    if (hin2 < 0) {
        half_[last].next = last + 1; half_[last + 1].prev = last;
    } else {
        int hout2 = half_[hin2].next;
        half_[hin2].next = last + 1; half_[last + 1].prev = hin2;
        half_[last].next = hout2; half_[hout2].prev = last;
    }
}

void DomainMesh::rebuild_faces(const std::vector<int>& hes, int reuse, std::vector<int>& fids) {
    touch_face(reuse);
    std::vector<int>& cycles = tmp_.cycles;
    std::vector<double>& areas = tmp_.areas;
    cycles.clear();
    areas.clear();
    const uint64_t seen = tmp_.next_stamp(tmp_.seen_mark, half_.size());
    for (int h0 : hes) {
        if (tmp_.seen_mark[h0] == seen) continue;
        int h = h0, guard = 0;
        do { tmp_.seen_mark[h] = seen; h = half_[h].next; } while (h != h0 && ++guard < 1000000);
        cycles.push_back(h0);
        areas.push_back(loop_area(h0));
    }
    std::vector<int>& outers = tmp_.outers;
    std::vector<int>& holes = tmp_.holes;
    outers.clear();
    holes.clear();
    for (size_t i = 0; i < cycles.size(); ++i) (areas[i] > 0 ? outers : holes).push_back((int)i);
    if (outers.empty() && !holes.empty()) {  // numerically flat: the largest loop is the outer one
        auto it = std::max_element(holes.begin(), holes.end(), [&](int x, int y) { return std::fabs(areas[x]) < std::fabs(areas[y]); });
        outers.push_back(*it);
        holes.erase(it);
        ++stats_.warnings;
    }
    fids.clear();
    if (!outers.empty()) {
        // New faces start as copies of `reuse` (its quadratic and label), without its loops.
        assert(faces_[reuse].alive);  // (dead faces are never revived: see live_faces_)
        faces_[reuse].loops.clear();
        const Face proto = faces_[reuse];
        for (size_t k = 0; k < outers.size(); ++k) {
            int fid = reuse;
            if (k > 0) {
                faces_.push_back(proto);
                fid = (int)faces_.size() - 1;
                live_faces_.push_back(fid);
            }
            faces_[fid].loops.assign(1, cycles[outers[k]]);
            faces_[fid].alive = true;
            fids.push_back(fid);
        }
    }
    for (int hi : holes) {
        // A point on the hole lies strictly inside exactly the outer loops that enclose the hole.
        const Edge& E = edges_[cycles[hi] >> 1];
        Vec2 p = E.curve(0.5 * (E.z0 + E.z1));
        int best = -1;
        double best_area = HUGE_VAL;
        for (size_t k = 0; k < outers.size(); ++k) {
            int n = loop_crossings(cycles[outers[k]], p);
            if ((n & 1) && areas[outers[k]] < best_area) { best = (int)k; best_area = areas[outers[k]]; }
        }
        if (best < 0) { best = 0; ++stats_.warnings; }
        faces_[fids[best]].loops.push_back(cycles[hi]);
    }
    for (int fid : fids) {
        for_each_half_edge(fid, [&](int h) { half_[h].face = fid; });
        touch_face(fid);
    }
}

void DomainMesh::remove_edge(int e) {
    touch_edge_faces(e);
    int h = 2 * e, t = 2 * e + 1;
    int hn = half_[h].next, hp = half_[h].prev, tn = half_[t].next, tp = half_[t].prev;
    if (hn == t && tn == h) {
        vertices_[half_[h].origin].alive = false;
        vertices_[half_[t].origin].alive = false;
    } else if (hn == t) {  // target of h is the tip of a dangling edge
        half_[hp].next = tn; half_[tn].prev = hp;
        vertices_[half_[t].origin].alive = false;
    } else if (tn == h) {
        half_[tp].next = hn; half_[hn].prev = tp;
        vertices_[half_[h].origin].alive = false;
    } else {
        half_[hp].next = tn; half_[tn].prev = hp;
        half_[tp].next = hn; half_[hn].prev = tp;
    }
    edges_[e].alive = false;
    edge_alive_[e] = 0;
    half_[h].face = half_[t].face = -1;
}

void DomainMesh::merge_equal_neighbours(const Listener* L) {
    bool changed = true;
    // Each pass removes at least one edge, so there are at most as many passes as edges.
    for (size_t pass = 0; changed && pass <= edges_.size(); ++pass) {
        changed = false;
        const std::vector<int>& live_edges = live_edge_ids();  // no edge is added while merging
        for (size_t i = 0; i < live_edges.size(); ++i) {
            const size_t e = (size_t)live_edges[i];
            if (!edge_alive_[e]) continue;
            int F = half_[2 * e].face, G = half_[2 * e + 1].face;
            if (F <= 0 || G <= 0) continue;
            const Face &fa = faces_[F], &fb = faces_[G];
            bool equal = F == G || (fa.infinite && fb.infinite) ||
                         (!fa.infinite && !fb.infinite && same_quadratic(fa.poly, fb.poly, delta_));
            if (!equal) continue;
            int keep = std::min(F, G), gone = std::max(F, G);
            std::vector<int>& hes = tmp_.merge_hes;
            hes.clear();
            for_each_half_edge(F, [&](int h) { hes.push_back(h); });
            if (G != F) for_each_half_edge(G, [&](int h) { hes.push_back(h); });
            remove_edge((int)e);
            hes.erase(std::remove_if(hes.begin(), hes.end(), [&](int h) { return (h >> 1) == (int)e; }), hes.end());
            if (gone != keep) faces_[gone].alive = false, faces_[gone].loops.clear(), touch_face(gone);
            if (hes.empty()) { faces_[keep].alive = false; faces_[keep].loops.clear(); touch_face(keep); ++stats_.warnings; continue; }
            // Only half-edges still in a loop (a removed dangling edge takes its tip with it).
            std::vector<int>& live = tmp_.live;
            live.clear();
            for (int h : hes)
                if (edge_alive_[h >> 1]) live.push_back(h);
            std::vector<int>& fids = tmp_.fids;
            rebuild_faces(live, keep, fids);
            if (fids.size() != 1) ++stats_.warnings;
            ++stats_.merges;
            if (L && L->on_merge && gone != keep) L->on_merge(keep, gone);
            changed = true;
        }
    }
}

void DomainMesh::replace_loop_start(int face, int from, int to) {
    if (face < 0) return;
    for (int& l : faces_[face].loops) {
        if (l == from) l = to;
    }
}

void DomainMesh::dissolve_collinear_vertices() {
    std::vector<int>& degree = tmp_.degree;
    std::vector<int>& any_out = tmp_.any_out;
    degree.assign(vertices_.size(), 0);
    any_out.assign(vertices_.size(), -1);
    for (int e : live_edge_ids())
        for (int h : {2 * e, 2 * e + 1}) { ++degree[half_[h].origin]; any_out[half_[h].origin] = h; }
    for (int vi : live_vertex_ids()) {
        const size_t v = (size_t)vi;
        if (v < 3) continue;  // the target's corners stay
        if (!vertices_[v].alive || degree[v] != 2) continue;
        int o1 = any_out[v];
        int h1 = half_[o1 ^ 1].next == o1 ? -1 : half_[o1].prev;  // incoming to v on o1's face
        if (h1 < 0) continue;
        int h2 = o1;  // h1: a -> v, h2: v -> b
        int e1 = h1 >> 1, e2 = h2 >> 1;
        if (e1 == e2 || !edges_[e1].curve.straight() || !edges_[e2].curve.straight()) continue;
        if (edges_[e1].kind != edges_[e2].kind) continue;
        int a = half_[h1].origin, b = target(h2);
        if (a == b) continue;
        Vec2 pa = vertices_[a].p, pv = vertices_[v].p, pb = vertices_[b].p;
        Vec2 d1 = pv - pa, d2 = pb - pv;
        // Two pieces of one line (their equations agree) with v between their far ends. Angles
        // between tiny pieces mean nothing, so the equations decide, not the positions.
        const Quadratic2 &q1 = edges_[e1].equation, &q2 = edges_[e2].equation;
        if (!same_polynomial(q1, q2, 1e-9) && !same_polynomial(q1, q2 * -1.0, 1e-9)) continue;
        if (dot(d1, d2) < 0 && norm(d1) > kCluster && norm(d2) > kCluster) continue;
        // h1 becomes a -> b, its twin b -> a; e2 goes away.
        touch_edge_faces(e1);  // (e2 has the same faces)
        int t1 = h1 ^ 1, t2 = h2 ^ 1;  // t2: b -> v, t1: v -> a
        half_[h1].next = half_[h2].next; half_[half_[h2].next].prev = h1;
        half_[t1].origin = b;
        half_[t1].prev = half_[t2].prev; half_[half_[t2].prev].next = t1;
        Edge& E = edges_[e1];
        Vec2 from = (h1 & 1) ? pb : pa, to = (h1 & 1) ? pa : pb;
        E.curve = RationalCurve{};
        E.curve.n0 = from; E.curve.n1 = to - from;
        E.z0 = 0; E.z1 = 1;
        set_arc_geometry(e1);
        edges_[e2].alive = false;
        edge_alive_[e2] = 0;
        const int fh2 = half_[h2].face, ft2 = half_[t2].face;
        half_[h2].face = half_[t2].face = -1;
        vertices_[v].alive = false;
        // A loop may start at h2 or t2 only in their own faces (every half-edge of a face's loops
        // carries that face).
        replace_loop_start(fh2, h2, h1);
        replace_loop_start(fh2, t2, t1);
        replace_loop_start(ft2, h2, h1);
        replace_loop_start(ft2, t2, t1);
#ifndef NDEBUG
        for (const Face& f : faces_)
            for (int l : f.loops) assert(l != h2 && l != t2);
#endif
        if (any_out[b] == t2) any_out[b] = t1;
        if (any_out[a] == h2) any_out[a] = h1;
    }
}

// ---------------------------------------------------------------- Newton polishing

bool DomainMesh::polish_on_two(const Quadratic2& f, const Quadratic2& g, Vec2& p) const {
    Vec2 x = p;
    for (int it = 0; it < 4; ++it) {
        Vec2 gf = f.gradient(x), gg = g.gradient(x);
        double det = cross(gf, gg);
        if (std::fabs(det) <= 1e-6 * norm(gf) * norm(gg)) return false;  // nearly tangent: keep p
        double F = f(x), G = g(x);
        Vec2 step{(F * gg.y - G * gf.y) / det, (gf.x * G - gg.x * F) / det};
        x -= step;
        if (norm(step) < 1e-17) break;
    }
    if (norm(x - p) > 1e-7) return false;
    p = x;
    return true;
}

bool DomainMesh::polish_arc_max(const Quadratic2& q, const Quadratic2& g, Vec2& p) const {
    Vec2 x = p;
    for (int it = 0; it < 5; ++it) {
        Vec2 dq = q.gradient(x), dg = g.gradient(x);
        double G1 = g(x), G2 = cross(dq, dg);
        double d2x = 2 * q.a * dg.y + dq.x * 2 * g.b - 2 * q.b * dg.x - dq.y * 2 * g.a;
        double d2y = 2 * q.b * dg.y + dq.x * 2 * g.c - 2 * q.c * dg.x - dq.y * 2 * g.b;
        double det = dg.x * d2y - dg.y * d2x;
        if (std::fabs(det) < 1e-14) return false;
        Vec2 step{(G1 * d2y - dg.y * G2) / det, (dg.x * G2 - d2x * G1) / det};
        x -= step;
        if (norm(step) < 1e-17) break;
    }
    if (norm(x - p) > 1e-6 || q(x) < q(p) - 1e-15 * (1 + std::fabs(q(p)))) return false;
    p = x;
    return true;
}

// ---------------------------------------------------------------- the clip primitive

std::vector<DomainMesh::SplitPiece> DomainMesh::split_face(int f, const Quadratic2& g) {
    std::vector<SplitPiece> out;
    split_face_into(f, g, out);
    return out;
}

void DomainMesh::split_face_into(int f, const Quadratic2& g_in, std::vector<SplitPiece>& out) {
    out.clear();
    double gs = g_in.scale();
    if (!(gs > 0)) { out.push_back({f, 0}); return; }
    const Quadratic2 g = g_in * (1.0 / gs);
    {
        // Most faces lie wholly on one side: a conservative bound over the face's box says so.
        Box2 b = cached_face_box(f);
        Interval r = g.range(b.lo, b.hi);
        if (r.lo > kZero) { out.push_back({f, 1}); return; }
        if (r.hi < -kZero) { out.push_back({f, -1}); return; }
    }
    std::vector<int>& zero_list = tmp_.zero_list;  // vertices on the curve (few): a list, not a flag per vertex
    zero_list.clear();
    auto mark_zero = [&](int v) {
        if (std::find(zero_list.begin(), zero_list.end(), v) == zero_list.end()) zero_list.push_back(v);
    };
    auto is_zero = [&](int v) { return std::find(zero_list.begin(), zero_list.end(), v) != zero_list.end(); };

    // 1. Split the boundary where g changes sign.
    std::vector<int>& hes = tmp_.hes;
    collect_half_edges(f, hes);
    std::vector<int>& edge_list = tmp_.edge_list;  // each edge once, in the order of `hes`
    edge_list.clear();
    {
        const uint64_t seen = tmp_.next_stamp(tmp_.edge_mark, edges_.size());
        for (int h : hes)
            if (tmp_.edge_mark[h >> 1] != seen) {
                tmp_.edge_mark[h >> 1] = seen;
                edge_list.push_back(h >> 1);
            }
    }
    for (int e : edge_list) {
        const Poly along = edges_[e].curve.compose(g);  // g along the arc, times w^2
        if (no_sign_change(along, edges_[e].z0, edges_[e].z1)) continue;  // most arcs: nothing to find
        const RationalCurve curve = edges_[e].curve;   // copies: split_edge may move edges_
        const Quadratic2 eq = edges_[e].equation;
        double roots[kMaxSignChangeRoots];
        const int nroots = sign_change_roots(along, edges_[e].z0, edges_[e].z1, roots);
        int cur = e;
        for (int k = 0; k < nroots; ++k) {
            const double z = roots[k];
            Vec2 p = curve(z);
            int va = half_[2 * cur].origin, vb = half_[2 * cur + 1].origin;
            if (norm(p - vertices_[va].p) <= kSnap) { mark_zero(va); ++stats_.snaps; continue; }
            if (norm(p - vertices_[vb].p) <= kSnap) { mark_zero(vb); ++stats_.snaps; continue; }
            if (!(z > edges_[cur].z0 && z < edges_[cur].z1)) continue;
            polish_on_two(g, eq, p);
            int v = split_edge(cur, z);
            vertices_[v].p = p;
            touch_edge_faces(cur);  // the polished vertex moved off curve(z) by rounding
            mark_zero(v);
            cur = (int)edges_.size() - 1;
        }
    }
    collect_half_edges(f, hes);

    // 2. Classify vertices on the curve and boundary arcs by side.
    for (int h : hes) {
        Vec2 p = vertices_[half_[h].origin].p;
        const double gp = std::fabs(g(p));
        if (gp <= kZero) { mark_zero(half_[h].origin); continue; }
        // Far from the curve by a bound of |grad g| (the norm is at most |gx| + |gy|): no root needed.
        const Vec2 gr = g.gradient(p);
        if (gp > kZero + kOnCurve * ((std::fabs(gr.x) + std::fabs(gr.y)) * (1 + 1e-12))) continue;
        if (gp <= kZero + kOnCurve * norm(gr)) mark_zero(half_[h].origin);
    }
    // Each arc's side, as the signed distance-like value of g at its middle,
    //   sd = |g(m)| <= kZero ? 0 : g(m) / max(|grad g(m)|, 1e-3):
    // the arc farthest from the curve is the one whose side is certain. Kept per half-edge of
    // `hes` (stamped; arcs added below have none) as g(m) and |grad g(m)|^2: the sign of sd is that
    // of g(m), and its value (a root and a division) is only taken where signs disagree.
    const uint64_t sided = tmp_.next_stamp(tmp_.he_mark, half_.size());
    if (tmp_.side_val.size() < half_.size()) {
        tmp_.side_val.resize(half_.size());
        tmp_.side_n2.resize(half_.size());
    }
    auto marked = [&](int h) { return (size_t)h < tmp_.he_mark.size() && tmp_.he_mark[h] == sided; };
    auto side_value = [&](int h) {
        const double val = tmp_.side_val[h];
        return std::fabs(val) <= kZero ? 0.0 : val / std::max(std::sqrt(tmp_.side_n2[h]), 1e-3);
    };
    auto side_sign = [&](int h) {  // the sign of side_value(h)
        const double val = tmp_.side_val[h];
        if (!(std::fabs(val) <= HUGE_VAL && std::fabs(tmp_.side_n2[h]) < HUGE_VAL)) {  // NaN or inf: be exact
            const double v = side_value(h);
            return v > 0 ? 1 : (v < 0 ? -1 : 0);
        }
        return std::fabs(val) <= kZero ? 0 : (val > 0 ? 1 : -1);
    };
    auto side_of = [&](int h, double& v) {
        if (!marked(h)) return false;
        v = side_value(h);
        return true;
    };
    int npos = 0, nneg = 0;
    for (int h : hes) {
        const Edge& E = edges_[h >> 1];
        Vec2 m = E.curve(0.5 * (E.z0 + E.z1));
        const Vec2 gr = g.gradient(m);
        tmp_.side_val[h] = g(m);
        tmp_.side_n2[h] = dot(gr, gr);  // norm(gr) is sqrt of exactly this
        tmp_.he_mark[h] = sided;
        const int sg = side_sign(h);
        npos += sg > 0;
        nneg += sg < 0;
    }
    // The sign of the side of the arc of `loop_hes` farthest from the curve (the first of equals).
    auto decided_side = [&](const std::vector<int>& loop_hes) {
        bool pos = false, neg = false;
        for (int h : loop_hes)
            if (marked(h)) {
                const int sg = side_sign(h);
                pos |= sg > 0;
                neg |= sg < 0;
            }
        if (!(pos && neg)) return pos ? 1 : (neg ? -1 : 0);
        double best = 0, v;
        for (int h : loop_hes)
            if (side_of(h, v) && std::fabs(v) > std::fabs(best)) best = v;
        return best > 0 ? 1 : (best < 0 ? -1 : 0);
    };

    // 3. Pieces of the curve g = 0 inside the face, between consecutive crossing points.
    std::vector<Chord>& chords = tmp_.chords;
    chords.clear();
    std::vector<int>& zverts = tmp_.zverts;
    zverts.clear();
    for (int h : hes) {
        int v = half_[h].origin;
        if (is_zero(v) && std::find(zverts.begin(), zverts.end(), v) == zverts.end()) zverts.push_back(v);
    }
    ConicDecomposition& dec = tmp_.dec;
    decompose_conic(g, dec);
    if (dec.type == ConicType::LinePair && dec.components.size() == 2) {
        // The two lines cross at the centre: inside the face it must be a vertex of both.
        const CurveComponent &l1 = dec.components[0], &l2 = dec.components[1];
        double den = cross(l1.u, l2.u);
        if (den != 0) {
            Vec2 m = l1.c + (cross(l2.c - l1.c, l2.u) / den) * l1.u;
            bool near = false;
            for (int v : zverts) near |= norm(vertices_[v].p - m) <= kCluster;
            if (!near && point_in_face(f, m)) {
                int vm = add_vertex(m);
                mark_zero(vm);
                zverts.push_back(vm);
            }
        }
    }
    bool line_like = dec.type == ConicType::Line || dec.type == ConicType::ParallelLines || dec.type == ConicType::LinePair;
    for (const CurveComponent& comp : dec.components) {
        std::vector<std::pair<double, int>>& pts = tmp_.pts;
        pts.clear();
        for (int v : zverts) {
            Vec2 p = vertices_[v].p;
            double t = comp.param_of(p);
            if (norm(comp.at(t) - p) <= 1e-7) pts.push_back({t, v});
        }
        std::sort(pts.begin(), pts.end());
        std::vector<Chord>& cand = tmp_.cand;
        cand.clear();
        if (comp.closed()) {
            if (pts.empty()) {
                if (npos + nneg > 0 && point_in_face(f, comp.at(0)) && point_in_face(f, comp.at(M_PI)))
                    cand.push_back({comp, 0, kTwoPi, -1, -1});
            } else {
                for (size_t i = 0; i < pts.size(); ++i) {
                    auto [ta, va] = pts[i];
                    auto [tb, vb] = pts[(i + 1) % pts.size()];
                    if (i + 1 == pts.size()) tb += kTwoPi;
                    cand.push_back({comp, ta, tb, va, vb});
                }
            }
        } else {
            for (size_t i = 0; i + 1 < pts.size(); ++i)
                cand.push_back({comp, pts[i].first, pts[i + 1].first, pts[i].second, pts[i + 1].second});
        }
        for (const Chord& c : cand) {
            if (c.va >= 0 && c.va == c.vb && !comp.closed()) continue;
            if (c.va >= 0 && !(c.t1 - c.t0 > 1e-12)) continue;
            Vec2 mid = comp.at(0.5 * (c.t0 + c.t1));
            if (c.va >= 0 && !comp.closed() && norm(vertices_[c.va].p - vertices_[c.vb].p) <= kCluster) continue;
            if (c.va >= 0) {
                // A piece along the face's boundary is already there; one outside is not ours.
                if (near_boundary(f, mid, kCluster)) continue;
                if (!point_in_face(f, mid)) continue;
            }
            chords.push_back(c);
        }
    }

    if (chords.empty()) {
        int s = decided_side(hes);
        if (s == 0) {
            Vec2 p;
            if (interior_point(f, p)) s = g(p) > 0 ? 1 : (g(p) < 0 ? -1 : 0);
        }
        out.push_back({f, s});
        return;
    }

    // 4. Insert the chords, each as a path of well-conditioned arcs.
    ArcKind kind = line_like && g_in.is_linear() ? ArcKind::RegionBoundary : ArcKind::Conic;
    for (const Chord& c : chords) {
        std::vector<CurveComponent::Piece>& pieces = tmp_.arc_pieces;
        c.comp.pieces(c.t0, c.t1, pieces);
        std::vector<int>& verts = tmp_.verts;
        std::vector<int>& es = tmp_.es;
        verts.clear();
        es.clear();
        int start = c.va >= 0 ? c.va : add_vertex(c.comp.at(c.t0));
        verts.push_back(start);
        for (size_t k = 0; k < pieces.size(); ++k) {
            int e = add_edge(pieces[k].curve, pieces[k].z0, pieces[k].z1, g, kind, c.comp.kind);
            es.push_back(e);
            if (k + 1 < pieces.size()) verts.push_back(add_vertex(pieces[k].curve(pieces[k].z1)));
        }
        verts.push_back(c.va >= 0 ? c.vb : start);
        if (c.va < 0 && pieces.size() < 2) { ++stats_.warnings; continue; }
        for (int e : es) { hes.push_back(2 * e); hes.push_back(2 * e + 1); }
        insert_path(f, hes, verts, es, c.va < 0);
        ++stats_.splits;
    }

    // 5. The face's half-edges now form several loops: one face per outer loop.
    std::vector<int>& fids = tmp_.fids;
    rebuild_faces(hes, f, fids);
    std::vector<int>& fh = tmp_.fh;
    for (int fid : fids) {
        int pos = 0, neg = 0;
        collect_half_edges(fid, fh);
        double v;
        for (int h : fh)
            if (side_of(h, v)) { pos += v > 1e-6; neg += v < -1e-6; }
        if (pos > 0 && neg > 0) ++stats_.warnings;
        int s = decided_side(fh);
        if (s == 0) {
            Vec2 p;
            if (interior_point(fid, p)) s = g(p) > 0 ? 1 : (g(p) < 0 ? -1 : 0);
        }
        out.push_back({fid, s});
    }
}

// ---------------------------------------------------------------- inserting a source

void DomainMesh::insert(const SourceProjection& src, FaceCull cull, const Listener* L) {
    delta_ = std::max(delta_, src.delta);
    std::vector<int>& snapshot = tmp_.snapshot;
    snapshot.clear();
    for (int f : live_face_ids()) snapshot.push_back(f);
    const size_t R = src.regions.size();
    assert(R <= 7);

    // The debugger's view of a split: the pieces' ids (built only when someone listens).
    auto report_split = [&](int parent, const std::vector<SplitPiece>& pieces, const Quadratic2& curve) {
        if (!(L && L->on_split && pieces.size() > 1)) return;
        std::vector<int>& ids = tmp_.ids;
        ids.clear();
        for (const SplitPiece& pc : pieces) ids.push_back(pc.face);
        L->on_split(parent, ids, curve);
    };
    auto apply = [&](int P, const SourceRegion& reg) {
        DomainLabel lab{(int32_t)src.source, reg.kind};
        if (faces_[P].infinite) {
            DomainLabel old = faces_[P].label;
            faces_[P].poly = reg.poly; faces_[P].label = lab; faces_[P].infinite = false;
            if (L && L->on_relabel) L->on_relabel(P, old, lab);
            return;
        }
        if (same_quadratic(faces_[P].poly, reg.poly, delta_)) return;  // the existing domain keeps it (a tie)
        Quadratic2 Q = faces_[P].poly - reg.poly;                // > 0 where the source is nearer
        std::vector<SplitPiece>& pieces = tmp_.pieces;
        split_face_into(P, Q, pieces);
        report_split(P, pieces, Q);
        for (const SplitPiece& pc : pieces)
            if (pc.sign > 0) {
                DomainLabel old = faces_[pc.face].label;
                faces_[pc.face].poly = reg.poly; faces_[pc.face].label = lab;
                if (L && L->on_relabel) L->on_relabel(pc.face, old, lab);
            }
    };

    // Each region clipped to T': a face whose box misses it needs no cut for it, and a face whose
    // box lies inside it (the region is convex) needs none either. The clipped regions' boxes are
    // the same for every face, so they are taken once.
    Box2 region_box[7];
    bool region_empty[7];
    {
        std::vector<Vec2>& tri = tmp_.tri;
        tri.clear();
        for_each_half_edge(0, [&](int h) { tri.push_back(vertices_[half_[h].origin].p); });
        std::reverse(tri.begin(), tri.end());  // the outside loop runs clockwise
        for (size_t k = 0; k < R; ++k) {
            std::vector<Vec2>& P = tmp_.clipped;
            P.assign(tri.begin(), tri.end());
            clip_convex_in_place(P, src.regions[k].planes, tmp_.clip_tmp);
            region_empty[k] = P.empty();
            for (Vec2 p : P) region_box[k].add(p);
        }
    }
    auto box_misses = [&](const Box2& b, size_t k) {
        if (region_empty[k]) return true;
        const Box2& rb = region_box[k];
        const double m = 1e-9;
        return rb.hi.x < b.lo.x - m || rb.lo.x > b.hi.x + m || rb.hi.y < b.lo.y - m || rb.lo.y > b.hi.y + m;
    };
    auto box_inside = [&](const Box2& b, size_t k) {
        for (const HalfPlane& hp : src.regions[k].planes) {
            if (hp.kind == HalfPlane::All) continue;
            if (hp.kind == HalfPlane::None) return false;
            for (Vec2 c : {b.lo, b.hi, Vec2{b.lo.x, b.hi.y}, Vec2{b.hi.x, b.lo.y}})
                if (dot(hp.n, c) - hp.offset <= 1e-9) return false;
        }
        return true;
    };

    std::vector<int>& pending = tmp_.pending;
    std::vector<int>& inside = tmp_.inside;
    std::vector<int>& rest = tmp_.rest;
    std::vector<int>& cur = tmp_.cur;
    std::vector<int>& nxt = tmp_.nxt;
    std::vector<SplitPiece>& hp_pieces = tmp_.hp_pieces;
    for (int F : snapshot) {
        if (!faces_[F].alive) continue;
        if (cull && cull(F)) continue;
        pending.assign(1, F);
        for (size_t k = 0; k < R && !pending.empty(); ++k) {
            const SourceRegion& reg = src.regions[k];
            inside.clear();
            if (k + 1 == R) {
                inside.swap(pending);
            } else if (pending.size() == 1 && pending[0] == F && box_misses(cached_face_box(F), k)) {
                continue;
            } else if (pending.size() == 1 && pending[0] == F && box_inside(cached_face_box(F), k)) {
                inside.swap(pending);
            } else {
                rest.clear();
                for (int P : pending) {
                    cur.assign(1, P);
                    for (const HalfPlane& hp : reg.planes) {
                        if (hp.kind == HalfPlane::All) continue;
                        if (hp.kind == HalfPlane::None) { rest.insert(rest.end(), cur.begin(), cur.end()); cur.clear(); break; }
                        nxt.clear();
                        for (int c : cur) {
                            split_face_into(c, hp.as_quadratic(), hp_pieces);
                            report_split(c, hp_pieces, hp.as_quadratic());
                            for (const SplitPiece& pc : hp_pieces) (pc.sign > 0 ? nxt : rest).push_back(pc.face);
                        }
                        cur.swap(nxt);
                        if (cur.empty()) break;
                    }
                    inside.insert(inside.end(), cur.begin(), cur.end());
                }
                pending.swap(rest);
            }
            for (int P : inside) apply(P, reg);
        }
    }
    merge_equal_neighbours(L);
    dissolve_collinear_vertices();
}

// ---------------------------------------------------------------- maxima

double DomainMesh::edge_max(int e, const Quadratic2& q, Vec2* where) {
    const Edge& E = edges_[e];
    assert(curved_of_[e] >= 0);  // only curved arcs have interior maxima
    EdgeMax& C = curved_[curved_of_[e]].max;
    if (C.cached && std::memcmp(&C.poly, &q, sizeof q) == 0 && C.z0 == E.z0 && C.z1 == E.z1) {
        if (where) *where = C.point;
        return C.value;
    }
    double v = edge_max_uncached(e, q, where ? where : &C.point);
    C.cached = true;
    C.poly = q;
    C.z0 = E.z0;
    C.z1 = E.z1;
    C.value = v;
    if (where) C.point = *where;
    return v;
}

double DomainMesh::edge_max_uncached(int e, const Quadratic2& q, Vec2* where) const {
    const Edge& E = edges_[e];
    double z;
    double v = arc_interior_max(E.curve, E.z0, E.z1, q, &z);
    if (v == -HUGE_VAL) return v;
    Vec2 p = E.curve(z);
    polish_arc_max(q, E.equation, p);
    if (where) *where = p;
    return q(p);
}

std::vector<Candidate> DomainMesh::update_maxima() {
    std::vector<Candidate> out;
    update_maxima(out);
    return out;
}

void DomainMesh::update_maxima(std::vector<Candidate>& out) {
    out.clear();
    std::vector<double>& vval = tmp_.vval;
    vval.assign(vertices_.size(), HUGE_VAL);
    for (int fi : live_face_ids()) {
        const size_t f = (size_t)fi;
        Face& F = faces_[f];
        F.max_value = F.infinite ? HUGE_VAL : -HUGE_VAL;
        if (F.infinite) continue;
        for_each_half_edge((int)f, [&](int h) {
            int v = half_[h].origin;
            double val = F.poly(vertices_[v].p);
            F.max_value = std::max(F.max_value, val);
            vval[v] = std::min(vval[v], val);  // equal up to rounding; the smallest is the safest
        });
    }
    for (int v : live_vertex_ids())
        if (vval[v] < HUGE_VAL) out.push_back({vertices_[v].p, vval[v], v, -1});
    for (int ei : live_edge_ids()) {
        const size_t e = (size_t)ei;
        const Edge& E = edges_[e];
        if (E.curve.straight()) continue;
        int F = half_[2 * e].face, G = half_[2 * e + 1].face;
        int use = F > 0 && !faces_[F].infinite ? F : G;
        if (use <= 0 || faces_[use].infinite) continue;
        Vec2 p;
        double val = edge_max((int)e, faces_[use].poly, &p);
        if (val == -HUGE_VAL) continue;
        for (int fid : {F, G})
            if (fid > 0 && !faces_[fid].infinite) faces_[fid].max_value = std::max(faces_[fid].max_value, faces_[fid].poly(p));
        out.push_back({p, val, -1, (int)e});
    }
}

// ---------------------------------------------------------------- invariants

std::string DomainMesh::validate(double area_tol) const {
    char buf[256];
    for (size_t h = 0; h < half_.size(); ++h) {
        if (!edges_[h >> 1].alive) continue;
        const HalfEdge& H = half_[h];
        if (H.next < 0 || H.prev < 0 || half_[H.next].prev != (int)h || half_[H.prev].next != (int)h)
            return std::snprintf(buf, sizeof buf, "half-edge %zu: next/prev not inverse", h), buf;
        if (half_[H.next].origin != target((int)h))
            return std::snprintf(buf, sizeof buf, "half-edge %zu: next does not start at its target", h), buf;
        if (half_[H.next].face != H.face)
            return std::snprintf(buf, sizeof buf, "half-edge %zu: next is in another face", h), buf;
        if (H.face < 0 || !faces_[H.face].alive)
            return std::snprintf(buf, sizeof buf, "half-edge %zu: in a dead face", h), buf;
    }
    double total = 0;
    for (size_t f = 1; f < faces_.size(); ++f) {
        if (!faces_[f].alive) continue;
        double a = face_area((int)f);
        if (a < -area_tol) return std::snprintf(buf, sizeof buf, "face %zu: negative area %g", f, a), buf;
        total += a;
    }
    double target_area = -loop_area(faces_[0].loops[0]);
    if (std::fabs(total - target_area) > area_tol)
        return std::snprintf(buf, sizeof buf, "faces do not tile T': areas sum to %.15g, T' has %.15g", total, target_area), buf;
    for (size_t e = 0; e < edges_.size(); ++e) {
        const Edge& E = edges_[e];
        if (!E.alive) continue;
        for (int h : {(int)(2 * e), (int)(2 * e + 1)}) {
            Vec2 p = vertices_[half_[h].origin].p;
            double val = std::fabs(E.equation(p)), gn = norm(E.equation.gradient(p));
            if (val > 1e-7 * std::max(gn, 1e-3))
                return std::snprintf(buf, sizeof buf, "edge %zu: its curve does not vanish at vertex %d (%g)", e, half_[h].origin, val), buf;
        }
        int F = half_[2 * e].face, G = half_[2 * e + 1].face;
        if (F > 0 && G > 0 && F != G && !faces_[F].infinite && !faces_[G].infinite && same_quadratic(faces_[F].poly, faces_[G].poly, delta_))
            return std::snprintf(buf, sizeof buf, "faces %d and %d are neighbours with the same polynomial", F, G), buf;
    }
    return "";
}

}  // namespace hlens
