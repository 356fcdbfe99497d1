// Straub 2007, "Exact Computation of the Hausdorff Distance between Triangular Meshes", §3.1:
// the attributed half-edge structure holding d^2 over one target triangle, its geometric queries,
// the maxima of d^2 on it and its invariants. The insertion of a source is in domain_insert.cpp,
// the clipping primitive it uses (split a face by a curve) in domain_split.cpp. See domain_mesh.h
// and ../shared/design/algorithm.md ("The domain mesh").
#include "domain_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace hlens {

namespace {
Quadratic2 normalized(const Quadratic2& q) {
    double s = q.scale();
    return s > 0 ? q * (1.0 / s) : q;
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

DomainMesh::DomainMesh(const std::array<Vec2, 3>& P) : grown_(grown_target(P)) {
    const Vec2 c = (grown_[0] + grown_[1] + grown_[2]) / 3.0;
    for (int i = 0; i < 3; ++i) tripled_[i] = c + (grown_[i] - c) * 3.0;
    faces_.resize(2);
    faces_[0].infinite = true;  // outside T': never a domain
    for (int i = 0; i < 3; ++i) add_vertex(P[i]);
    for (int i = 0; i < 3; ++i) {
        int e = straight_edge(P[i], P[(i + 1) % 3], ArcKind::TargetBoundary);
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

bool DomainMesh::compact() {
    std::vector<int> vmap(vertices_.size(), -1), emap(edges_.size(), -1), fmap(faces_.size(), -1);
    std::vector<Vertex> V;
    std::vector<Edge> E;
    std::vector<Face> F;
    std::vector<int> curved_of;
    std::vector<CurvedArc> curved;
    V.reserve(num_live_vertices());
    E.reserve(num_live_edges());
    F.reserve(num_live_faces() + 1);
    curved_of.reserve(E.capacity());
    for (size_t v = 0; v < vertices_.size(); ++v)
        if (vertices_[v].alive) { vmap[v] = (int)V.size(); V.push_back(vertices_[v]); }
    for (size_t e = 0; e < edges_.size(); ++e) {
        if (!edges_[e].alive) continue;
        emap[e] = (int)E.size();
        E.push_back(edges_[e]);
        curved_of.push_back(curved_of_[e] < 0 ? -1 : (int)curved.size());
        if (curved_of_[e] >= 0) curved.push_back(curved_[curved_of_[e]]);
    }
    for (size_t f = 0; f < faces_.size(); ++f)
        if (faces_[f].alive || f == 0) { fmap[f] = (int)F.size(); F.push_back(faces_[f]); }
    auto hmap = [&](int h) { return h < 0 || emap[h >> 1] < 0 ? -1 : 2 * emap[h >> 1] + (h & 1); };
    std::vector<HalfEdge> H(2 * E.size());
    for (size_t e = 0; e < edges_.size(); ++e) {
        if (emap[e] < 0) continue;
        for (int k = 0; k < 2; ++k) {
            const HalfEdge& h = half_[2 * e + k];
            HalfEdge& n = H[2 * emap[e] + k];
            n = {h.origin < 0 ? -1 : vmap[h.origin], hmap(h.next), hmap(h.prev), h.face < 0 ? -1 : fmap[h.face]};
            if (n.origin < 0 || n.next < 0 || n.prev < 0 || n.face < 0) return false;
        }
    }
    for (Face& f : F)
        for (int& l : f.loops)
            if ((l = hmap(l)) < 0) return false;
    vertices_.swap(V);
    edges_.swap(E);
    half_.swap(H);
    faces_.swap(F);
    curved_of_.swap(curved_of);
    curved_.swap(curved);
    edge_alive_.assign(edges_.size(), 1);
    live_edges_.resize(edges_.size());
    for (size_t e = 0; e < edges_.size(); ++e) live_edges_[e] = (int)e;
    live_vertices_.resize(vertices_.size());
    for (size_t v = 0; v < vertices_.size(); ++v) live_vertices_[v] = (int)v;
    live_faces_.clear();
    for (size_t f = 1; f < faces_.size(); ++f) live_faces_.push_back((int)f);
    face_stamp_.assign(faces_.size(), 0);
    std::vector<uint64_t>().swap(box_stamp_);
    std::vector<Box2>().swap(box_cache_);
    return true;
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
    // The area between the arc and its chord, by quadrature on the parameter, about the arc's start
    // (the chord's own term is then 0): about the origin, the quadrature's error was relative to
    // the area swept from there, not to the segment's. (Generate_pairs13.py "closed_box" 2720,
    // side B, target 4, the debugger's construction: a hyperbola's branch 0.16 long within 7e-10 of
    // its chord, a segment of 7e-11 whose area came out off by 1e-10; the loop of a sliver and a
    // corner 4e-6 across, beside the face's side, summed to -1e-11, a hole, and the corner, where a
    // perpendicular plane is nearer by up to 1.6e-11 in d^2, was lost.)
    const Vec2 p0 = E.curve(E.z0);
    double zm = 0.5 * (E.z0 + E.z1), zr = 0.5 * (E.z1 - E.z0), seg = 0;
    for (int i = 0; i < 5; ++i)
        for (int s : {-1, 1}) {
            double z = zm + s * kGx[i] * zr;
            seg += kGw[i] * 0.5 * cross(E.curve(z) - p0, E.curve.derivative(z));
        }
    G.segment = seg * zr;
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

// Half-edge h's share of the signed area of its loop, added to `area`: the trapezoid rule's term
// of its chord, and for a curved arc the segment between the arc and its chord.
void DomainMesh::add_half_edge_area(int h, double& area) const {
    area += 0.5 * cross(vertices_[half_[h].origin].p, vertices_[target(h)].p);
    if (!edges_[h >> 1].curve.straight()) {
        const double seg = arc_geometry(h >> 1).segment;
        area += (h & 1) ? -seg : seg;
    }
}

double DomainMesh::loop_area(int start) const {
    double area = 0;
    int h = start;
    do {
        add_half_edge_area(h, area);
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
// Number of crossings of the ray {(x, p.y) : x > p.x} with the segment a-b (half-open in y, as
// every piece below: a point shared by two pieces is counted once).
int segment_crossings(Vec2 a, Vec2 b, Vec2 p) {
    if ((a.y > p.y) == (b.y > p.y)) return 0;
    return a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x ? 1 : 0;
}

// Number of crossings of the ray {(x, p.y) : x > p.x} with the arc from vertex A to vertex B, by
// y-monotone pieces (split where y turns, at `turns`). A curved arc starts at its curve's point
// c(z0), which may lie up to kFlatTip from A (a chord ended at a flat conic's tip, whose arc starts
// at the foot: domain_split.cpp), and ends at c(z1) by B: the loop is closed by the straight
// connectors A-c(z0) and c(z1)-B. Without them a ray could pass through the gap: generate_pairs.py
// "sliver" 37698, a lens 4e-10 wide along a region line whose arc started 2e-5 from its vertex
// counted a point 7e-6 off the line as inside, and validate() held the lens to d^2 there.
int ray_crossings(const RationalCurve& c, double z0, double z1, const double* turns, int nturns, Vec2 A, Vec2 B, Vec2 p) {
    if (c.straight()) return segment_crossings(A, B, p);
    double zs[10];
    size_t nz = 0;
    zs[nz++] = z0;
    for (int k = 0; k < nturns; ++k) zs[nz++] = turns[k];
    zs[nz++] = z1;
    const Vec2 c0 = c(z0), c1 = c(z1);
    int n = segment_crossings(A, c0, p) + segment_crossings(c1, B, p);
    auto pt = [&](size_t i) { return i == 0 ? c0 : (i + 1 == nz ? c1 : c(zs[i])); };
    for (size_t i = 0; i + 1 < nz; ++i) {
        Vec2 a = pt(i), b = pt(i + 1);
        if ((a.y > p.y) == (b.y > p.y)) continue;
        // y is monotone on this piece: bisect for the crossing
        double lo = zs[i], hi = zs[i + 1];
        bool up = b.y > a.y;
        for (int it = 0; it < 80; ++it) {
            double m = 0.5 * (lo + hi);
            if ((c(m).y > p.y) == up) hi = m; else lo = m;
        }
        if (c(0.5 * (lo + hi)).x > p.x) ++n;
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

bool DomainMesh::near_boundary(int f, Vec2 p, double tol, int except) const {
    bool near = false;
    for_each_half_edge(f, [&](int h) {
        if (!near && (h >> 1) != except) near = near_arc(h, p, tol);
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
        return segment_distance(p, a, b) <= tol;
    }
    const Vec2 gr = E.equation.gradient(p);
    const double ev = std::fabs(E.equation(p));
    // |grad| <= |gx| + |gy|: far off the conic without taking the root.
    if (ev > tol * ((std::fabs(gr.x) + std::fabs(gr.y)) * (1 + 1e-12))) return false;
    double gn = norm(gr);
    if (gn == 0 || ev > tol * gn) return false;
    // On the conic; on this arc if the foot lies within the arc's parameter range. Each of 16
    // cells of the parameter is searched where p lies within tol of its samples plus twice the
    // longer of the cells beside it: the parameterisation is not uniform, and where the arc
    // covers a tiny parameter range the cells' lengths differ eight-fold (a parabola's arc whose
    // first cell is 1.1e-6 long, its last 9e-6: a point 2.5e-8 off the arc lay 2e-6 from the
    // nearest sample, past tol plus the first cell's length; generate_pairs11.py
    // "crack_overlap_step" 6000).
    const double lo = std::min(E.z0, E.z1), hi = std::max(E.z0, E.z1), dz = (hi - lo) / 16.0;
    Vec2 s[17];
    for (int i = 0; i <= 16; ++i) s[i] = E.curve(lo + dz * i);
    for (int i = 0; i <= 16; ++i) {
        const double cell = std::max(i > 0 ? norm(s[i] - s[i - 1]) : 0.0, i < 16 ? norm(s[i + 1] - s[i]) : 0.0);
        if (norm(s[i] - p) <= tol + 2 * cell) {
            // refine by golden-section on |curve(z) - p| over the neighbouring cells
            const double z0 = lo + dz * i;
            double l = std::max(lo, z0 - dz), r = std::min(hi, z0 + dz);
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
        for (size_t i = 0; i < order.size() && i < 8; ++i)
            if (point_beside(f, order[i].second, -order[i].first + 1e-300, step, out)) return true;
    return false;
}

// A straight arc is the segment between its vertices (as point_in_face has it), not its line,
// which the arc's ends (polished vertices) may be off: stepped from the line's middle, a needle
// piece 2.8e-6 long and 4.2e-10 wide at its base, whose apex is 4e-10 off the line, was missed at
// every step, interior_point's fallback found a point at its short end, and the piece went to a
// region 1.8e-6 away from it (generate_pairs4.py "thin_shell_far" 37587, side A, target 0, the
// debugger's order, leftover_region). Also generate_pairs7.py "bowtie_vertex" 1274.
bool DomainMesh::point_beside(int f, int h, double len, double step, Vec2& out) const {
    const Edge& E = edges_[h >> 1];
    Vec2 m, d;
    if (E.curve.straight()) {
        const Vec2 a = vertices_[half_[h].origin].p, b = vertices_[target(h)].p;
        m = 0.5 * (a + b);
        d = b - a;
    } else {
        const double z = 0.5 * (E.z0 + E.z1);
        m = E.curve(z), d = E.curve.derivative(z);
        if (h & 1) d = -1.0 * d;
    }
    const double l = norm(d);
    if (l == 0) return false;
    const Vec2 cand = m + (step * std::min(1.0, len) / l) * perp(d);
    if (!point_in_face(f, cand)) return false;
    out = cand;
    return true;
}

int DomainMesh::face_at(Vec2 p) const {
    for (size_t f = 1; f < faces_.size(); ++f)
        if (faces_[f].alive && point_in_face((int)f, p)) return (int)f;
    return -1;
}

// ---------------------------------------------------------------- maxima

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

// How far the quadratics of faces F and G may differ at p, where their boundary lies up to `pos`
// off (to first order in their gradients, and `pos_sq` beyond), and by their rounding and the tie
// rule's slack (validate; on an arc between them, pos = max(kOffCurve, delta_), pos_sq = pos^2).
double DomainMesh::jump_allowance(int F, int G, Vec2 p, double pos, double pos_sq) const {
    const Quadratic2 &qF = faces_[F].poly, &qG = faces_[G].poly;
    const double rounding = rounding_allowance(std::max(qF.scale(), qG.scale()), delta_);
    return pos * (norm(qF.gradient(p)) + norm(qG.gradient(p))) + pos_sq + rounding + 1e-13 * (qF.scale() + qG.scale()) +
           faces_[F].tie_slack + faces_[G].tie_slack;
}

// The arc e between F and G, at its middle m, has a sliver on one side, X (F or G), narrower than
// the precision to which a split places a vertex on a curve (kOnCurve, 1e-8):
// another arc of X, to a face H, passes that close. The construction cannot tell such a sliver's
// side, and it may carry a polynomial off d^2 within its width times the gradients; d^2 is
// continuous across it if X agrees with H to that, and H with the other side, Y, as across an arc
// between them. (Generate_pairs15.py "box_union" 10323, the debugger's order: where a plane
// parallel to T' and two box edges are within 3.2e-10 of each other in d^2, the plane's domain
// kept a sliver at most 4e-10 wide along an edge's arc, where the other edge is nearer by 1.2e-10:
// a step across that arc, though the domains on either side of the sliver meet within rounding.
// A sliver 5.9e-8 wide, generate_pairs15.py 2061, is resolved instead: real_sliver_beside_chord;
// with kCluster here rather than 1e-8, its step would have passed.)
bool DomainMesh::sliver_beside_arc(int F, int G, int e, Vec2 m) const {
    const double pos = std::max(kOffCurve, delta_);
    for (int pass = 0; pass < 2; ++pass) {
        const int X = pass == 0 ? F : G, Y = pass == 0 ? G : F;
        bool explained = false;
        for_each_half_edge(X, [&](int h) {
            if (explained || (h >> 1) == e || !near_arc(h, m, kOnCurve)) return;
            const int H = half_[h ^ 1].face;
            if (H <= 0 || H == X || faces_[H].infinite) return;
            const double qH = faces_[H].poly(m);
            explained = std::fabs(faces_[X].poly(m) - qH) <= jump_allowance(X, H, m, kOnCurve, 0) &&
                        (H == Y || std::fabs(qH - faces_[Y].poly(m)) <= jump_allowance(H, Y, m, pos, pos * pos));
        });
        if (explained) return true;
    }
    return false;
}

std::string DomainMesh::validate(double area_tol) const {
    char buf[256];
    for (size_t h = 0; h < half_.size(); ++h) {
        if (!edges_[h >> 1].alive) continue;
        const HalfEdge& H = half_[h];
        if (H.next < 0 || H.prev < 0 || half_[H.next].prev != (int)h || half_[H.prev].next != (int)h)
            return std::snprintf(buf, sizeof buf, "half-edge %zu: next/prev not inverse", h), buf;
        if (!edges_[H.next >> 1].alive || !edges_[H.prev >> 1].alive)
            return std::snprintf(buf, sizeof buf, "half-edge %zu: next or prev is a removed edge's", h), buf;
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
            if (val > kOffCurve * std::max(gn, 1e-3))
                return std::snprintf(buf, sizeof buf, "edge %zu: its curve does not vanish at vertex %d (%g)", e, half_[h].origin, val), buf;
        }
        int F = half_[2 * e].face, G = half_[2 * e + 1].face;
        if (!(F > 0 && G > 0 && F != G && !faces_[F].infinite && !faces_[G].infinite)) continue;
        const Quadratic2 &qF = faces_[F].poly, &qG = faces_[G].poly;
        if (same_feature_quadratic(qF, faces_[F].label.region, qG, faces_[G].label.region, delta_))
            return std::snprintf(buf, sizeof buf, "faces %d and %d are neighbours with the same polynomial", F, G), buf;
        // d^2 is continuous: across an arc the two domains' quadratics agree, up to the arc lying
        // kOffCurve off where they meet, or a sliver that narrow dropped between them (where a
        // third feature was nearer: to first order in the two gradients, to second in that
        // feature's curvature, at most 1 in frame units for an edge or a corner region), and
        // their rounding. A missing piece of the envelope wider than that shows as a jump
        // (degenerate pair "mirror" 11642: an edge's sliver 3.5e-6 wide, and the maximum with it).
        // Where the tie rule kept one of two quadratics within its allowance, d^2 may step by
        // their difference (Face::tie_slack; generate_pairs.py "crossing" 11707: two face regions
        // 3e-12 apart merged, a step of 2.6e-12 against the other's edge region).
        // Where the sources' corners lie so far from T' (in units of its size) that their frame
        // coordinates' rounding, delta_, exceeds kOffCurve, the region lines and the quadratics'
        // zero sets are only that precise, and delta_ takes its place: a target 1.4e-11 long on
        // the edge of a source of size 3 (reach 2e11, delta_ 0.003) has the edge's quadratic
        // 7.8e-11 above 0 on the region line as computed ("mixed_scale" pairs of a third
        // generator), far below any distance its coordinates can express.
        // The quadratics' own values are as precise as the tie rule's absolute allowance says (a
        // height h off by delta_ puts h^2 off by 2 h delta_ + delta_^2): a constant plane quadratic
        // and an edge's, from corners 4e4 from the frame's origin (a target 1e-5 over a coplanar
        // strip of size 1, generate_pairs3.py "mixed_scale" 4698), differed by 2.2e-12 on their
        // shared region line, where d^2 is 0.41 and has no gradient.
        const Vec2 m = E.curve(0.5 * (E.z0 + E.z1));
        const double jump = std::fabs(qF(m) - qG(m));
        const double pos = std::max(kOffCurve, delta_);
        const double tol = jump_allowance(F, G, m, pos, pos * pos);
        // Nor where another arc of F or G passes within kTinyChord of m: there one of them is a
        // sliver thinner than a chord the splits insert (find_chords), which stays on the side of
        // the rest of its face, whatever its polynomial (as a face that thin as a whole,
        // TargetSolver::validate). Generate_pairs3.py "sliver" 11734, the paper's order: a needle's
        // corner region, a wedge 5e-7 wide per unit, crossed by another needle's region line where
        // it was 3e-12 wide; the wedge's tip below the line, 5.4e-6 long, kept the edge region
        // above, d^2 7e-12 by its polynomial beside 0 (the needle lies in T''s plane).
        if (jump > tol && !near_boundary(F, m, kTinyChord, (int)e) && !near_boundary(G, m, kTinyChord, (int)e) &&
            !sliver_beside_arc(F, G, (int)e, m))
            return std::snprintf(buf, sizeof buf, "faces %d and %d: d^2 jumps by %g across edge %zu (%g and %g)", F, G, jump, e,
                                 qF(m), qG(m)), buf;
    }
    return "";
}

}  // namespace hlens