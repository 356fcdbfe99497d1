// Where a source can be nearer: the insertion of Straub 2007 §3.1 without the cuts that the
// merging would undo. See domain_mesh.h and ../shared/design/algorithm.md ("The domain mesh").
//
// The paper's insertion (domain_insert.cpp) cuts every domain the source reaches by the source's
// seven regions, then each piece by the conic q_domain - q_region = 0, and finally merges the
// pieces where the source was not nearer back into one domain. On real pairs most of those cuts
// are undone: on a coarse target among fine sources, 61% of insertions change nothing and half of
// the regions that reach a domain win none of it. Here a region is cut into a domain only if it
// may be nearer somewhere on it, decided without cutting (region_nowhere_nearer): q_F - q_R <= 0
// (up to kNowhere) on F ∩ R is checked where its maximum can be, on supersets of those places, so
// a "nowhere" is certain and the pieces it saves are those the merging would have joined again.
//
// The result is the same function d^2 := min(d^2, d_T^2) on the same domains, with fewer spurious
// vertices left on curved arcs (tests: Lean.*, which compare it with the paper's insertion). The
// debugger, which shows every cut as an event, runs the paper's insertion (insert with a
// Listener); everything else (paper and fast mode, statistics) runs this one, but on a face that a
// region thinner than kCluster may reach (DomainMesh::thin_region_reaches).
#include "domain_mesh.h"

#include <algorithm>
#include <cmath>

