// Straub 2007 §3.1, the insertion of a source triangle into the domain mesh: d^2 := min(d^2,
// d_T^2). Each domain the source reaches is clipped by the source's regions (half-planes) and by
// the conic q_domain - q_region = 0 (the clipping primitive, domain_split.cpp); the side where the
// source is nearer takes its quadratic and label. Then neighbouring domains whose quadratics are
// equal are merged and collinear vertices dissolved. See domain_mesh.h and
// ../shared/design/algorithm.md ("The domain mesh").
#include "domain_mesh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <optional>

namespace hlens {

// A face whose box `b` misses region k's box (clipped to T'; or nothing of it is left) needs no
// cut for it.
bool DomainMesh::region_box_misses(const Box2& b, const RegionBoxes& boxes, size_t k) {
    if (boxes.empty[k]) return true;
    const Box2& rb = boxes.box[k];
    const double m = 1e-9;
    return rb.hi.x < b.lo.x - m || rb.lo.x > b.hi.x + m || rb.hi.y < b.lo.y - m || rb.lo.y > b.hi.y + m;
}
// Nor does a face whose box lies inside the region (the region is convex).
bool DomainMesh::region_box_inside(const Box2& b, const SourceRegion& reg) {
    for (const HalfPlane& hp : reg.planes) {
        if (hp.kind == HalfPlane::All) continue;
        if (hp.kind == HalfPlane::None) return false;
        for (Vec2 c : {b.lo, b.hi, Vec2{b.lo.x, b.hi.y}, Vec2{b.hi.x, b.lo.y}})
            if (dot(hp.n, c) - hp.offset <= 1e-9) return false;
    }
    return true;
}

// ---------------------------------------------------------------- inserting a source

bool DomainMesh::insert(const SourceProjection& src, FaceCull cull, const Listener* L) {
    std::optional<PlainBisection> plain;  // watched: the paper's insertion, its roots to the bit
    if (L) plain.emplace();
    // Merging looks only at edges beside a face this insertion touched: the others' neighbours
    // were unequal after the last merging, unless the tie rule's allowance has grown.
    const bool grew = src.delta > delta_;
    const uint64_t since = grew ? 0 : clock_;
    delta_ = std::max(delta_, src.delta);
    std::vector<int>& snapshot = tmp_.snapshot;
    snapshot.clear();
    for (int f : live_face_ids()) snapshot.push_back(f);
    assert(src.regions.size() <= 7);
    RegionBoxes boxes;
    bool clipped = false;  // the regions are clipped to T' when a face first needs them
    const size_t nv = vertices_.size(), ne = edges_.size();
    const long nr = relabels_;
    for (int F : snapshot) {
        if (!faces_[F].alive) continue;
        if (cull && cull(F)) continue;
        if (!clipped) clip_regions_to_target(src, boxes), clipped = true;
        // Someone watches every cut (the debugger): the paper's insertion. Otherwise only the
        // regions that may be nearer (domain_reach.cpp): the same d^2, without the cuts the
        // merging would undo; but the paper's insertion where a region thinner than kCluster
        // reaches F (thin_region_reaches).
        if (L || thin_region_reaches(F, src, boxes)) insert_into_face(F, src, boxes, L);
        else insert_where_nearer(F, src, boxes);
    }
    // Nothing cut, nothing relabelled: the mesh is as the last insertion left it, merged, unless
    // the larger allowance (a source farther from the frame's origin) makes neighbours that were
    // not ties before ties now: then every edge is compared (since = 0; Degenerate.LargerTieAllowance...).
    const bool unchanged = !L && vertices_.size() == nv && edges_.size() == ne && relabels_ == nr;
    if (unchanged && !grew) return false;
    detach_orphan_loops(since, L);
    if (!merge_equal_neighbours(L, since) && unchanged) return false;
    dissolve_collinear_vertices();
    if (unfold_needles(since)) {  // on whole arcs, the collinear vertices along them dissolved
        merge_equal_neighbours(L, since);
        dissolve_collinear_vertices();
    }
    return true;
}

// Each region clipped to T': a face whose box misses it needs no cut for it, and a face whose box
// lies inside it (the region is convex) needs none either. The clipped regions' boxes are the same
// for every face, so they are taken once.
// T' (its corners P, counter-clockwise) with its edges moved out by kCluster: a chord's end may
// stand that far beyond them (the domain mesh's resolution), and a region that meets T' along an
// edge alone (a coplanar source's edge region on T''s edge: clipped to T', its box one corner of
// T', by rounding) must still reach the faces that poke out there. (Generate_pairs6.py
// "stacked_layers_far" 609, side A, target 5, nearest first: a corner of a face 1.6e-7 beyond
// T''s corner, where a coplanar source's edge is 2e-7 off, kept a layer 6e-5 away, d^2 3.3e-9
// beside 1e-19.) Taken once, by the constructor.
std::array<Vec2, 3> DomainMesh::grown_target(const std::array<Vec2, 3>& P) {
    std::array<Vec2, 3> corner;
    for (int i = 0; i < 3; ++i) {
        const Vec2 a = P[(i + 2) % 3], b = P[i], c = P[(i + 1) % 3];
        const Vec2 u = (b - a) / norm(b - a), v = (c - b) / norm(c - b);  // edges into and out of b
        const double sine = cross(u, v);  // > 0: T' is counter-clockwise
        // b moved out by kCluster from both edges: b + kCluster (n_u + n_v) / (1 + n_u . n_v),
        // n the outward normals; at a needle's tip, no farther than 1000 kCluster.
        const Vec2 nu{u.y, -u.x}, nv{v.y, -v.x};
        const Vec2 shift = (kCluster / std::max(1 + dot(nu, nv), 1e-6)) * (nu + nv);
        corner[i] = sine > 0 ? b + std::min(1.0, 1e3 * kCluster / norm(shift)) * shift : b;
    }
    return corner;
}

// Whether a region of the source thinner than kCluster in itself (RegionBoxes::thin) may reach face
// F. A cut by such a region's lines leaves a sliver of it that the cut by its other line drops as
// hugging the boundary; the paper's insertion then cuts it off by the neighbouring region's cut
// along the same line, which the lean insertion passes over as nowhere nearer, and the sliver kept
// the old source. (Generate_pairs9.py "perp_corner_tiny" 6680, B's target 1, the paper's order,
// the 5th insertion: a source 3e-8 across standing on T', its edge region a strip 3.7e-8 wide; a
// cut by its corner region left a sliver of the strip 1.8e-8 to 3.7e-8 wide and 7e-4 long joined
// to the passed-over corner region on its other side, and the sliver kept a source 3% above d^2.)
// Such sources are tiny or stand on T', rare on real meshes: the lean insertion's savings stay.
bool DomainMesh::thin_region_reaches(int F, const SourceProjection& src, const RegionBoxes& boxes) {
    for (size_t k = 0; k < src.regions.size(); ++k)
        if (boxes.thin[k] && !region_box_misses(cached_face_box(F), boxes, k)) return true;
    return false;
}

void DomainMesh::clip_regions_to_target(const SourceProjection& src, RegionBoxes& out) {
    // T' grown by kCluster (grown_target): the points its boundary gained since lie between its
    // corners.
    for (size_t k = 0; k < src.regions.size(); ++k) {
        std::vector<Vec2>& P = tmp_.clipped;
        P.assign(grown_.begin(), grown_.end());
        clip_convex_in_place(P, src.regions[k].planes, tmp_.clip_tmp);
        out.empty[k] = P.empty();
        for (Vec2 p : P) out.box[k].add(p);
        if (P.empty()) continue;
        // Thin in itself (thin_region_reaches): its area clipped to T' grown three times about its
        // centre at most kCluster times its size there; not a region that meets T' along an edge
        // only (a neighbour of a coincident source), which is most of them on near-copies.
        P.assign(tripled_.begin(), tripled_.end());
        clip_convex_in_place(P, src.regions[k].planes, tmp_.clip_tmp);
        Box2 b;
        double a = 0;
        for (size_t i = 0; i < P.size(); ++i) a += cross(P[i], P[(i + 1) % P.size()]), b.add(P[i]);
        out.thin[k] = P.size() < 3 || 0.5 * std::fabs(a) <= kCluster * norm(b.hi - b.lo);
    }
}

// Face F (alive when the insertion began) cut by the regions in turn: the pieces inside region k
// take its quadratic where the source is nearer (apply_region), the rest go on to region k + 1.
// The last region takes what is left (the regions tile the plane), but for a piece wholly outside
// it that a dropped chord left (leftover_region).
void DomainMesh::insert_into_face(int F, const SourceProjection& src, const RegionBoxes& boxes, const Listener* L) {
    const size_t R = src.regions.size();
    std::vector<int>& pending = tmp_.pending;
    std::vector<int>& inside = tmp_.inside;
    pending.assign(1, F);
    for (size_t k = 0; k < R && !pending.empty(); ++k) {
        const SourceRegion& reg = src.regions[k];
        inside.clear();
        if (k + 1 == R) {
            inside.swap(pending);
        } else if (pending.size() == 1 && pending[0] == F && region_box_misses(cached_face_box(F), boxes, k)) {
            continue;
        } else if (pending.size() == 1 && pending[0] == F && region_box_inside(cached_face_box(F), reg)) {
            inside.swap(pending);
        } else {
            cut_by_region(reg, L);
        }
        for (int P : inside) apply_region(P, src, k + 1 == R ? src.regions[leftover_region(P, src, ~0u, R - 1)] : reg, L);
    }
}

// The faces of tmp_.pending cut by the half-planes of `reg`: the pieces inside it go to
// tmp_.inside, the others become tmp_.pending.
void DomainMesh::cut_by_region(const SourceRegion& reg, const Listener* L) {
    std::vector<int>& pending = tmp_.pending;
    std::vector<int>& inside = tmp_.inside;
    std::vector<int>& rest = tmp_.rest;
    std::vector<int>& cur = tmp_.cur;
    std::vector<int>& nxt = tmp_.nxt;
    std::vector<SplitPiece>& hp_pieces = tmp_.hp_pieces;
    rest.clear();
    for (int P : pending) {
        cur.assign(1, P);
        for (const HalfPlane& hp : reg.planes) {
            if (hp.kind == HalfPlane::All) continue;
            if (hp.kind == HalfPlane::None) { rest.insert(rest.end(), cur.begin(), cur.end()); cur.clear(); break; }
            nxt.clear();
            for (int c : cur) {
                split_face_into(c, hp.as_quadratic(), hp_pieces);
                report_split(L, c, hp_pieces, hp.as_quadratic());
                for (const SplitPiece& pc : hp_pieces) (pc.sign > 0 ? nxt : rest).push_back(pc.face);
            }
            cur.swap(nxt);
            if (cur.empty()) break;
        }
        inside.insert(inside.end(), cur.begin(), cur.end());
    }
    pending.swap(rest);
}

// Face P lies in region `reg`: where the source is nearer (the conic's positive side), d^2 becomes
// the region's quadratic.
void DomainMesh::apply_region(int P, const SourceProjection& src, const SourceRegion& reg, const Listener* L) {
    if (faces_[P].infinite) {
        give_to_region(P, src, reg, L);
        return;
    }
    if (same_feature_quadratic(faces_[P].poly, faces_[P].label.region, reg.poly, reg.kind, delta_)) {  // the existing domain keeps it (a tie)
        note_tie(P, reg.poly);
        return;
    }
    std::vector<SplitPiece>& pieces = tmp_.pieces;
    const Quadratic2 Q = split_where_below(P, reg.poly, pieces);  // Q > 0 where the source is nearer
    report_split(L, P, pieces, Q);
    for (const SplitPiece& pc : pieces)
        if (pc.sign > 0) give_to_region(pc.face, src, reg, L);
}

// Face P takes the region's quadratic and label (counted and stamped: insert asks whether
// anything changed, merging which faces did). It keeps P's tie slack: the region won where it is
// below P's quadratic, which the tie rule may have kept up to that slack above d^2 (a third
// feature, tied with it, nearer), so the winner is only that close to d^2 too. Generate_pairs4.py
// "thin_shell_far" 17833, nearest first: an edge's domain kept where another edge, 2e-12 nearer in
// d^2 (7.8e-10), tied with it; a vertex region then won a piece of it and, its slack cleared,
// was 1e-12 above d^2 there, past what validate() allowed the new domain.
void DomainMesh::give_to_region(int P, const SourceProjection& src, const SourceRegion& reg, const Listener* L) {
    const DomainLabel old = faces_[P].label, lab{(int32_t)src.source, reg.kind};
    faces_[P].poly = reg.poly;
    faces_[P].label = lab;
    faces_[P].infinite = false;
    ++relabels_;
    touch_face(P);
    if (L && L->on_relabel) L->on_relabel(P, old, lab);
}

// ---------------------------------------------------------------- folded needles
//
// A face's loop may run out along one straight arc and back along another that lies on the far
// side of the first: a needle of the face turned inside out, thinner than the resolution, which
// the face covers negatively and its two neighbours across those arcs both cover. Two region lines
// crossing at a small angle, each cut within the vertex tolerance of where it is, leave one
// (generate_pairs4.py "lod_surface" 28934, nearest first, side B, target 7: three near-coplanar
// sources' lines crossing 5e-5 rad apart; the face went 3.4e-6 down one line and back up the
// other, 2e-10 beside it, and across those arcs its quadratic, undercut there by the neighbours'
// source by up to 4.6e-11, met theirs with a step of 2.3e-11 at d^2 1.2e-6). The areas still sum
// to T''s, so only the continuity of d^2 across the arcs shows it (generate_pairs5.py
// "coinc_retess_far" 15803 too: a needle 1.3e-5 long and 1.2e-9 wide, a step of 3.6e-10 at d^2
// 1.6e-5). Unfolded: the face's loop takes the short straight chord across the needle's base
// instead, and the needle goes to the neighbour on one side (the one whose quadratic is lower at
// its middle), which then keeps it, the other neighbour's loop running round it. What is left at
// the base, where the lines and the chord meet within the needle's width, is below the resolution
// (a cluster of boundaries within kVertexTolerance of one point). Needles shorter than 8 times
// that, or with a curved side, are left as they are.
bool DomainMesh::unfold_needles(uint64_t since) {
    bool any = false;
    std::vector<int> faces = live_face_ids();
    for (int f : faces) {
        if (since > 0 && !((size_t)f < face_stamp_.size() && face_stamp_[f] > since)) continue;
        for (int rounds = 0, again = 1; again && rounds < 16 && faces_[f].alive; ++rounds) {
            again = 0;
            for (size_t l = 0; l < faces_[f].loops.size() && !again; ++l) {
                const int start = faces_[f].loops[l];
                int h = start, guard = 0;
                do {
                    if (unfold_at(f, h)) { again = 1, any = true; break; }
                    h = half_[h].next;
                } while (h != start && ++guard < 1000000);
            }
        }
    }
    return any;
}

// Arc e is straight, or curved off its chord by less than a tenth of the vertex tolerance: a
// piece of a conic that is one line to the domain mesh's resolution, such as the double line where
// an edge's quadratic meets a coplanar face's 0.
bool DomainMesh::nearly_straight(int e) const {
    const Edge& E = edges_[e];
    if (E.curve.straight()) return true;
    const double chord = norm(E.curve(E.z1) - E.curve(E.z0));
    return chord > 0 && 1.5 * std::fabs(arc_geometry(e).segment) <= 0.1 * kVertexTolerance * chord;
}

// An arc no longer than the needle width: the blunt tip of a needle whose two straight sides end
// on a curve that crosses both within the resolution.
bool DomainMesh::tiny_arc(int h) const {
    const Vec2 p = vertices_[half_[h].origin].p;
    return norm(vertices_[target(h)].p - p) <= kVertexTolerance && norm(he_point(h, 0.5) - p) <= kVertexTolerance;
}

// The folded needle of face f ending with half-edge h (to w), if there is one: unfolded
// (unfold_needles). True if it was. Its tip is h's origin v, or a tiny arc from v1 to v before h
// (generate_pairs16.py "fillet_strip" 4121, the debugger's order, B's target 22: two region lines
// through a source corner, 6e-4 rad apart, ran 2.8e-6 down to a conic that crossed both 3.7e-9
// apart; the face between them was folded there and met its neighbours with a step of 1.5e-11,
// 2% of d^2).
bool DomainMesh::unfold_at(int f, int h) {
    int b = h, tip = tiny_arc(half_[h].prev) ? half_[h].prev : -1, a = half_[tip >= 0 ? tip : b].prev;
    if (!nearly_straight(a >> 1) || !nearly_straight(b >> 1) || (a >> 1) == (b >> 1) || half_[b].next == a ||
        (tip >= 0 && ((tip >> 1) == (a >> 1) || (tip >> 1) == (b >> 1))) ||
        half_[a].origin == target(b))  // both arcs between the same two vertices: no base to cut
        return false;
    const ArcKind kind = edges_[a >> 1].kind;  // the chord across the base is of that kind
    const Vec2 pu = vertices_[half_[a].origin].p, p1 = vertices_[target(a)].p, p2 = vertices_[half_[b].origin].p,
               pw = vertices_[target(b)].p;
    const Vec2 du = pu - p1, dw = pw - p2;
    const double lu = norm(du), lw = norm(dw);
    if (!(lu > 0 && lw > 0) || dot(du, dw) <= 0) return false;
    // The face lies left of its arcs: where the needle between a and b lies outside it, the cycle
    // u, v1, v, w turns clockwise (a vertex tip: its angle at v is nearly a full turn).
    const double twice_area = cross(p1 - pu, p2 - pu) + cross(p2 - pu, pw - pu);
    const double length = std::min(lu, lw), width = -twice_area / std::max(lu, lw);
    if (!(twice_area < 0 && width <= kVertexTolerance && length >= 8 * kVertexTolerance)) return false;
    // A side may be T''s edge (B or A is 0, outside T'): the needle lies outside T' then, and the
    // face beside it inside gives it up (target 33 of 4121: a region line 3.6e-9 outside T''s edge).
    const int A = half_[a ^ 1].face, B = half_[b ^ 1].face;
    if (A < 0 || B < 0 || A + B == 0 || A == f || B == f || !faces_[A].alive || !faces_[B].alive) return false;
    const Vec2 axis = (du / lu + dw / lw) / norm(du / lu + dw / lw), mid = 0.5 * (p1 + p2) + axis * (0.5 * length);
    auto q = [&](int F) { return faces_[F].infinite ? HUGE_VAL : faces_[F].poly(mid); };  // F > 0 here
    // The neighbour that gives the needle up (the one whose quadratic is higher at its middle; one
    // neighbour all round: that one): its twins of the needle's arcs must be one run of its loop.
    const int loser = A == B ? A : A == 0 ? B : B == 0 ? A : q(A) <= q(B) ? B : A;
    std::array<int, 4> cycle{};  // f's arcs of the needle, then the chord's half in the loser
    int n = 0;
    cycle[n++] = a;
    if (tip >= 0) cycle[n++] = tip;
    cycle[n++] = b;
    cycle[n++] = -1;
    int first = -1, last = -1;
    for (int i = 0; i + 1 < n; ++i)
        if (half_[cycle[i] ^ 1].face == loser) last = i, first = first < 0 ? i : first;
    assert(first >= 0);  // the loser is a's or b's neighbour
    if (half_[cycle[last] ^ 1].prev == (cycle[first] ^ 1)) return false;  // its loop is more than the run
    for (int i = first; i < last; ++i)
        if (half_[cycle[i] ^ 1].face != loser || half_[cycle[i + 1] ^ 1].next != (cycle[i] ^ 1)) return false;
    // The longer arc split at the foot of the shorter one's end, unless that is its own end. A
    // foot past the longer arc's end, where the two ends lie within kVertexTolerance of each
    // other, is that end: the arc's line runs by its vertex within kOffCurve, so the foot of a
    // point beside that vertex may fall past it. (Generate_pairs5.py "coinc_noise_far" 58438, the
    // debugger's order: a needle 1.26e-5 long and 2.2e-9 wide, its sides 1.5e-9 apart in length,
    // the foot 3e-10 past the end; left folded, a later source's region line along the needle
    // pinched its base, no piece was cut, and the face kept an edge's quadratic 5% above d^2.)
    if (std::fabs(lu - lw) > kTinyChord) {
        const int e = lu < lw ? (b >> 1) : (a >> 1);
        if (!edges_[e].curve.straight()) return false;
        const Vec2 end = lu < lw ? pu : pw;  // the shorter arc's end, whose foot splits the longer
        const double z = straight_foot(e, end);
        if (z > edges_[e].z0 && z < edges_[e].z1) {
            split_edge(e, z);  // the arcs at the tip: the longer one cut, the piece there kept
            if (lu < lw) b = cycle[n - 2] = half_[cycle[n - 3]].next;
            else a = cycle[0] = half_[cycle[1]].prev;
        } else if (!(norm(end - (lu < lw ? pw : pu)) <= kVertexTolerance)) {
            return false;
        }
    }
    cut_needle_base(f, cycle, n, first, last, loser, kind);
    touch_face(f);
    for (int F : {A, B})
        if (F > 0) touch_face(F);
    ++stats_.unfolds;
    return true;
}

// Face f's needle, its arcs cycle[0..n-2] (f's halves, in its loop), unfolded: f takes the chord
// x -> y across the base; the loser's run of their twins, from the twin of cycle[last] to that of
// cycle[first], becomes the rest of the cycle that the chord's other half y -> x closes:
// cycle[last + 1], ..., c1, cycle[0], ..., cycle[first - 1]. The run's arcs go, and the vertices
// inside it.
void DomainMesh::cut_needle_base(int f, std::array<int, 4>& cycle, int n, int first, int last, int loser, ArcKind kind) {
    const int a = cycle[0], b = cycle[n - 2], x = half_[a].origin, y = target(b);
    const Vec2 px = vertices_[x].p, py = vertices_[y].p;
    const int c = add_edge(segment_curve(px, py), 0, 1, line_through(px, py), kind, CurveKind::Line);
    const int c0 = 2 * c, c1 = 2 * c + 1;  // x -> y in f; y -> x in the loser
    cycle[n - 1] = c1;
    auto link = [&](int p, int q) { half_[p].next = q; half_[q].prev = p; };
    half_[c0].origin = x, half_[c1].origin = y;
    half_[c0].face = f;
    link(half_[a].prev, c0), link(c0, half_[b].next);
    for (int& l : faces_[f].loops)
        for (int i = 0; i + 1 < n; ++i)
            if (l == cycle[i]) l = c0;
    const int before = half_[cycle[last] ^ 1].prev, after = half_[cycle[first] ^ 1].next;
    int p = before;
    for (int k = 1; k < n - (last - first); ++k) {
        const int q = cycle[(last + k) % n];
        half_[q].face = loser;
        link(p, q), p = q;
    }
    link(p, after);
    for (int& l : faces_[loser].loops)
        for (int i = first; i <= last; ++i)
            if (l == (cycle[i] ^ 1)) l = cycle[(last + 1) % n];
    for (int i = first; i <= last; ++i) {
        if (i < last) vertices_[target(cycle[i])].alive = false;
        drop_edge(cycle[i] >> 1);
    }
}

// The debugger's view of a split: the pieces' ids (built only when someone listens).
void DomainMesh::report_split(const Listener* L, int parent, const std::vector<SplitPiece>& pieces, const Quadratic2& curve) {
    if (!(L && L->on_split && pieces.size() > 1)) return;
    std::vector<int>& ids = tmp_.ids;
    ids.clear();
    for (const SplitPiece& pc : pieces) ids.push_back(pc.face);
    L->on_split(parent, ids, curve);
}

// ---------------------------------------------------------------- merging and dissolving

// An edge may be a loop: a chord between the two feet of one vertex at a thin conic's hairpin
// (add_chords_of_component) runs from that vertex round the hairpin's tip and back, one arc whose
// inner side is a cycle of itself alone (its next is itself). Removing it splices only the outer
// side, and its vertex stays (generate_pairs4.py "f32_export" 15711, target 21 in the paper's
// order: the general splice linked a live half-edge to the removed loop, and the next split
// walked a face's loop forever).
void DomainMesh::remove_edge(int e) {
    touch_edge_faces(e);
    int h = 2 * e, t = 2 * e + 1;
    int hn = half_[h].next, hp = half_[h].prev, tn = half_[t].next, tp = half_[t].prev;
    const bool loop = half_[h].origin == half_[t].origin;
    if ((hn == t || hn == h) && (tn == h || tn == t)) {
        vertices_[half_[h].origin].alive = false;
        vertices_[half_[t].origin].alive = false;
    } else if (hn == t) {  // target of h is the tip of a dangling edge
        half_[hp].next = tn; half_[tn].prev = hp;
        if (!loop) vertices_[half_[t].origin].alive = false;
    } else if (tn == h) {
        half_[tp].next = hn; half_[hn].prev = tp;
        if (!loop) vertices_[half_[h].origin].alive = false;
    } else if (tn == t) {  // a loop whose inner side is itself alone
        half_[hp].next = hn; half_[hn].prev = hp;
    } else if (hn == h) {
        half_[tp].next = tn; half_[tn].prev = tp;
    } else {
        half_[hp].next = tn; half_[tn].prev = hp;
        half_[tp].next = hn; half_[hn].prev = tp;
    }
    drop_edge(e);
}

void DomainMesh::drop_edge(int e) {
    edges_[e].alive = false;
    edge_alive_[e] = 0;
    half_[2 * e].face = half_[2 * e + 1].face = -1;
}

// A loop of a face that its outer loop does not enclose, of no area (a spike: two vertices 7e-7
// apart and a third on the first), is left over where many boundaries meet at a sliver source's
// corner: rebuild_faces gives such a cycle, a "hole" in no outer loop, to the first face it
// builds, which then touched its neighbours along arcs where d^2 differed by 0.07 (independent
// pairs 1682 and 3330: a coplanar needle's tip). It belongs to no face's interior: it becomes a
// face of its own, with the quadratic and label of the face across its longest arc, and the
// merging joins the two (the listener sees it created, relabelled from the face it left, then
// merged). True if one was found.
bool DomainMesh::detach_orphan_loops(uint64_t since, const Listener* L) {
    bool any = false;
    const size_t n = faces_.size();
    for (size_t f = 1; f < n; ++f) {
        if (!faces_[f].alive || faces_[f].infinite || faces_[f].loops.size() < 2) continue;
        if (since > 0 && !((size_t)f < face_stamp_.size() && face_stamp_[f] > since)) continue;
        for (size_t k = 1; k < faces_[f].loops.size(); ++k) {
            const int h0 = faces_[f].loops[k];
            if (std::fabs(loop_area(h0)) > kCluster * kCluster) continue;
            const Edge& E0 = edges_[h0 >> 1];
            if (loop_crossings(faces_[f].loops[0], E0.curve(0.5 * (E0.z0 + E0.z1))) & 1) continue;  // inside: a hole
            int first, second;
            if (split_orphan_at_waist((int)f, h0, first, second)) {  // each part in turn, this one first
                faces_[f].loops[k] = first;
                faces_[f].loops.push_back(second);
                --k;
                continue;
            }
            std::vector<int> hs;
            int h = h0;
            do { hs.push_back(h); h = half_[h].next; } while (h != h0);
            const int across = face_across_longest((int)f, hs, 0, (int)hs.size());
            if (across < 0) continue;
            Face piece = faces_[across];
            piece.loops.assign(1, h0);
            faces_.push_back(piece);
            const int id = (int)faces_.size() - 1;
            live_faces_.push_back(id);
            h = h0;
            do { half_[h].face = id; h = half_[h].next; } while (h != h0);
            faces_[f].loops.erase(faces_[f].loops.begin() + (long)k);
            --k;
            touch_face(id);
            touch_face((int)f);
            ++stats_.warnings;
            any = true;
            if (L && L->on_relabel) L->on_relabel(id, faces_[f].label, faces_[id].label);
        }
    }
    return any;
}

// The live finite face other than f across half-edge he; -1 if there is none.
int DomainMesh::finite_face_across(int f, int he) const {
    const int g = half_[he ^ 1].face;
    return g > 0 && g != f && faces_[g].alive && !faces_[g].infinite ? g : -1;
}

// finite_face_across the longest of the arcs hs[i], ..., hs[i + cnt - 1] that have one (indices
// modulo hs.size()), the first of equals; -1 if none has.
int DomainMesh::face_across_longest(int f, const std::vector<int>& hs, int i, int cnt) const {
    const int n = (int)hs.size();
    int best = -1;
    double len = -1;
    for (int k = 0; k < cnt; ++k) {
        const int he = hs[(i + k) % n], g = finite_face_across(f, he);
        const double l = norm(vertices_[target(he)].p - vertices_[half_[he].origin].p);
        if (g >= 0 && l > len) len = l, best = g;
    }
    return best;
}

// An orphan loop may be two needles joined at a waist where an earlier cut's curve crossed it, each
// beside domains of its own: given whole to the face across its longest arc, d^2 steps along the
// other needle's arcs. (Generate_pairs4.py "lod_surface" 21658, side B, target 3, the debugger's
// order: two near-coplanar sources' region lines, through one vertex and 2e-15 apart 7.9e-6 from
// it, bound an inside-out needle 1e-10 wide; a conic crossed it where it was 6e-11 wide, and the
// part beyond, given to the far side's domain, stepped d^2 by 3.3e-11 at 2.8e-6 along 4e-6.) It is
// cut at two of its vertices within kCluster of each other, each part keeping two arcs or more,
// where the parts' faces across their longest arcs differ and the step at the arcs' middles (the
// loop's quadratic against the face across) is at most half the whole loop's, the least there is,
// and each part is of no area either. True if it was: `first` and `second` are half-edges of the
// two loops.
bool DomainMesh::split_orphan_at_waist(int f, int h0, int& first, int& second) {
    std::vector<int> hs;
    int h = h0;
    do { hs.push_back(h); h = half_[h].next; } while (h != h0 && hs.size() <= 64);
    const int n = (int)hs.size();
    if (h != h0 || n < 4) return false;
    auto longest = [&](int i, int cnt) { return face_across_longest(f, hs, i, cnt); };
    auto step = [&](int i, int cnt, int g) {  // the largest step of d^2 at those arcs' middles, g's quadratic inside
        double s = 0;
        for (int k = 0; k < cnt; ++k) {
            const int he = hs[(i + k) % n], a = finite_face_across(f, he);
            if (a < 0) continue;
            const Edge& E = edges_[he >> 1];
            const Vec2 m = E.curve(0.5 * (E.z0 + E.z1));
            s = std::max(s, std::fabs(faces_[g].poly(m) - faces_[a].poly(m)));
        }
        return s;
    };
    const int whole = longest(0, n);
    if (whole < 0) return false;
    double best = 0.5 * step(0, n, whole);
    int bi = -1, bj = -1;
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n && n - (j - i) >= 2; ++j) {
            const int a = half_[hs[i]].origin, b = half_[hs[j]].origin;
            if (a == b || !(norm(vertices_[a].p - vertices_[b].p) <= kCluster)) continue;
            const int g1 = longest(i, j - i), g2 = longest(j, n - (j - i));
            if (g1 < 0 || g2 < 0 ||
                same_feature_quadratic(faces_[g1].poly, faces_[g1].label.region, faces_[g2].poly, faces_[g2].label.region, delta_))
                continue;
            const double s = std::max(step(i, j - i, g1), step(j, n - (j - i), g2));
            if (s < best) best = s, bi = i, bj = j;
        }
    if (bi < 0) return false;
    const int a = half_[hs[bi]].origin, b = half_[hs[bj]].origin;
    const Vec2 pa = vertices_[a].p, pb = vertices_[b].p;
    const int c = add_edge(segment_curve(pa, pb), 0, 1, line_through(pa, pb), ArcKind::Conic, CurveKind::Line);
    const int c0 = 2 * c, c1 = 2 * c + 1;  // a -> b closes hs[bj], ...; b -> a closes hs[bi], ...
    auto link = [&](int p, int q) { half_[p].next = q; half_[q].prev = p; };
    half_[c0].origin = a, half_[c1].origin = b;
    half_[c0].face = half_[c1].face = f;
    link(hs[bj - 1], c1), link(c1, hs[bi]);
    link(hs[(bi + n - 1) % n], c0), link(c0, hs[bj]);
    first = hs[bi], second = hs[bj];
    if (std::fabs(loop_area(first)) <= kCluster * kCluster && std::fabs(loop_area(second)) <= kCluster * kCluster) return true;
    link(hs[bj - 1], hs[bj]), link(hs[(bi + n - 1) % n], hs[bi]);  // a part with area: not two needles
    drop_edge(c);
    return false;
}

