// Confirming the top of the result without the domain meshes (issue 8: the certified interval is a
// promise; design notes, "Certified answer").
//
// A domain mesh's maximum is exact up to where its vertices sit: a crossing within 1e-8 of a vertex
// snaps onto it, and a vertex polished onto two curves may sit 1e-7 off a third. So a maximum at a
// corner of domains can be measured up to ~1e-7 of the target's size away from where it is, and
// come out lower by as much (d(., B) is 1-Lipschitz). Only a target whose value (or bound) lies
// within kReach of its size below the result can hold a larger value; each of those is bounded
// from above here as the cascade bounds pieces, independently of its domain mesh:
//   - for any triangle T of B, d(., T) is convex, so its maximum over a sub-triangle S is at a
//     corner of S: max_S d <= max over the corners of d(., T), T the nearest triangle to S's centre;
//   - d(., B) is 1-Lipschitz: max_S d <= d(c) + r on S's enclosing ball (c, r).
// A sub-triangle whose bound is at most the largest distance measured so far, plus `tol`, is done;
// the others are split in four until their radius is below `tol`, and the largest bound of those
// done bounds the result.
// A centre farther than the result is a point the domain mesh missed: the result is raised to it
// and polished by a local search, so the answer is the largest distance actually measured.
// The subdivision closes quickly where d is smooth or one triangle is nearest; along a seam of B
// where d is flat (coinciding meshes) it may not within its node budget: such a target stays open,
// and its domain mesh's value (with the rounding allowance the certificate adds) stands for it.
// Distances are taken relative to a corner of the target (an input point): their rounding scales
// with the target's size and the distances, not with the coordinates' magnitude.
#include "confirm_top.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cascade.h"
#include "point_triangle.h"

namespace hlens {

namespace {

constexpr double kReach = 1e-6;      // of the target's size: its domain mesh's vertex error, with margin
constexpr size_t kPerTarget = 4096;  // sub-triangles per target, and
constexpr size_t kBudget = 65536;    // per confirmation; a target not closed within them stays open

using Tri3 = std::array<Vec3, 3>;

// A sub-triangle in the target's barycentric coordinates (u, v: p = u E1 + v E2 from the origin
// corner) and the nearest triangle of B to its parent's centre.
struct Sub {
    std::array<Vec2, 3> uv;
    uint32_t hint;
};

struct Target {
    Vec3 o, e1, e2;  // corner 0 (an input point) and the two edges from it
    double size;
    Vec3 at(Vec2 uv) const { return uv.x * e1 + uv.y * e2; }  // relative to o
};

// The distance from o + p to triangle T of B, relative to o: exact rounding-wise up to a few ulps
// of |p| + |T - o|.
double dist_rel(const Vec3& p, const Tri3& T) { return std::sqrt(closest_point_on_triangle(p, T[0], T[1], T[2]).dist2); }

Tri3 relative(const TriangleMesh& B, uint32_t t, const Vec3& o) {
    const auto c = B.corners(t);
    return {c[0] - o, c[1] - o, c[2] - o};
}

// max over S's corners of d(., T): d(., T) over S (convexity).
double corner_bound(const std::array<Vec3, 3>& S, const Tri3& T) {
    return std::max({dist_rel(S[0], T), dist_rel(S[1], T), dist_rel(S[2], T)});
}

// The target's size: its longest edge.
double longest_edge(const std::array<Vec3, 3>& c) { return std::max({norm(c[1] - c[0]), norm(c[2] - c[1]), norm(c[0] - c[2])}); }

// The rounding of one such distance: a few ulps of the magnitudes involved, generously.
double rounding(double size, double d, const Tri3& T) {
    const double m = std::max({norm(T[0]), norm(T[1]), norm(T[2])});
    return 256 * 0x1p-52 * (size + d + m);
}

// d(o + at(uv), T), T the triangle the grid finds nearest to the rounded world point: at least
// d(o + at(uv), B), and at most that plus twice `off` (how far the rounded point may be).
double measure(const MeshGrid& g, const Target& tg, Vec2 uv, uint32_t& hint, double* off = nullptr) {
    const Vec3 p = tg.at(uv), w = tg.o + p;
    const MeshGrid::Nearest q = g.nearest(w, hint);
    if (q.triangle == UINT32_MAX) return HUGE_VAL;
    hint = q.triangle;
    if (off) *off = 0x1p-52 * (std::fabs(w.x) + std::fabs(w.y) + std::fabs(w.z) + norm(p));
    return dist_rel(p, relative(g.mesh(), q.triangle, tg.o));
}

// A local search for the largest distance near uv, inside the target: steps from `h` down to the
// last bit, eight directions each.
Vec2 polish(const MeshGrid& g, const Target& tg, Vec2 uv, double h, double& value) {
    uint32_t hint = UINT32_MAX;
    value = measure(g, tg, uv, hint);
    for (; h > 1e-17; h *= 0.5)
        for (int moves = 0; moves < 64; ++moves) {
            bool moved = false;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy) {
                    const Vec2 q{uv.x + dx * h, uv.y + dy * h};
                    if ((dx == 0 && dy == 0) || q.x < 0 || q.y < 0 || q.x + q.y > 1) continue;
                    const double d = measure(g, tg, q, hint);
                    if (d > value) { value = d; uv = q; moved = true; }
                }
            if (!moved) break;
        }
    return uv;
}

}  // namespace

