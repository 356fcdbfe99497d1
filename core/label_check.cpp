// The domain mesh's labels against brute force; see label_check.h (issue 8, Straub 2007 §3.1).
#include "label_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "point_triangle.h"

namespace hlens {

namespace {
// The nearest feature on the boundary: the three edges as segments, an end counted as the vertex.
// Also the whole answer for a zero-area triangle (a segment or a point), where a region test
// divides by the area: wrong feature, wrong distance (degenerate seed 1635: 0.61 for 0.0076).
NearestFeature nearest_on_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    NearestFeature best;
    const Vec3* v[3] = {&a, &b, &c};
    const Region vertex[3] = {Region::a, Region::b, Region::c}, edge[3] = {Region::ab, Region::bc, Region::ca};
    for (int k = 0; k < 3; ++k) {
        const Vec3 &s = *v[k], &e = *v[(k + 1) % 3];
        const ClosestPoint cp = closest_point_on_segment(p, s, e);  // an end exactly where it clamps
        if (cp.dist2 < best.d2) best = {cp.dist2, cp.point == s ? vertex[k] : cp.point == e ? vertex[(k + 1) % 3] : edge[k]};
    }
    return best;
}
}  // namespace

// Inside the face, the distance of closest_point_inside (the plane spanned by the longest
// edge and its re-orthogonalised height). Not Ericson's region test (5.1.5): its barycentric
// numerators are differences of products, and on a sliver (height 5e-6 of its length) its face
// distance was 3e-9 relative off, so a neighbour's shared edge 5e-12 farther looked nearer
// (independent pair 9225, "fan"). Outside the face the nearest point is on an edge.
NearestFeature nearest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    ClosestPoint cp;
    if (closest_point_inside(p, a, b, c, cp)) return {cp.dist2, Region::abc};
    return nearest_on_edges(p, a, b, c);
}

// The squared distance from p to one feature of the triangle abc: its face (only where the foot is
// inside it: elsewhere the face is not the feature nearest), one of its edges as a segment, or a
// corner. +inf for a face whose foot is outside.
static double feature_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Region r) {
    switch (r) {
        case Region::abc: {
            ClosestPoint cp;
            return closest_point_inside(p, a, b, c, cp) ? cp.dist2 : HUGE_VAL;
        }
        case Region::ab: return closest_point_on_segment(p, a, b).dist2;
        case Region::bc: return closest_point_on_segment(p, b, c).dist2;
        case Region::ca: return closest_point_on_segment(p, c, a).dist2;
        case Region::a: return norm2(p - a);
        case Region::b: return norm2(p - b);
        case Region::c: return norm2(p - c);
    }
    return HUGE_VAL;
}