namespace hlens {

namespace {
// g (scaled to unit size) may reach this much above 0 on F ∩ R and still count as nowhere nearer:
// a difference of quadratics below their rounding (TargetSolver::rounding_sq is 64 ulps of their
// coefficients, and g's are at most theirs), where the paper's insertion would give the source
// slivers of noise. Measured: such maxima are 0 to 1e-15 where not a rounding artefact, above 1e-7
// where a real piece is won.
constexpr double kNowhere = 1e-15;
constexpr double kRegionSlack = 1e-9;  // regions and boxes widened by this (frame units, T' of unit size)

// [lo, hi] of the line o + t u clipped by the half-plane (widened by kRegionSlack: the regions'
// normals have unit length, regions.cpp); false if empty.
bool clip_param(const HalfPlane& hp, Vec2 o, Vec2 u, double& lo, double& hi) {
    if (hp.kind == HalfPlane::All) return true;
    if (hp.kind == HalfPlane::None) return false;
    const double a = dot(hp.n, u), b = hp.offset - kRegionSlack - dot(hp.n, o);  // inside: a t >= b
    if (a > 0) lo = std::max(lo, b / a);
    else if (a < 0) hi = std::min(hi, b / a);
    else if (b > 0) return false;
    return lo <= hi;
}

bool boxes_miss(const Box2& a, const Box2& b) {
    return a.hi.x < b.lo.x || a.lo.x > b.hi.x || a.hi.y < b.lo.y || a.lo.y > b.hi.y;
}

// The regions of `mask` within `tol` of p.
unsigned regions_holding(const SourceProjection& src, Vec2 p, unsigned mask, double tol) {
    for (size_t k = 0; k < src.regions.size(); ++k)
        if ((mask >> k & 1u) && !in_region(src.regions[k], p, tol)) mask &= ~(1u << k);
    return mask;
}

}  // namespace

// Face F (alive when the insertion began): the regions that may be nearer somewhere on it are
// cut in, in the paper's order, and their pieces where the source is nearer relabelled
// (apply_region). The last region may take what is left uncut only if no region before it was
// passed over as nowhere nearer (the regions tile the plane, so then the rest is in it).
void DomainMesh::insert_where_nearer(int F, const SourceProjection& src, const RegionBoxes& boxes) {
    const size_t R = src.regions.size();
    unsigned may_win = 0;
    bool passed_over = false;
    tmp_.face_arcs.clear();  // F's arcs, read once for all its regions' tests
    for (size_t k = 0; k < R; ++k) {
        if (region_box_misses(cached_face_box(F), boxes, k)) continue;
        if (tmp_.face_arcs.empty())
            for_each_half_edge(F, [&](int h) {
                FaceArc a{vertices_[half_[h].origin].p, vertices_[target(h)].p, h >> 1, edges_[h >> 1].curve.straight(), {}};
                if (!a.straight) {
                    a.box = arc_geometry(a.e).bulge;
                    a.box.add(a.a), a.box.add(a.b);
                }
                tmp_.face_arcs.push_back(a);
            });
        if (region_nowhere_nearer(F, src.regions[k], boxes.box[k])) { passed_over = true; continue; }
        may_win |= 1u << k;
    }
    std::vector<int>& pending = tmp_.pending;
    std::vector<int>& inside = tmp_.inside;
    pending.assign(1, F);
    for (size_t k = 0; k < R && may_win && !pending.empty(); ++k) {
        if (!(may_win & (1u << k))) continue;
        const SourceRegion& reg = src.regions[k];
        inside.clear();
        if (k + 1 == R && !passed_over) inside.swap(pending);
        else if (pending.size() == 1 && pending[0] == F && region_box_inside(cached_face_box(F), reg)) inside.swap(pending);
        else cut_by_region(reg, nullptr);
        for (int P : inside) apply_region(P, src, k + 1 == R ? src.regions[leftover_region(P, src, may_win, R - 1)] : reg, nullptr);
    }
    // Where no region was passed over but the last of all missed F's box, the last that may win
    // takes what its cut left, as the last of all would: the others' boxes miss F's, so what is
    // left is a crack between the cuts. Generate_pairs4.py "f32_export" 19111, target 31 of B, the
    // paper's order: the first source's regions meeting T' were four of seven, the seventh not
    // among them, and a sliver 8e-8 wide that the cuts left stayed with no source (d^2 infinite)
    // until the next source won it whole with one region's quadratic, 0.5 where d^2 is 0.125.
    if (!passed_over && may_win && !pending.empty()) {
        size_t last = 0;
        for (size_t k = 0; k < R; ++k)
            if (may_win & (1u << k)) last = k;
        inside.clear();
        inside.swap(pending);
        for (int P : inside) apply_region(P, src, src.regions[leftover_region(P, src, may_win, last)], nullptr);
    }
    if (passed_over && may_win) {
        set_aside_dropped_pieces(src, may_win);
        claim_cracks(src, may_win);
        for (int P : tmp_.dropped) insert_into_face(P, src, boxes, nullptr);
    }
}

// The pieces of F left in no region (tmp_.pending) that reach into a region that may win, deeper
// than a vertex on its line can be (kOnCurve), move to tmp_.dropped: that region's cut dropped its
// chord as hugging the boundary and gave the whole piece the side of its farthest arc, outside.
// The paper's insertion then gives it to the region across that line, whose quadratic meets this
// one's along it, so d^2 is right to the resolution; here that region may have been passed over as
// nowhere nearer, and the piece would keep the old domain however far its quadratic is from the
// source's. So such a piece gets the paper's insertion (insert_into_face). (Generate_pairs10.py
// "unused_verts" 5288, side A, target 3, the paper's order, the 7th insertion: a sliver 2.6e-7
// wide along T''s edge, which the face region's line crosses at 1e-6 rad; its chord dropped, the
// sliver, 1.3e-7 deep in the face region over most of its length, went outside it, into the edge
// region passed over, and kept a farther source: d^2 0.202 beside 0.126 across its side.)
void DomainMesh::set_aside_dropped_pieces(const SourceProjection& src, unsigned may_win) {
    tmp_.dropped.clear();
    size_t kept = 0;
    for (int P : tmp_.pending) {
        const Quadratic2& q = faces_[P].poly;
        bool nearer = false;
        for_each_half_edge(P, [&](int h) {
            const Vec2 v = vertices_[half_[h].origin].p;
            for (size_t k = 0; k < src.regions.size() && !nearer; ++k) {
                if (!(may_win >> k & 1u) || !(region_margin(src.regions[k], v) > kOnCurve)) continue;
                const Quadratic2& r = src.regions[k].poly;
                nearer = q(v) - r(v) > kCluster * (norm(q.gradient(v)) + norm(r.gradient(v)));
            }
        });
        if (nearer) tmp_.dropped.push_back(P);
        else tmp_.pending[kept++] = P;
    }
    tmp_.pending.resize(kept);
    stats_.dropped_pieces += (long)tmp_.dropped.size();
}

// A point just inside face f beside the middle of its longest arc, or interior_point's. On a
// sliver 1e-7 wide and 0.24 long from a cluster of region lines to T''s edge, interior_point
// stepped in from a short arc at the cluster, within kCluster of every region there, and the
// sliver went to the last region (generated "mixed_scale" 862, the paper's insertion: the face
// region of a coplanar source 5e-8 across, d^2 0 along the whole sliver where it is up to 0.056).
bool DomainMesh::long_arc_point(int f, Vec2& out) const {
    int best = -1;
    double len = 0;
    for_each_half_edge(f, [&](int h) {
        const double l = norm(vertices_[target(h)].p - vertices_[half_[h].origin].p);
        if (l > len) len = l, best = h;
    });
    if (best >= 0)
        for (double step : {1e-3, 1e-5, 1e-7, 1e-9})
            if (point_beside(f, best, len, step, out)) return true;
    if (interior_point(f, out)) return true;
    // A piece folded by rounding (its loop clockwise, its area below rounding) has every point
    // beside its arcs outside it: its corners' centroid, where it lies in the piece (generate_pairs11.py
    // "a_cone_over_fan" 21079, side A, target 8: a piece 2.3e-6 by 1.4e-7 beside a needle source's
    // corner regions went to its face region, 6e-6 away, d^2 6.9e-11 below the truth).
    Vec2 c{0, 0};
    int n = 0;
    for_each_half_edge(f, [&](int h) { c = c + vertices_[half_[h].origin].p, ++n; });
    c = (1.0 / n) * c;
    if (!point_in_face(f, c)) return false;
    out = c;
    return true;
}

// What the regions before the last left is in the last one (the regions tile the plane), but
// where their lines cross within kCluster of a point a cut may drop its chord and leave part of
// another region outside it: a sliver 3e-9 wide and 6e-4 long of a source's corner region, between
// two of its lines 4e-6 rad apart, went to the face region, 2e-6 from it (generate_pairs.py "perp"
// 4531, the first insertion), and in the paper's insertion a wedge 1e-7 wide and 0.024 long of a
// corner region, 0.024 outside a face region whose edge line is T''s edge ("perp" 10291). A piece
// with a corner more than kCluster outside the last region, none more than kCluster inside it and
// its interior point outside goes to the region deepest at that point, if that one may be nearer.
// A piece across the last region's line is a cut that failed, no region's: it stays with the last
// (given to the region deepest at its interior point, such a piece of our stress seed 698,
// overlapping coplanar sources, made d^2 jump by 2.3e-8 relative across an edge).
size_t DomainMesh::leftover_region(int P, const SourceProjection& src, unsigned may_win, size_t last) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for_each_half_edge(P, [&](int h) {
        const double m = region_margin(src.regions[last], vertices_[half_[h].origin].p);
        lo = std::min(lo, m), hi = std::max(hi, m);
    });
    Vec2 x;
    if (!(lo < -kCluster) || hi > kCluster || !long_arc_point(P, x) || in_region(src.regions[last], x, kCluster)) return last;
    const size_t best = deepest_region(src, x);
    return (may_win >> best) & 1u ? best : last;
}