// Kept whole (~70 lines): the subdivision of each target shares the running largest distance, the
// raised witness and the node budgets with the loop over targets.
TopConfirmation confirm_top(const VoxelGrid& grid, int side, const TargetTable& tab, double best, double tol) {
    const TriangleMesh& A = grid.mesh(side);
    const MeshGrid& g = grid.of(1 - side);
    const TriangleMesh& B = g.mesh();
    TopConfirmation out;
    out.upper = best;
    double L = best;  // the largest distance measured so far
    Vec2 raised_uv;
    double raised_r = 0;
    // The targets that can reach the result, highest first (they get the budget first).
    std::vector<uint32_t> order;
    for (uint32_t t = 0; t < A.num_triangles(); ++t) {
        if (!(tab.bound[t] + kReach * longest_edge(A.corners(t)) + tab.slack[t] < L)) order.push_back(t);  // (a NaN bound too)
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return tab.bound[x] > tab.bound[y]; });
    std::vector<Sub> stack;
    for (uint32_t t : order) {
        const auto c = A.corners(t);
        const Target tg{c[0], c[1] - c[0], c[2] - c[0], longest_edge(c)};
        if (tab.bound[t] + kReach * tg.size + tab.slack[t] < L) continue;  // L has risen since
        ++out.targets;
        const size_t budget = std::min(out.nodes + kPerTarget, kBudget);
        double target_upper = -HUGE_VAL;
        stack.clear();
        stack.push_back({{Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, UINT32_MAX});
        while (!stack.empty() && out.nodes < budget) {
            const Sub s = stack.back();
            stack.pop_back();
            ++out.nodes;
            const std::array<Vec3, 3> S{tg.at(s.uv[0]), tg.at(s.uv[1]), tg.at(s.uv[2])};
            const Vec2 muv = (s.uv[0] + s.uv[1] + s.uv[2]) / 3.0;
            const Vec3 m = tg.at(muv);
            const double r = std::max({norm(S[0] - m), norm(S[1] - m), norm(S[2] - m)}) * (1 + 1e-12);
            uint32_t near = s.hint;
            double off;
            const double dm = measure(g, tg, muv, near, &off);
            if (!(dm < HUGE_VAL)) { out.upper = HUGE_VAL; return out; }  // B has no triangle
            const Tri3 T = relative(B, near, tg.o);
            const double slack = rounding(tg.size, dm, T) + 0x1p-50 * tg.size;  // (+ sub-triangles' seams)
            if (dm - 2 * off > L + slack) {  // farther than L for certain
                L = dm;
                out.raised = true;
                out.target = t;
                out.origin = tg.o;
                raised_uv = muv;
                raised_r = r / std::max(tg.size, 1e-300);
            }
            double u = dm + r;
            if (u > L) u = std::min(u, corner_bound(S, T));
            if (u > L && s.hint != UINT32_MAX && s.hint != near) u = std::min(u, corner_bound(S, relative(B, s.hint, tg.o)));
            u += slack;
            if (u <= L + tol || !(r > tol)) {  // done (a NaN radius too)
                target_upper = std::max(target_upper, u);
                continue;
            }
            const Vec2 ab = 0.5 * (s.uv[0] + s.uv[1]), bc = 0.5 * (s.uv[1] + s.uv[2]), ca = 0.5 * (s.uv[2] + s.uv[0]);
            stack.push_back({{s.uv[0], ab, ca}, near});
            stack.push_back({{ab, s.uv[1], bc}, near});
            stack.push_back({{ca, bc, s.uv[2]}, near});
            stack.push_back({{ab, bc, ca}, near});
        }
        if (stack.empty()) {
            ++out.closed;
            out.upper = std::max(out.upper, target_upper);
        } else {  // not closed within its budget: its domain mesh's value stands for it
            out.open_upper = std::max(out.open_upper, tab.bound[t] + tab.slack[t]);
        }
    }
    out.upper = std::max(out.upper, L);
    out.value = L;
    if (out.raised) {
        const auto c = A.corners(out.target);
        const Target tg{c[0], c[1] - c[0], c[2] - c[0], 0};
        const Vec2 uv = polish(g, tg, raised_uv, std::max(raised_r, 1e-12), out.value);
        out.offset = tg.at(uv);
        out.upper = std::max(out.upper, out.value);
    }
    return out;
}

bool polish_witness(const VoxelGrid& grid, int side, uint32_t target, const Vec3& point, double value, Vec3& origin,
                    Vec3& offset, double& polished) {
    const auto c = grid.mesh(side).corners(target);
    const Target tg{c[0], c[1] - c[0], c[2] - c[0], 0};
    // The point's (u, v) on the target: the normal equations of p - o = u E1 + v E2.
    const Vec3 p = point - c[0];
    const double a = dot(tg.e1, tg.e1), b = dot(tg.e1, tg.e2), d = dot(tg.e2, tg.e2), det = a * d - b * b;
    if (!(det > 0)) return false;  // a sliver: its slack covers it
    Vec2 uv{(d * dot(p, tg.e1) - b * dot(p, tg.e2)) / det, (a * dot(p, tg.e2) - b * dot(p, tg.e1)) / det};
    uv = {std::max(0.0, uv.x), std::max(0.0, uv.y)};
    if (uv.x + uv.y > 1) uv = uv / (uv.x + uv.y);
    uv = polish(grid.of(1 - side), tg, uv, kReach, polished);
    if (!(polished > value + 256 * 0x1p-52 * (longest_edge(c) + polished))) return false;
    origin = tg.o;
    offset = tg.at(uv);
    return true;
}

}  // namespace hlens