bool DomainMesh::merge_equal_neighbours(const Listener* L, uint64_t since) {
    auto touched = [&](int f) { return (size_t)f < face_stamp_.size() && face_stamp_[f] > since; };
    bool changed = true, any = false;
    // Each pass removes at least one edge, so there are at most as many passes as edges.
    for (size_t pass = 0; changed && pass <= edges_.size(); ++pass) {
        changed = false;
        const std::vector<int>& live_edges = live_edge_ids();  // no edge is added while merging
        for (size_t i = 0; i < live_edges.size(); ++i) {
            const size_t e = (size_t)live_edges[i];
            if (!edge_alive_[e]) continue;
            int F = half_[2 * e].face, G = half_[2 * e + 1].face;
            if (F <= 0 || G <= 0) continue;
            if (since > 0 && !touched(F) && !touched(G)) continue;
            const Face &fa = faces_[F], &fb = faces_[G];
            bool equal = F == G || (fa.infinite && fb.infinite) ||
                         (!fa.infinite && !fb.infinite && same_feature_quadratic(fa.poly, fa.label.region, fb.poly, fb.label.region, delta_));
            if (!equal) continue;
            int keep = std::min(F, G), gone = std::max(F, G);
            if (gone != keep && !fa.infinite)  // the kept quadratic now meets the other's neighbours
                faces_[keep].tie_slack = std::max(faces_[keep].tie_slack,
                                                  faces_[gone].tie_slack + unit_box_bound(faces_[keep].poly - faces_[gone].poly));
            std::vector<int>& hes = tmp_.merge_hes;
            hes.clear();
            for_each_half_edge(F, [&](int h) { hes.push_back(h); });
            if (G != F) for_each_half_edge(G, [&](int h) { hes.push_back(h); });
            remove_edge((int)e);
            any = true;
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
    return any;
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
        if (a == b || a == (int)v || b == (int)v) continue;  // (a loop edge at v: remove_edge)
        Vec2 pa = vertices_[a].p, pv = vertices_[v].p, pb = vertices_[b].p;
        Vec2 d1 = pv - pa, d2 = pb - pv;
        // Two pieces of one line (their equations agree) with v between their far ends. Angles
        // between tiny pieces mean nothing, so the equations decide, not the positions.
        const Quadratic2 &q1 = edges_[e1].equation, &q2 = edges_[e2].equation;
        if (!same_polynomial(q1, q2, 1e-9) && !same_polynomial(q1, q2 * -1.0, 1e-9)) continue;
        // One equation is one line only if it is linear: the two lines of a line pair (a conic
        // q_domain - q_region that factors) share their quadratic, and v where they cross is a
        // corner. Such pieces are one line only if v lies on the chord from a to b.
        if (!q1.is_linear() && std::fabs(cross(pb - pa, pv - pa)) > 1e-9 * norm(pb - pa)) continue;
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

}  // namespace hlens