// The pieces of F left in no region after the cuts (tmp_.pending) are those of the regions passed
// over, and the cracks between regions: where three or more region lines cross within kCluster of
// each other, a region's part of the face may be a piece that small, and the cut that should take
// it in drops its chord as hugging the boundary (domain_split.cpp) and gives it the face's side.
// Each later region, whose lines are the same lines, leaves it outside too, and the piece keeps the
// old domain where the source is far nearer (independent pair "parallel_offset" 19917: a triangle
// 1e-7 across at the projection of a source's corner on T''s edge kept d^2 = 0.057 where the source
// gives 3e-15). The same holds for a sliver along one region line, as long as it likes but no wider
// than kCluster ("sliver" 11746: 6.6e-6 by 1e-8 at a needle source's corner, left with a domain
// 0.05 away, d^2 0.0026 beside 2e-11). The paper's insertion gives what is left to the last region;
// here a piece goes to a region that may be nearer on F and holds all of it (its corners and curved
// arcs, regions_holding_piece) and a point beside its longest arc (long_arc_point), up to kCluster:
// such a piece is no region's part of any face but by rounding. Of several, the one deepest at that
// point. (Not merely the region deepest there: a sliver 1.2e-7 wide along T''s edge, across which
// runs the line between a source's edge and face regions, was dropped by both cuts, and its point,
// from interior_point at the short arc at its end, lay deepest in a corner region; from its long
// arc it may lie just inside the face region, which misses a far corner by 1.03e-7, where the edge
// region holds it all (generate_pairs4.py "f32_export" 21117, target 7 of B, the paper's order: the
// sliver kept d^2 0.2 where the source gives 1e-15). Nor the deepest of the regions holding every
// corner alone: generate_pairs6.py "zero_area" 3977's face region held a piece's corners but not
// its middle, 6.7e-7 beyond.)
void DomainMesh::claim_cracks(const SourceProjection& src, unsigned may_win) {
    std::vector<int>& cracks = tmp_.inside;  // free again: the region loop is done with it
    cracks.clear();
    std::vector<int> slivers;
    for (int P : tmp_.pending) {  // most lie in regions passed over, whose corners no region may win holds
        if (regions_holding_corners(P, src, may_win)) {
            cracks.push_back(P);
            continue;
        }
        const Box2 b = cached_face_box(P);
        if (face_area(P) <= kCluster * norm(b.hi - b.lo)) slivers.push_back(P);
    }
    for (int P : cracks) claim_crack(P, src, may_win);
    for (int P : slivers) claim_sliver(P, src, may_win);
}

