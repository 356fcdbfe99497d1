// The certified interval of a one-sided distance: design notes, "Certified answer"
// (../shared/design/algorithm.md). See certificate.h.
#include "certificate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "cascade.h"
#include "confirm_top.h"
#include "point_triangle.h"
#include "target_solver.h"

namespace hlens {

namespace {

std::string format_g17(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The distance from the point origin + offset to the mesh of `grid`, computed without forming
// that point: each triangle is taken relative to `origin` (an input point), so the result is off
// by rounding relative to the distances involved, not to the coordinates' magnitude (which would
// be an ulp of 1e6 for a mesh of size 1 far from the origin). The grid's nearest point to the
// rounded sum bounds which triangles can be nearest; `to_point` is the nearest point. `distance`
// is the search's evaluation (closest_point_on_triangle), `lower` each triangle's distance taken
// from below: the search's may be too far by a sliver's height (generate_pairs3.py "sliver" 12014:
// a source 3.3e-12 high taken as its edges, the lower end 1.6e-12 where the distance is 6.3e-13).
struct Witness { double distance = HUGE_VAL, lower = HUGE_VAL; Vec3 to_point; };
Witness witness_distance(const MeshGrid& grid, const Vec3& origin, const Vec3& offset) {
    Witness w;
    const Vec3 p = origin + offset;
    const MeshGrid::Nearest q = grid.nearest(p);
    w.to_point = q.point;
    if (q.triangle == UINT32_MAX) return w;
    // |p - (origin + offset)| <= half an ulp per axis; triangles farther than d0 + 2 eps from p
    // are farther from the exact point than the one found.
    const double eps = 0x1p-53 * (std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z)) * (1 + 1e-9);
    const double reach = (std::sqrt(q.dist2) + 3 * eps) * (1 + 1e-12);
    w.distance = grid.distance_relative(origin, offset, reach);
    w.lower = grid.distance_lower_relative(origin, offset, reach);
    return w;
}

// The witness: the largest exact value, the lowest index among equals. Returns its square, or -1
// if no target was solved whole.
double choose_witness(const TargetTable& tab, size_t n, OneSidedResult& r) {
    double best = -1;
    for (size_t t = 0; t < n; ++t) {
        if (tab.value_sq[t] > best) { best = tab.value_sq[t]; r.target = (uint32_t)t; }
        r.exact_targets += tab.exact[t];
    }
    return best;
}

// The rounding of an exactly computed witness distance d (16 ulps of the diagonal and d): lower
// ends lie this far below it.
double witness_rounding(double d, const Box3& box) { return 16 * 0x1p-52 * (box.diagonal() + d); }

// The allowance for the rounding of coordinates where no confirmation covers a value `v`: 1e-13
// of the coordinates' magnitude and the diagonal, and 1e-12 of v.
double coordinate_allowance(double v, double coord, const Box3& box) { return 1e-13 * (coord + box.diagonal()) + 1e-12 * v; }

// lower: the true distance from the witness to B, by exact point-triangle distances over the
// whole of B, independently of the domain meshes, less their rounding (relative to the distances:
// the witness is never formed in world coordinates, see witness_distance). Sets the witness points.
double lower_end(const VoxelGrid& grid, int side, const TargetTable& tab, const Box3& box, OneSidedResult& r) {
    // The witness in world coordinates, as TargetSolver::max_point() gives it, and its offset from
    // the target's frame origin (a corner of the target, an input point).
    const std::array<Vec3, 3> c = grid.mesh(side).corners(r.target);
    const TargetFrame frame = TargetFrame::make(c);
    const Vec2 w = tab.where[r.target];
    r.from_point = frame.to_world(w);
    Vec3 offset = (w.x * frame.scale) * frame.e1 + (w.y * frame.scale) * frame.e2;
    // A sliver target's witness, on its edges in the frame, may lie off the sliver by up to its
    // height (the frame's plane is the sliver's only to that), its slack: it is taken to the
    // nearest point of the target itself, relative to the frame's origin (one of its corners), so
    // that its distance bounds the one-sided distance from below. Less the slack instead, the
    // lower end was 0 where the distance was 4.2e-4 (generate_pairs4.py "thin_shell_far" 187: a
    // rim sliver 8e-4 high joining the two sides of a shell, coordinates 4e9).
    if (tab.slack[r.target] > 0) {
        offset = closest_point_on_triangle(offset, c[0] - frame.origin, c[1] - frame.origin, c[2] - frame.origin).point;
        r.from_point = frame.origin + offset;
    }
    const Witness wd = witness_distance(grid.of(1 - side), frame.origin, offset);
    r.to_point = tab.copy[r.target] ? r.from_point : wd.to_point;  // a copy's point lies on the other mesh, exactly
    return std::max(0.0, std::min(r.distance, wd.lower - witness_rounding(wd.lower, box)));
}

// upper: what the confirmation of the top left (confirm_top.cpp: a bound without the domain
// meshes, over every target that can reach the result). Over closed targets its rounding is
// relative to the targets' sizes and the distances, not to the coordinates.
// A sliver target's true maximum may lie above its value by its slack (its height, at most 1e-7 of
// its longest edge): the confirmation's reach (1e-6 of the target's size, plus the slack) takes in
// every sliver that can reach the result, in either mode (fast mode's table has the slack of the
// targets it did not solve whole), and bounds it by subdivision of the triangle itself. So the
// sliver pieces' values with their slack (tab.piece_upper, fast mode only: the interval was looser
// than paper mode's) are not needed here; a cancelled run, which has no confirmation, uses them.
// Targets left open (not closed within the subdivision's budget) are bounded by what their
// subdivision had when it stopped (confirm_top.cpp, pending_bound), or by their longest edge's
// bound plus their height where lower (edge_bound), not by their domain meshes' maximum, which is
// no bound (generate_pairs4.py "cap_sliver" 9260).
double upper_end(const TopConfirmation& top, double distance) {
    double upper = std::max(distance, top.upper);
    if (top.open_upper >= 0) upper = std::max(upper, top.open_upper);
    return upper * (1 + 1e-15);
}

// A cancelled run has no confirmation: the domain meshes' maximum, widened by a bound on the
// rounding of coordinates.
double cancelled_upper_end(const TargetTable& tab, size_t n, double distance, double coord, const Box3& box) {
    double upper = std::max(distance, tab.piece_upper);
    for (size_t t = 0; t < n; ++t)  // a sliver target's value may be short by its height
        if (tab.slack[t] > 0 && tab.value_sq[t] >= 0) upper = std::max(upper, std::sqrt(tab.value_sq[t]) + tab.slack[t]);
    return upper + coordinate_allowance(distance, coord, box);
}

// At most this many targets are polished (a fan of triangles round the witness vertex has a few).
constexpr size_t kPolish = 16;

// The witness polished (polish_witness): a domain mesh's maximum may sit ~1e-7 of its target's size
// off the true one, and where the maximum is at or near a vertex shared by several targets, the
// farther point may lie in a neighbour of the witness target, beyond the witness's own local search
// (independent pair 11608: 2.5e-9 farther, 6e-6 from the shared vertex, in the witness's
// neighbour). So every target whose exact value ties with the best (tie_threshold_sq) is polished:
// fast mode solves all of them whole (cascade.cpp), so the set, its order (value descending, lowest
// index among equals) and the result are paper mode's. At most kPolish of them, in that order. True
// (the point origin + offset and its target) if one is farther than `value` by more than rounding;
// the farthest, the first in the order among equals.
bool polish_ties(const VoxelGrid& grid, int side, const TargetTable& tab, size_t n, double value, double tol, double coord,
                 Vec3& origin, Vec3& offset, uint32_t& target) {
    const double tie = tie_threshold_sq(value * value, coord);
    std::vector<uint32_t> ties;
    for (uint32_t t = 0; t < n; ++t)
        if (tab.value_sq[t] >= 0 && tab.value_sq[t] >= tie && !tab.copy[t]) ties.push_back(t);
    std::stable_sort(ties.begin(), ties.end(), [&](uint32_t x, uint32_t y) { return tab.value_sq[x] > tab.value_sq[y]; });
    if (ties.size() > kPolish) ties.resize(kPolish);
    bool found = false;
    double best = value;
    for (uint32_t t : ties) {
        const Vec3 point = TargetFrame::make(grid.mesh(side).corners(t)).to_world(tab.where[t]);
        Vec3 o, off;
        double polished;
        if (polish_witness(grid, side, t, point, value, tol, coord, o, off, polished) && polished > best) {
            best = polished;
            origin = o;
            offset = off;
            target = t;
            found = true;
        }
    }
    return found;
}

}  // namespace

double point_distance_lower(const VoxelGrid& grid, int side, const Vec3& p) {
    Box3 box = grid.mesh(side).bounds();
    box.add(grid.mesh(1 - side).bounds());
    const Witness w = witness_distance(grid.of(1 - side), p, Vec3{0, 0, 0});
    if (!(w.lower < HUGE_VAL)) return w.lower;  // the other mesh is empty
    return std::max(0.0, w.lower - witness_rounding(w.lower, box));
}

void certify(const VoxelGrid& grid, int side, const TargetTable& tab, Mode mode, OneSidedResult& r) {
    const TriangleMesh& A = grid.mesh(side);
    const TriangleMesh& B = grid.mesh(1 - side);
    const size_t n = A.num_triangles();
    const double best = choose_witness(tab, n, r);
    r.exact_solves = tab.solves;
    if (best < 0) return;
    r.distance = std::sqrt(best);
    Box3 box = A.bounds();
    box.add(B.bounds());
    const double coord = coordinate_magnitude(A, B);
    if (r.cancelled) {
        r.lower = lower_end(grid, side, tab, box, r);
        r.upper = cancelled_upper_end(tab, n, r.distance, coord, box);
        return;
    }
    // The top, confirmed without the domain meshes to 1e-10 of the diagonal (the interval's goal
    // is 1e-9); where it finds a point farther than the domain meshes did, that point is the witness.
    const double tol = 1e-10 * box.diagonal();
    const TopConfirmation top = confirm_top(grid, side, tab, r.distance, tol, coord);
    r.lower = lower_end(grid, side, tab, box, r);
    Vec3 origin = top.origin, offset = top.offset;
    uint32_t raised_target = top.target;
    bool raised = top.raised;
    if (!raised) raised = polish_ties(grid, side, tab, n, r.distance, tol, coord, origin, offset, raised_target);
    if (raised) {
        const Witness wd = witness_distance(grid.of(1 - side), origin, offset);
        const double lower = wd.lower - witness_rounding(wd.lower, box);
        if (lower > r.lower && wd.distance >= r.distance) {
            r.target = raised_target;
            r.distance = wd.distance;
            r.lower = std::min(wd.distance, lower);
            r.from_point = origin + offset;
            r.to_point = wd.to_point;
        }
    }
    r.upper = upper_end(top, r.distance);
    // A one-sided distance is never below its farthest vertex's distance.
    // (The vertices' distances were taken in world coordinates: rounding of their magnitude.)
    if (!(r.upper + 1e-13 * coord >= std::sqrt(tab.vertex_sq)))
        throw std::logic_error("internal error: one-sided distance " + format_g17(r.distance) + " (upper " +
                               format_g17(r.upper) + ") is below the farthest vertex distance " +
                               format_g17(std::sqrt(tab.vertex_sq)) + " (" + mode_name(mode) + " mode)");
}

}  // namespace hlens