// The squared distance (frame units) from the frame's point q to the face of the source s (world
// coordinates) where q's foot on its plane lies inside it, else +inf; in long double, from the
// signs of the triple products n.(e x (p - corner)) of its three edges. On a sliver the frame's
// rounded corners cannot say: generate_pairs.py "sliver" 33474, a source 34317 long and 1.7e-4
// tall (4.7e-9 of T') standing on T' at 90 degrees less 3e-9 rad. Rounding the corners to the
// frame turns its height's direction by some 2e-8 rad, and so moves the foot of a point 0.28 of T'
// away by some 6e-9 across it: closest_point_inside put the foot outside where its exact
// barycentric coordinates (rationals from the input doubles) are (0.13, 0.71, 0.15), and the face,
// as near as the edges ca and ab to 1e-16, was not counted as a tie with them. In long double
// from world coordinates the products there are good to some 1e-3 of their size. All relative to
// the frame's origin, and q not rounded to a world point: on a target a few ulps of its
// coordinates across (generate_pairs8.py "mixed_scale_sim" 1746, 2.4e-7 at 3.5e8), that rounding
// is a quarter of T'.
static double face_distance2_world(const TargetFrame& fr, Vec2 q, const std::array<Vec3, 3>& s) {
    using LD = long double;
    struct V { LD x, y, z; };
    const LD qx = (LD)q.x * fr.scale, qy = (LD)q.y * fr.scale;
    const V p{qx * fr.e1.x + qy * fr.e2.x, qx * fr.e1.y + qy * fr.e2.y, qx * fr.e1.z + qy * fr.e2.z};
    auto rel = [&](const Vec3& u) { return V{(LD)u.x - fr.origin.x, (LD)u.y - fr.origin.y, (LD)u.z - fr.origin.z}; };
    auto sub = [](const V& u, const V& v) { return V{u.x - v.x, u.y - v.y, u.z - v.z}; };
    auto cross = [](const V& u, const V& v) { return V{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x}; };
    auto dot = [](const V& u, const V& v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
    const std::array<V, 3> c{rel(s[0]), rel(s[1]), rel(s[2])};
    const V n = cross(sub(c[1], c[0]), sub(c[2], c[0]));
    const LD nn = dot(n, n);
    if (!(nn > 0)) return HUGE_VAL;
    // The height over the plane from the point of the edges' lines nearest p (on the plane to
    // its rounding), not from a corner: n is off by its rounding over the source's area, 1e-7 on
    // a sliver 1e-12 thin, and from a corner 1.2e4 away that put a point 1e-12 from the face
    // 2e-6 off it (generate_pairs8.py "mixed_scale_sim" 702).
    V from{};
    LD nearest = HUGE_VALL;
    for (int k = 0; k < 3; ++k) {
        const V e = sub(c[(k + 1) % 3], c[k]), w = sub(p, c[k]);
        if (dot(n, cross(e, w)) < 0) return HUGE_VAL;
        const LD ee = dot(e, e), t = ee > 0 ? dot(w, e) / ee : 0;
        const V r{w.x - t * e.x, w.y - t * e.y, w.z - t * e.z};  // p less its foot on the line
        if (const LD rr = dot(r, r); rr < nearest) nearest = rr, from = r;
    }
    const LD h = dot(n, from);
    return (double)(h * h / nn) / ((LD)fr.scale * fr.scale);
}

// Whether the region test (face_foot: a height below 1e-12 of the longest edge is no face) takes
// for its edges a source whose projection has a face region (a height above 1e-14 of it,
// project_source): there the face is tested from world coordinates (face_distance2_world).
// Generate_pairs8.py "mixed_scale" 4589: a needle 1.4e9 long and 7e-4 wide, coplanar with a target
// 1.4e-3 across lying inside it, was taken for its edge, 1.4e-5 away, where d is 0: the domain
// labelled with a coplanar face of the same quadratic was counted as a disagreement.
static bool thin_face(const std::array<Vec3, 3>& s, const SourceProjection& proj) {
    if (proj.degenerate) return false;
    const double l2 = std::max({norm2(s[1] - s[0]), norm2(s[2] - s[1]), norm2(s[0] - s[2])});
    return norm2(cross(s[1] - s[0], s[2] - s[0])) <= 2e-24 * l2 * l2;  // generously: the test is only more precise
}

// feature_distance2 of source s's feature r at the frame point p, a thin face from world coordinates.
static double feature_distance2_at(Vec2 p, const std::array<Vec3, 3>& src, const std::array<Vec3, 3>& world, bool thin,
                                   Region r, const TargetFrame& fr) {
    const double d = feature_distance2(Vec3(p.x, p.y, 0), src[0], src[1], src[2], r);
    return r == Region::abc && d == HUGE_VAL && thin ? face_distance2_world(fr, p, world) : d;
}

const Quadratic2* region_quadratic(const SourceProjection& p, Region r) {
    for (const SourceRegion& reg : p.regions)
        if (reg.kind == r) return &reg.poly;
    return nullptr;
}

std::vector<int> tie_classes(const std::vector<SourceProjection>& proj, double delta) {
    std::vector<int> cls(8 * proj.size(), -1);
    std::vector<std::pair<int, const Quadratic2*>> feat;  // (index, quadratic) of every region
    for (size_t s = 0; s < proj.size(); ++s)
        for (const SourceRegion& r : proj[s].regions) {
            const int i = feature_index(s, r.kind);
            cls[i] = i;
            feat.push_back({i, &r.poly});
        }
    // Union-find over the pairs that tie, each class named by its smallest index.
    auto find = [&](int i) {
        while (cls[i] != i) i = cls[i] = cls[cls[i]];
        return i;
    };
    for (size_t a = 0; a < feat.size(); ++a)
        for (size_t b = a + 1; b < feat.size(); ++b)
            if (same_feature_quadratic(*feat[a].second, (Region)(feat[a].first % 8), *feat[b].second, (Region)(feat[b].first % 8), delta)) {
                const int x = find(feat[a].first), y = find(feat[b].first);
                if (x != y) cls[std::max(x, y)] = std::min(x, y);
            }
    for (const auto& f : feat) cls[f.first] = find(f.first);
    return cls;
}

std::array<Vec3, 3> source_in_frame(const TargetFrame& fr, const std::array<Vec3, 3>& c) {
    std::array<Vec3, 3> f;
    for (int k = 0; k < 3; ++k) {
        const Vec3 w = (c[k] - fr.origin) / fr.scale;
        f[k] = Vec3(dot(w, fr.e1), dot(w, fr.e2), dot(w, fr.normal));
    }
    return f;
}

Vec2 LabelCheck::sample_point(int x, int y) const {
    const double px = (hi.x - lo.x) / std::max(1, width);
    return {lo.x + (x + 0.5) * px, lo.y + (height - y - 0.5) * px};
}

namespace {

// True if no sample within `border` of (x, y) differs in either map (a sample at the edge of the
// box is near a change: T''s boundary).
bool away_from_changes(const LabelCheck& L, int x, int y, int border) {
    const int i = y * L.width + x;
    for (int dy = -border; dy <= border; ++dy)
        for (int dx = -border; dx <= border; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= L.width || yy >= L.height) return false;
            const int j = yy * L.width + xx;
            if (L.domain[j] != L.domain[i] || L.nearest[j] != L.nearest[i]) return false;
        }
    return true;
}

// 1. Both maps: the nearest feature (the first minimum over the sources, `src` in the frame) and
// the domain's label, as slot * 8 + region; best_d2: the nearest feature's squared distance.
void map_labels(const DomainMesh& mesh, const std::vector<std::array<Vec3, 3>>& src, const std::vector<std::array<Vec3, 3>>& world,
                const std::vector<char>& thin, const TargetFrame& fr, const std::vector<uint32_t>& ids,
                const LabelCheckOptions& opt, LabelCheck& L, std::vector<double>& best_d2) {
    auto slot_of = [&](int source) {
        for (size_t i = 0; i < ids.size(); ++i)
            if ((int)ids[i] == source) return (int)i;
        return -1;
    };
    for (int y = 0; y < L.height; ++y)
        for (int x = 0; x < L.width; ++x) {
            const int i = y * L.width + x;
            const Vec2 p = L.sample_point(x, y);
            const int f = mesh.face_at(p);
            if (f < 0) continue;
            const DomainMesh::Face& F = mesh.faces()[f];
            L.domain[i] = F.infinite || F.label.source < 0 ? -2 : feature_index(slot_of(F.label.source), F.label.region);
            const Vec3 q(p.x, p.y, 0);
            NearestFeature best;
            int bs = -1;
            for (int s = 0; s < (int)src.size(); ++s) {
                // The source being inserted counts only where its domains already are.
                if (s == opt.current && !(L.domain[i] >= 0 && L.domain[i] / 8 == s)) continue;
                NearestFeature ft = nearest_feature(q, src[s][0], src[s][1], src[s][2]);
                if (thin[s] && ft.region != Region::abc)
                    if (const double f = face_distance2_world(fr, p, world[s]); f <= ft.d2) ft = {f, Region::abc};
                if (ft.d2 < best.d2) best = ft, bs = s;
            }
            if (bs < 0) continue;
            L.nearest[i] = feature_index(bs, best.region);
            best_d2[i] = best.d2;
        }

}

// The nearest feature `nf` (source t, named as the region test names a triangle's features) as its
// projection names it: a degenerate source is a segment (its two ends and the edge between them)
// or a point, so the triangle's edge ca lying inside the segment bc is the segment's edge
// (independent pair "fan" 24969: a zero-area blade's edge tied with a neighbour's, a disagreement
// only by name). The region of the projection that holds p.
int projection_feature(const std::vector<SourceProjection>& proj, int t, int nf, Vec2 p) {
    if (!proj[t].degenerate) return nf;
    for (const SourceRegion& reg : proj[t].regions)
        if (in_region(reg, p, 1e-9)) return feature_index(t, reg.kind);
    return nf;
}

// 2. Compare away from changes. A different label is a tie where the two features' quadratics
// are one polynomial (or linked by a chain of such: tie_classes), or where the labelled feature
// itself is as near as the nearest one (to 1e-9 relative): two features whose distances differ by
// less than the quadratics can resolve. (Independent pair "perpendicular" 23555: a source standing
// 5e-7 rad off the vertical on an edge it shares, in T''s plane, with another; its face is nearer
// than that edge by 2.6e-13 relative, 3.6e-17 where d^2 is 1.4e-4, below the rounding of the
// quadratics (~1e-16): their difference is a square whose sign is noise over a band 0.02 wide
// along the edge, and part of it kept the edge's label.) A label stands for its tie class, so
// "the labelled feature" is the nearest of its class: a sliver source whose three corners lie on
// one line has three edges of one quadratic, and the domain named by one of them (merged, or the
// first inserted) covers the others' regions (generate_pairs.py "sliver" 2930 and 3970: a domain
// labelled edge bc 0.57 from bc, where edge ca of the same line is the nearest feature; the
// region test named the sliver's face, whose plane is 7e-10 relative nearer, its foot far outside).
void compare_labels(const std::vector<std::array<Vec3, 3>>& src, const std::vector<std::array<Vec3, 3>>& world,
                    const std::vector<char>& thin, const TargetFrame& fr, const std::vector<SourceProjection>& proj, double delta,
                    const std::vector<uint32_t>& ids, const LabelCheckOptions& opt, const std::vector<double>& best_d2,
                    LabelCheck& L) {
    const std::vector<int> classes = tie_classes(proj, delta);
    std::vector<std::vector<int>> members(classes.size());  // each class's features, by its name
    for (size_t f = 0; f < classes.size(); ++f)
        if (classes[f] >= 0) members[classes[f]].push_back((int)f);
    // The least and largest of a class's quadratics at p.
    auto spread = [&](const std::vector<int>& features, Vec2 p) {
        std::pair<double, double> r{HUGE_VAL, -HUGE_VAL};
        for (int f : features)
            if (const Quadratic2* qf = region_quadratic(proj[f / 8], (Region)(f % 8))) r.first = std::min(r.first, (*qf)(p)), r.second = std::max(r.second, (*qf)(p));
        return r;
    };
    for (int y = 0; y < L.height; ++y)
        for (int x = 0; x < L.width; ++x) {
            const int i = y * L.width + x;
            if (L.domain[i] < 0 || L.nearest[i] < 0) continue;
            if (!away_from_changes(L, x, y, opt.border)) { ++L.ignored; continue; }
            ++L.samples;
            if (L.domain[i] == L.nearest[i]) continue;
            const int s = L.domain[i] / 8, t = L.nearest[i] / 8;
            const Region r = (Region)(L.domain[i] % 8), rn = (Region)(L.nearest[i] % 8);
            bool tie = classes[L.domain[i]] >= 0 && classes[L.domain[i]] == classes[projection_feature(proj, t, L.nearest[i], L.sample_point(x, y))];
            if (!tie) {
                // A degenerate source's features carry other names in its projection (a segment's
                // ends and its one edge) than in the region test: compare the labelled quadratic's
                // value with the nearest distance instead.
                const Vec2 p = L.sample_point(x, y);
                double near = feature_distance2_at(p, src[s], world[s], true, r, fr);  // or the nearest of its tie class
                if (const int c = classes[L.domain[i]]; c >= 0)
                    for (int f : members[c])
                        if (f != L.domain[i])
                            near = std::min(near, feature_distance2_at(p, src[f / 8], world[f / 8], thin[f / 8], (Region)(f % 8), fr));
                // As near to within delta (the rounding of the sources' frame coordinates, the
                // tie rule's allowance on heights): distances that close are not resolved by the
                // quadratics. (A third generator's "stacked" 2457: layers 1e-13 of T' apart, about
                // an ulp of coordinates 2.7e4; a tie kept one layer's quadratic where another is
                // 1.4e-26 nearer in d^2, a third layer, nearer than the kept quadratic, took the
                // domain, and on 625 samples a layer 1.6e-27 away in d^2 was nearest where the
                // label's is 1.9e-27 away: 3.6e-15 apart in distance, delta 4.3e-14.)
                tie = near <= best_d2[i] * (1 + 1e-9) + 1e-300 || std::sqrt(near) <= std::sqrt(best_d2[i]) + delta;
                // Or within the spread of the class's quadratics at p: the rule made them one
                // polynomial, so the domain cannot tell a distance between them from the class's.
                // (Generate_pairs4.py "strip_vs_tri" 190: a strip 7e-12 of T' wide, its cells'
                // diagonals parallel lines 7e-12 apart, tied; a rail between them, 1.2e-9 relative
                // nearer than the diagonal whose region held p, 2.7e-15 farther than the other.)
                if (const int c = classes[L.domain[i]]; !tie && c >= 0) {
                    const auto [lo, hi] = spread(members[c], p);
                    tie = hi > lo && near - best_d2[i] <= hi - lo;
                }
                // Or, the other way round, within the spread of the nearest feature's class: the
                // rule made the class one polynomial, which the domain mesh holds by one member's
                // quadratic, and a feature nearer than that quadratic takes the domain from it.
                // (Generate_pairs5.py "point_like" 56486: a target 5e-15 across on an edge of an
                // octahedron 61 from the origin, where delta is 0.028 of T'; a face and its edge
                // tied, the edge's quadratic kept, 0.0116 at a sample where the face's d^2 is
                // 0.0013, and the neighbouring face, 0.0099 there, took the domain from it.)
                if (const int c = classes[projection_feature(proj, t, L.nearest[i], p)]; !tie && c >= 0 && members[c].size() > 1) {
                    const auto [lo, hi] = spread(members[c], p);
                    tie = hi > lo && near <= hi;
                }
                const Quadratic2* q = proj[s].degenerate ? region_quadratic(proj[s], r) : nullptr;
                tie = tie || (q && std::fabs((*q)(p) - best_d2[i]) <= 1e-9 * best_d2[i] + 64 * delta);
            }
            if (tie) { ++L.ties; continue; }
            ++L.disagree;
            if (L.first.empty()) {
                const Vec2 p = L.sample_point(x, y);
                char buf[256];
                std::snprintf(buf, sizeof buf, "at (%.9g, %.9g): domain labelled source %u %s, nearest is source %u %s (d^2 %.12g)",
                              p.x, p.y, ids[s], region_name(r), ids[t], region_name(rn), best_d2[i]);
                L.first = buf;
            }
        }
}

}  // namespace