// A crack (claim_cracks) goes to the region that holds it, deepest at a point beside its long arc.
void DomainMesh::claim_crack(int P, const SourceProjection& src, unsigned may_win) {
    Vec2 x;
    if (!long_arc_point(P, x)) return;
    const unsigned holding = regions_holding_piece(P, src, may_win);
    if (!holding) return;
    const size_t best = deepest_region(src, x, holding);
    if (in_region(src.regions[best], x, kCluster)) apply_region(P, src, src.regions[best], nullptr);
}

// A sliver no wider than kCluster on the whole (its area below kCluster times its size) that no
// region holds: the regions' lines run along it within kCluster, so no cut could take it in, and
// part of it may lie in a region passed over. Where the source is nearer than the domain by the
// quadratic of the region deepest beside its long arc, its pieces are cracks. (Generate_pairs9.py
// "shared_edge_tiny" 2146, side B, target 2, the paper's order: a sliver source 1.6e-8 across
// standing on T''s edge, its region lines within 1.5e-7 of that edge for 0.17 of T'; the sliver of
// the old domain between them, 0.17 long, kept the old source, whose d^2 there is up to 0.0013
// where this one's is 0, and only its far end lies in the corner region passed over.)
void DomainMesh::claim_sliver(int P, const SourceProjection& src, unsigned may_win) {
    Vec2 x;
    if (!long_arc_point(P, x)) return;
    const size_t k = deepest_region(src, x, may_win);
    if (k >= src.regions.size() || !in_region(src.regions[k], x, kCluster)) return;
    std::vector<SplitPiece> pieces;
    split_where_below(P, src.regions[k].poly, pieces);
    for (const SplitPiece& pc : pieces)
        if (pc.sign > 0) claim_crack(pc.face, src, may_win);
}