LabelCheck check_labels(const DomainMesh& mesh, const TargetFrame& fr, const std::vector<std::array<Vec3, 3>>& sources,
                        const std::vector<uint32_t>& ids, const LabelCheckOptions& opt) {
    LabelCheck L;
    std::vector<std::array<Vec3, 3>> src;
    std::vector<SourceProjection> proj;
    double delta = 0;
    for (size_t s = 0; s < sources.size(); ++s) {
        src.push_back(source_in_frame(fr, sources[s]));  // the sample plane is z = 0
        proj.push_back(project_source(fr, sources[s], ids[s]));
        delta = std::max(delta, proj.back().delta);
    }

    Box2 box;
    for (const Vec2& c : fr.corners) box.add(c);
    const double bw = std::max(1e-300, box.hi.x - box.lo.x), bh = std::max(1e-300, box.hi.y - box.lo.y);
    const double px = std::max(bw, bh) / std::max(1, opt.resolution);
    L.width = std::max(1, (int)std::ceil(bw / px));
    L.height = std::max(1, (int)std::ceil(bh / px));
    L.lo = box.lo;
    L.hi = Vec2(box.lo.x + L.width * px, box.lo.y + L.height * px);
    const int n = L.width * L.height;
    L.nearest.assign(n, -1);
    L.domain.assign(n, -1);
    std::vector<double> best_d2(n, HUGE_VAL);

    std::vector<char> thin;
    for (size_t s = 0; s < sources.size(); ++s) thin.push_back(thin_face(src[s], proj[s]));
    map_labels(mesh, src, sources, thin, fr, ids, opt, L, best_d2);
    compare_labels(src, sources, thin, fr, proj, delta, ids, opt, best_d2, L);
    return L;
}

}  // namespace hlens