// The regions of `mask` within kCluster of every corner of face P.
unsigned DomainMesh::regions_holding_corners(int P, const SourceProjection& src, unsigned mask) const {
    for_each_half_edge(P, [&](int h) { mask = regions_holding(src, vertices_[half_[h].origin].p, mask, kCluster); });
    return mask;
}

// The regions of `mask` within kCluster of all of face P: of its corners and of points along its
// curved arcs, which may bulge out of a region whose lines hold their ends (the region is convex,
// so a straight-sided piece whose corners it holds lies in it). A lens between a region line and a
// conic, its two corners 1.6e-6 apart on the line and its arc 1.4e-6 across it, is not the region's
// (generate_pairs3.py "dup_faces" 47130, target 3 of A, nearest first, a crack rule that asked for
// the corners and one point beside the straight arc).
unsigned DomainMesh::regions_holding_piece(int P, const SourceProjection& src, unsigned mask) const {
    mask = regions_holding_corners(P, src, mask);
    for_each_half_edge(P, [&](int h) {
        if (edges_[h >> 1].curve.straight()) return;
        for (double t : {0.25, 0.5, 0.75}) mask = regions_holding(src, edge_point(h >> 1, t), mask, kCluster);
    });
    return mask;
}

// True if region R of the source is nowhere nearer than face F's domain on F ∩ R: g = q_F - q_R
// <= kNowhere there, so the paper's insertion would give no piece of F to R but rounding noise. A
// quadratic that is not strictly concave takes its maximum over a compact set on the set's
// boundary, which lies on F's arcs inside R and on R's lines inside F; a strictly concave one may
// also take it at its centre. Each is checked on a superset (a curved arc whole, a line between
// its first and last crossing of F's boundary), so "true" is certain and "false" means "cut".
bool DomainMesh::region_nowhere_nearer(int F, const SourceRegion& reg, const Box2& rbox) {
    const Face& face = faces_[F];
    if (face.infinite) return false;
    if (same_feature_quadratic(face.poly, face.label.region, reg.poly, reg.kind, delta_)) {  // a tie: the domain keeps it
        note_tie(F, reg.poly);
        return true;
    }
    Quadratic2 g = face.poly - reg.poly;
    const double gs = g.scale();
    if (!(gs > 0)) return false;
    g = g * (1.0 / gs);
    const Box2 fb = cached_face_box(F);
    const Box2 b{{std::max(fb.lo.x, rbox.lo.x) - kRegionSlack, std::max(fb.lo.y, rbox.lo.y) - kRegionSlack},
                 {std::min(fb.hi.x, rbox.hi.x) + kRegionSlack, std::min(fb.hi.y, rbox.hi.y) + kRegionSlack}};
    if (b.lo.x > b.hi.x || b.lo.y > b.hi.y) return true;  // F's box misses R's
    if (g.range(b.lo, b.hi).hi <= kNowhere) return true;
    if (Vec2 x; g.a < 0 && g.centre(x)) {  // strictly concave: its centre, if in the box
        const bool in_r = x.x >= b.lo.x && x.x <= b.hi.x && x.y >= b.lo.y && x.y <= b.hi.y && in_region(reg, x, kRegionSlack);
        if (in_r && !(g(x) <= kNowhere)) return false;
    }
    return arcs_nowhere_nearer(reg, g, b) && lines_nowhere_nearer(reg, g);
}

// g <= kNowhere on F's arcs inside R: a straight arc clipped to R exactly, a curved one whole
// (its box permitting).
bool DomainMesh::arcs_nowhere_nearer(const SourceRegion& reg, const Quadratic2& g, const Box2& b) const {
    for (const FaceArc& arc : tmp_.face_arcs) {
        const Vec2 pa = arc.a, pb = arc.b;
        if (arc.straight) {
            double lo = 0, hi = 1;
            bool in = true;
            for (const HalfPlane& hp : reg.planes) in = in && clip_param(hp, pa, pb - pa, lo, hi);
            if (in && !(range_along(g, pa, pb - pa, lo, hi).hi <= kNowhere)) return false;
            continue;
        }
        if (boxes_miss(arc.box, b)) continue;
        // The whole arc (a superset of its part inside R): g - kNowhere negative all along it,
        // by a bound if that suffices, else by its sign changes (none) and one value.
        const Edge& E = edges_[arc.e];
        Quadratic2 shifted = g;
        shifted.f -= kNowhere;
        const Poly along = E.curve.compose(shifted);  // (g - kNowhere) w^2: the sign of g - kNowhere
        double roots[kMaxSignChangeRoots];
        if (!(along(0.5 * (E.z0 + E.z1)) < 0 && (one_sign_on(along, E.z0, E.z1) || sign_change_roots(along, E.z0, E.z1, roots) == 0)))
            return false;
    }
    return true;
}

// g <= kNowhere on R's lines inside F: each line between its first and last crossing of F's boundary (a
// superset of line ∩ F: F is bounded, so a line that meets it crosses its boundary), clipped to
// R's other half-planes. A straight arc crosses the line where its ends' signed distances say
// (the rounding of that point is far below kRegionSlack); a curved one within its box's shadow.
bool DomainMesh::lines_nowhere_nearer(const SourceRegion& reg, const Quadratic2& g) const {
    // One pass over F's arcs for all of R's lines (at most 3).
    const HalfPlane* line[3];
    int nl = 0;
    for (const HalfPlane& hp : reg.planes)
        if (hp.kind == HalfPlane::Line) {
            if (nl == 3) return false;
            line[nl++] = &hp;
        }
    if (nl == 0) return true;
    constexpr double tol = 1e-12;  // (unit normals)
    double tmin[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, tmax[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    Vec2 u[3], o[3];
    for (int j = 0; j < nl; ++j) u[j] = {-line[j]->n.y, line[j]->n.x}, o[j] = line[j]->n * line[j]->offset;
    auto cover = [&](int j, Vec2 p) {
        const double t = dot(p - o[j], u[j]);
        tmin[j] = std::min(tmin[j], t);
        tmax[j] = std::max(tmax[j], t);
    };
    for (const FaceArc& arc : tmp_.face_arcs) {
        const Vec2 pa = arc.a, pb = arc.b;
        if (arc.straight) {
            for (int j = 0; j < nl; ++j) {
                const HalfPlane& hp = *line[j];
                const double ha = dot(hp.n, pa) - hp.offset, hb = dot(hp.n, pb) - hp.offset;
                if ((ha > tol && hb > tol) || (ha < -tol && hb < -tol)) continue;
                if (std::fabs(ha) <= tol) cover(j, pa);
                if (std::fabs(hb) <= tol) cover(j, pb);
                if ((ha > tol && hb < -tol) || (ha < -tol && hb > tol)) cover(j, pa + (pb - pa) * (ha / (ha - hb)));
            }
            continue;
        }
        const Box2& ab = arc.box;
        const Vec2 corners[4] = {ab.lo, ab.hi, Vec2{ab.lo.x, ab.hi.y}, Vec2{ab.hi.x, ab.lo.y}};
        for (int j = 0; j < nl; ++j) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (Vec2 c : corners) {
                const double v = dot(line[j]->n, c) - line[j]->offset;
                lo = std::min(lo, v), hi = std::max(hi, v);
            }
            if (lo > tol || hi < -tol) continue;
            for (Vec2 c : corners) cover(j, c);
        }
    }
    for (int j = 0; j < nl; ++j) {
        if (!(tmin[j] <= tmax[j])) continue;  // the line misses F
        double lo = tmin[j] - kRegionSlack, hi = tmax[j] + kRegionSlack;
        bool empty = false;
        for (const HalfPlane& other : reg.planes)
            if (&other != line[j] && !clip_param(other, o[j], u[j], lo, hi)) { empty = true; break; }
        if (empty) continue;
        if (!(range_along(g, o[j], u[j], lo, hi).hi <= kNowhere)) return false;
    }
    return true;
}

}  // namespace hlens
