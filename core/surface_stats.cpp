// Surface statistics of the distance field (issue 9; Straub 2007 §5, "future work"): every
// target's full domain mesh integrated (integrals.h), percentiles by bisection on the exact area
// above t (surface_stats.h describes the passes).
#include "surface_stats.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "cascade.h"
#include "copies.h"
#include "hausdorff.h"
#include "integrals.h"
#include "parallel.h"
#include "target_solver.h"

namespace hlens {

namespace {

// One domain's share of the estimate of the distribution (world units): its area, its distances
// taken as spread uniformly over [lo, hi] (the uniform law with the domain's mean and variance of
// d, clipped to its range). Only where the percentiles' passes start: never in a result.
struct EstimatePiece { double area, lo, hi; };

using Partial = std::vector<std::pair<int, double>>;  // (level index, area above it), by level

// What the first pass keeps of one target: its integrals (world units), its distance range, and
// the area above each first-pass level inside that range (levels outside it are all or nothing).
struct TargetPass {
    TriangleStats tri;
    double dmin = 0;                              // a lower bound of d over the target
    Partial partial;                              // at the first pass's levels
    std::vector<EstimatePiece> estimate;          // per domain, when percentiles are asked for
    bool sliver = false;
    double sliver_area = 0;
    std::array<double, 3> corner_d{{0, 0, 0}};
    double err_area = 0, err_d2 = 0, err_d = 0;   // quadrature bounds and estimate (world units)
};

double triangle_area(const std::array<Vec3, 3>& c) { return 0.5 * norm(cross(c[1] - c[0], c[2] - c[0])); }

// The area above each level (world distances, ascending) inside [dmin, dmax): the levels at or
// above the maximum have none, those below dmin the whole area; only the others are clipped.
Partial partial_areas(const DomainMesh& m, double scale, double dmin, double dmax, const std::vector<double>& levels) {
    std::vector<double> t2;
    std::vector<int> index;
    for (size_t j = 0; j < levels.size(); ++j)
        if (levels[j] >= dmin && levels[j] < dmax) {
            t2.push_back(levels[j] * levels[j] / (scale * scale));
            index.push_back((int)j);
        }
    std::vector<double> a = area_above_levels(m, t2);
    Partial out;
    for (size_t k = 0; k < a.size(); ++k) out.push_back({index[k], a[k] * scale * scale});
    return out;
}

// Domain meshes kept from the first pass for the percentile passes, compacted (DomainMesh::compact:
// the live part only, about a sixth of the construction's arrays on a coarse target), up to a
// memory budget; the others are rebuilt (re-running the construction) in every pass that needs them.
struct MeshCache {
    std::vector<std::unique_ptr<DomainMesh>> mesh;
    std::vector<double> scale;
    std::atomic<size_t> bytes{0};
    size_t budget = size_t(1) << 30;
    explicit MeshCache(size_t n) : mesh(n), scale(n) {}
    static size_t size_of(const DomainMesh& m) {  // an estimate: the main arrays and the per-edge data
        return sizeof(DomainMesh) + m.edges().size() * (sizeof(DomainMesh::Edge) + 2 * sizeof(DomainMesh::HalfEdge) + 16) +
               m.faces().size() * (sizeof(DomainMesh::Face) + 24) + m.vertices().size() * sizeof(DomainMesh::Vertex);
    }
    // Keep a compacted copy of target t's finished mesh, if it fits.
    void keep(uint32_t t, const DomainMesh& m, double s) {
        if (t >= mesh.size()) return;  // no percentiles asked for: nothing kept
        auto c = std::make_unique<DomainMesh>(m);
        if (!c->compact()) return;
        const size_t sz = size_of(*c);
        if (bytes.fetch_add(sz) + sz > budget) { bytes.fetch_sub(sz); return; }
        mesh[t] = std::move(c);
        scale[t] = s;
    }
    // fn(mesh, scale) with target t's finished domain mesh.
    template <class Fn>
    void with_mesh(const VoxelGrid& grid, int side, uint32_t t, Fn&& fn) {
        if (mesh[t]) return fn(*mesh[t], scale[t]);
        TargetSolver ts(grid, side, t);
        ts.run();
        keep(t, *ts.domain_mesh(), ts.frame().scale);
        fn(*ts.domain_mesh(), ts.frame().scale);
    }
};

void add_estimate_pieces(const std::vector<FaceMoments>& faces, double s, std::vector<EstimatePiece>& out) {
    for (const FaceMoments& f : faces) {
        if (!(f.area > 0)) continue;
        const double mean = f.int_d / f.area, sd = std::sqrt(std::max(0.0, f.int_d2 / f.area - mean * mean));
        const double lo = std::sqrt(f.min_d2_lower), hi = std::sqrt(std::max(0.0, f.max_d2));
        const double a = std::clamp(mean - std::sqrt(3.0) * sd, lo, hi), b = std::clamp(mean + std::sqrt(3.0) * sd, lo, hi);
        out.push_back({f.area * s * s, a * s, std::max(a, b) * s});
    }
}

// A copy of a source triangle (copies.h): d = 0 on all of it, exactly. No construction: its area
// by cross product, nothing above any level. (A sliver copy stays a sliver, as solve_target has it.)
bool copy_pass(const std::array<Vec3, 3>& c, TargetPass& r) {
    if (TargetFrame::make(c).degenerate) return false;
    r.tri.area = triangle_area(c);
    r.estimate.push_back({r.tri.area, 0.0, 0.0});
    return true;
}

TargetPass solve_target(const VoxelGrid& grid, int side, uint32_t t, const std::vector<double>& levels, MeshCache& cache,
                        bool estimate, bool copy) {
    TargetPass r;
    if (copy && copy_pass(grid.mesh(side).corners(t), r)) return r;
    TargetSolver ts(grid, side, t);
    ts.run();
    const TargetFrame& fr = ts.frame();
    const double s = fr.scale;
    for (int k = 0; k < 3; ++k) r.corner_d[k] = std::sqrt(ts.direct_d2(fr.corners[k])) * s;
    r.tri.max = std::sqrt(ts.max_sq());
    const DomainMesh* dm = ts.domain_mesh();
    if (!dm) {
        r.sliver = true;
        r.sliver_area = triangle_area(grid.mesh(side).corners(t));
        return r;
    }
    std::vector<FaceMoments> faces;
    const DomainIntegrals di = domain_integrals(*dm, estimate ? &faces : nullptr);
    add_estimate_pieces(faces, s, r.estimate);
    r.tri.area = di.area * s * s;
    r.tri.int_d2 = di.int_d2 * s * s * s * s;
    r.tri.int_d = di.int_d * s * s * s;
    r.dmin = std::sqrt(di.min_d2_lower) * s;
    r.err_area = di.err_area * s * s;
    r.err_d2 = di.err_d2 * s * s * s * s;
    r.err_d = di.err_d * s * s * s;
    r.partial = partial_areas(*dm, s, r.dmin, r.tri.max, levels);
    if (r.dmin < r.tri.max) cache.keep(t, *dm, s);  // a percentile may lie in its range
    return r;
}

// Exact area above each level, summed over the targets in index order (deterministic).
// `partials` (one per target) instead of the first pass's own, if given.
std::vector<double> level_areas(const std::vector<TargetPass>& pass, const std::vector<double>& levels,
                                const std::vector<Partial>* partials = nullptr) {
    std::vector<double> A(levels.size(), 0.0);
    for (size_t t = 0; t < pass.size(); ++t) {
        const TargetPass& p = pass[t];
        if (p.sliver) continue;
        const Partial& part = partials ? (*partials)[t] : p.partial;
        size_t k = 0;
        for (size_t j = 0; j < levels.size(); ++j) {
            while (k < part.size() && part[k].first < (int)j) ++k;
            if (k < part.size() && part[k].first == (int)j) A[j] += part[k].second;
            else if (levels[j] < p.dmin) A[j] += p.tri.area;
        }
    }
    return A;
}

// Where the estimate of the distribution (the first pass's pieces) puts each goal: the distance
// above which that much area lies. Its area above t is piecewise linear in t (each piece adds its
// area for t below lo, a linear share on [lo, hi]), so one sweep over the pieces' ends, sorted,
// finds every goal. -1 where there is nothing to go by.
std::vector<double> estimate_levels(const std::vector<TargetPass>& pass, const std::vector<double>& goals) {
    struct End { double t, slope, jump; };  // at t: the slope of A changes by `slope`, A drops by `jump`
    std::vector<End> ends;
    double A = 0;
    for (const TargetPass& p : pass)
        for (const EstimatePiece& e : p.estimate) {
            A += e.area;
            if (e.hi > e.lo) ends.push_back({e.lo, -e.area / (e.hi - e.lo), 0}), ends.push_back({e.hi, e.area / (e.hi - e.lo), 0});
            else ends.push_back({e.lo, 0, e.area});
        }
    std::vector<double> out(goals.size(), -1.0);
    if (ends.empty()) return out;
    std::sort(ends.begin(), ends.end(), [](const End& x, const End& y) { return x.t < y.t; });
    double t = 0, slope = 0;  // A(t) on [t, next end) is A + slope (t' - t)
    for (const End& e : ends) {
        const double next = A + slope * (e.t - t);  // A just before e.t
        for (size_t k = 0; k < goals.size(); ++k)
            if (out[k] < 0 && next <= goals[k]) out[k] = slope < 0 ? t + (goals[k] - A) / slope : t;
        A = next - e.jump;
        t = e.t;
        slope += e.slope;
        for (size_t k = 0; k < goals.size(); ++k)
            if (out[k] < 0 && A <= goals[k]) out[k] = t;
    }
    return out;
}

// Every level whose exact area above is known, ascending: (t, A(t)).
using Known = std::vector<std::pair<double, double>>;

// t as a polynomial in A through the n points p (Neville), at A = goal; NaN where two points have
// the same area (A flat between them: no inverse).
double inverse_interpolate(const std::pair<double, double>* p, int n, double goal) {
    double t[4];
    for (int i = 0; i < n; ++i) t[i] = p[i].first;
    for (int m = 1; m < n; ++m)
        for (int i = 0; i + m < n; ++i) {
            const double a0 = p[i].second, a1 = p[i + m].second;
            if (!(a0 != a1)) return NAN;
            t[i] = ((goal - a1) * t[i] - (goal - a0) * t[i + 1]) / (a0 - a1);
        }
    return t[0];
}

// The percentiles by bisection: each starts bracketed by 0 and the maximum, and each pass clips the
// targets at a few levels inside the open brackets (Bracket::levels), then keeps the narrowest
// bracket the exact areas there certify.
struct Bracket {
    double lo, hi, goal;       // A(lo) > goal >= A(hi): the percentile lies in (lo, hi]
    double alo, ahi;           // A(lo), A(hi)
    bool done;
    double estimate = -1;      // where the first pass's estimate puts it (< 0: none)
    int kept_lo = 0, kept_hi = 0;  // passes in a row that moved only the other end (Illinois)
    double last_width = HUGE_VAL;  // hi - lo before the last pass
    // The next levels to clip at: a guess, and either side of it at distances delta and 4, 16 or
    // 32 delta. The first guess is the estimate, good to a few percent on real pairs (bunny: 0.2%
    // to 1.9%; delta 2.5% of it). Later ones interpolate t as a cubic in A through the bracket's
    // ends and the known levels next to them (Neville), delta twice its difference from the
    // quadratics through three of them (A is smooth but for small kinks). Where that fails (too
    // few levels known, A flat, the guess outside the bracket, an end kept twice), the regula falsi
    // point of the bracket with the Illinois rule (an end kept twice in a row counts half as far
    // from the goal), off the root by about |A''/A'| width^2 / 32 where A is smooth, taken as
    // width^2 / (2 guess) (A''/A' of the order of 1/t: 16 times that error). Once delta is within
    // two tolerances, the levels are 0.45 and 1.35 tolerances either side, so the next bracket is
    // narrower than one. The far levels and the middle (when the last pass did not halve the
    // bracket) bound the number of passes however A looks. The answer is certified by the exact
    // areas at the bracket's ends, however the levels were chosen.
    void levels(double width, const Known& known, std::vector<double>& out) const {
        const double mid = 0.5 * (lo + hi);
        double guess = NAN, delta = 0, far = 32;
        if (last_width == HUGE_VAL && estimate > lo && estimate < hi) {  // no pass yet
            guess = estimate;
            delta = 0.025 * estimate;
            far = 4;
        } else if (kept_lo < 2 && kept_hi < 2) {
            interpolated(known, guess, delta);
            far = 16;
        }
        if (!(guess > lo && guess < hi)) {
            far = 32;
            double fl = alo - goal, fh = ahi - goal;  // > 0, <= 0
            if (kept_lo >= 2) fl *= std::pow(0.5, kept_lo - 1);
            if (kept_hi >= 2) fh *= std::pow(0.5, kept_hi - 1);
            guess = fl - fh > 0 ? lo + (hi - lo) * fl / (fl - fh) : mid;
            delta = (hi - lo) * (hi - lo) / (2 * std::max(guess, 1e-300));
        }
        delta = std::min(delta, 0.25 * (hi - lo));
        if (delta <= 2 * width) delta = 0.45 * width, far = 3;
        for (double t : {guess - far * delta, guess - delta, guess + delta, guess + far * delta})
            if (t > lo && t < hi) out.push_back(t);
        if (hi - lo > 0.5 * last_width && mid > lo && mid < hi) out.push_back(mid);
    }
    // The cubic guess through the known levels around the bracket, and twice its distance from the
    // quadratic ones as delta; guess NaN if there are not three such levels with distinct areas.
    void interpolated(const Known& known, double& guess, double& delta) const {
        const auto it = std::lower_bound(known.begin(), known.end(), std::make_pair(lo, -HUGE_VAL));
        if (it == known.end() || it->first != lo || it + 1 == known.end() || (it + 1)->first != hi) return;
        const size_t i = (size_t)(it - known.begin());
        const size_t from = i > 0 ? i - 1 : i, to = std::min(known.size(), i + 3);  // [from, to): up to 4 points
        const int n = (int)(to - from);
        if (n < 3) return;
        const double g = inverse_interpolate(&known[from], n, goal);
        double err = 0;
        if (n == 4) {
            err = std::max(std::fabs(g - inverse_interpolate(&known[from], 3, goal)),
                           std::fabs(g - inverse_interpolate(&known[from + 1], 3, goal)));
        } else {
            err = std::fabs(g - inverse_interpolate(&known[i], 2, goal));
        }
        if (!std::isfinite(g) || !std::isfinite(err)) return;
        guess = g;
        delta = 2 * err;
    }
    // The narrowest bracket the exact areas A at `levels` (ascending) certify.
    void narrow(const std::vector<double>& levels, const std::vector<double>& A) {
        for (size_t j = 0; j < levels.size(); ++j) {
            if (levels[j] <= lo || levels[j] >= hi) continue;
            if (A[j] > goal) { lo = levels[j]; alo = A[j]; }
            else { hi = levels[j]; ahi = A[j]; break; }
        }
    }
    // After a pass: narrowed, and the counts of the Illinois rule and of the halving kept.
    void update(const std::vector<double>& levels, const std::vector<double>& A) {
        const double old_lo = lo, old_hi = hi;
        last_width = hi - lo;
        narrow(levels, A);
        kept_lo = lo == old_lo ? kept_lo + 1 : 0;
        kept_hi = hi == old_hi ? kept_hi + 1 : 0;
    }
};

// Targets whose distance range holds one of the levels: only these are clipped (the others are all
// above or all below each level).
std::vector<uint32_t> targets_at_levels(const std::vector<TargetPass>& pass, const std::vector<double>& levels) {
    std::vector<uint32_t> rerun;
    for (uint32_t t = 0; t < pass.size(); ++t) {
        if (pass[t].sliver) continue;
        const auto it = std::lower_bound(levels.begin(), levels.end(), pass[t].dmin);
        if (it != levels.end() && *it < pass[t].tri.max) rerun.push_back(t);
    }
    return rerun;
}

// One refinement pass at `levels` (ascending): the targets that hold one are clipped there (their
// kept domain meshes, or rebuilt), and each open bracket keeps what the exact areas certify.
std::vector<double> refine_brackets(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass,
                                    std::vector<Bracket>& br, const std::vector<double>& levels,
                                    const std::vector<uint32_t>& rerun, const StatsOptions& opt, MeshCache& cache) {
    std::vector<Partial> now(pass.size());  // the areas above the new levels, where clipped
    parallel_for(rerun.size(), resolve_threads(opt.threads), opt.cancel, [&](size_t i) {
        const TargetPass& p = pass[rerun[i]];
        cache.with_mesh(grid, side, rerun[i], [&](const DomainMesh& m, double scale) {
            now[rerun[i]] = partial_areas(m, scale, p.dmin, p.tri.max, levels);
        });
    });
    const std::vector<double> A = level_areas(pass, levels, &now);
    for (Bracket& b : br)
        if (!b.done) b.update(levels, A);
    return A;
}

// The area that may lie above each percentile.
std::vector<double> percentile_goals(const StatsOptions& opt, double area) {
    std::vector<double> goals;
    for (double p : opt.percentiles) goals.push_back((1 - p / 100) * area);
    return goals;
}

// `est`: estimate_levels of the goals, `first` and `first_area`: the first pass's levels (0 the
// first of them) and their exact areas above, `top`: the largest distance.
void percentiles(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass, const std::vector<double>& est,
                 const std::vector<double>& first, const std::vector<double>& first_area, double top,
                 const StatsOptions& opt, MeshCache& cache, SurfaceStats& out) {
    const std::vector<double> goals = percentile_goals(opt, out.area);
    const double a0 = first_area.front();  // above 0
    Known known;
    for (size_t j = 0; j < first.size(); ++j) known.push_back({first[j], first_area[j]});
    auto add_known = [&](double t, double a) {
        const auto it = std::lower_bound(known.begin(), known.end(), std::make_pair(t, -HUGE_VAL));
        if (it == known.end() || it->first != t) known.insert(it, {t, a});
    };
    add_known(top, 0.0);
    std::vector<Bracket> br;
    for (size_t k = 0; k < goals.size(); ++k) {
        Bracket b{0, top, goals[k], a0, 0, false};
        if (a0 <= goals[k]) { b.hi = 0; b.done = true; }  // d = 0 on enough of the surface
        b.estimate = est[k];
        if (!b.done) b.narrow(first, first_area);  // the first pass's levels (histogram, tolerance)
        br.push_back(b);
    }
    for (int guard = 0; guard < 200; ++guard) {
        std::vector<double> levels;
        for (Bracket& b : br) {
            b.done = b.done || b.hi - b.lo <= out.percentile_tolerance;
            if (!b.done) b.levels(out.percentile_tolerance, known, levels);
        }
        std::sort(levels.begin(), levels.end());
        levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
        if (levels.empty() || (opt.cancel && opt.cancel->load())) break;
        const std::vector<uint32_t> rerun = targets_at_levels(pass, levels);
        out.rerun_targets += rerun.size();
        ++out.percentile_passes;
        const std::vector<double> A = refine_brackets(grid, side, pass, br, levels, rerun, opt, cache);
        for (size_t j = 0; j < levels.size(); ++j) add_known(levels[j], A[j]);
    }
    out.cancelled = opt.cancel && opt.cancel->load();
    for (const Bracket& b : br) out.percentiles.push_back(b.hi);
}

// The first pass's levels (ascending): 0 (whether d = 0 on enough of the surface to make a
// percentile 0), the histogram's edges and the tolerance.
std::vector<double> first_pass_levels(const StatsOptions& opt, double dmax, std::vector<double>& hist_edges) {
    std::vector<double> levels{0.0};
    if (opt.histogram_bins > 0) {
        const double top = opt.histogram_max >= 0 ? opt.histogram_max : dmax;
        for (int k = 0; k <= opt.histogram_bins; ++k) hist_edges.push_back(top * k / opt.histogram_bins);
        levels.insert(levels.end(), hist_edges.begin(), hist_edges.end());
    }
    if (opt.tolerance >= 0) levels.push_back(opt.tolerance);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
}

double area_at(const std::vector<double>& levels, const std::vector<double>& A, double t) {
    return A[std::lower_bound(levels.begin(), levels.end(), t) - levels.begin()];
}

// The one-sided distance, without statistics: fast to find, and it sets the probe range.
double largest_distance(const VoxelGrid& grid, int side, const StatsOptions& opt);

}  // namespace

SurfaceStats surface_stats(const VoxelGrid& grid, int side, const StatsOptions& opt) {
    if (side != 0 && side != 1) throw std::invalid_argument("surface_stats: side must be 0 or 1");
    if (opt.histogram_bins < 0) throw std::invalid_argument("surface_stats: histogram_bins must be >= 0");
    for (double p : opt.percentiles)
        if (!(p >= 0 && p <= 100)) throw std::invalid_argument("surface_stats: percentiles must lie in [0, 100]");
    const TriangleMesh& M = grid.mesh(side);
    const size_t n = M.num_triangles();
    SurfaceStats out;
    // The distance itself is needed before the first pass only for the histogram's default top edge.
    const bool need_max = opt.histogram_bins > 0 && opt.histogram_max < 0;
    const double dmax = opt.known_max >= 0 ? opt.known_max : need_max ? largest_distance(grid, side, opt) : 0.0;
    std::vector<double> hist_edges;
    const std::vector<double> levels = first_pass_levels(opt, dmax, hist_edges);

    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    std::vector<TargetPass> pass(n);
    MeshCache cache(opt.percentiles.empty() ? 0 : n);
    std::vector<double> vertex_d2;
    farthest_vertex_sq(grid, side, resolve_threads(opt.threads), opt.cancel, nullptr, &vertex_d2);
    const std::vector<uint8_t> copy = copied_targets(grid, side, vertex_d2);
    ProgressTicker prog(opt.progress, n);
    parallel_for(n, resolve_threads(opt.threads), opt.cancel, [&](size_t t) {
        pass[t] = solve_target(grid, side, (uint32_t)t, levels, cache, !opt.percentiles.empty(), copy[t]);
        prog.tick();
    });
    if (opt.cancel && opt.cancel->load()) { out.cancelled = true; return out; }

    out.vertex_distance.assign(M.positions.size(), -1.0);
    out.triangles.resize(n);
    for (size_t t = 0; t < n; ++t) {
        const TargetPass& p = pass[t];
        out.triangles[t] = p.tri;
        out.max = std::max(out.max, p.tri.max);
        for (int k = 0; k < 3; ++k) out.vertex_distance[M.triangles[t][k]] = p.corner_d[k];
        if (p.sliver) { ++out.sliver_targets; out.sliver_area += p.sliver_area; continue; }
        out.area += p.tri.area;
        out.int_d += p.tri.int_d;
        out.int_d2 += p.tri.int_d2;
        out.err_area += p.err_area;
        out.err_d2 += p.err_d2;
        out.err_d += p.err_d;
    }
    const std::vector<double> A = level_areas(pass, levels);
    if (opt.histogram_bins > 0) {
        out.histogram_edges = hist_edges;
        // The area above each edge, made non-increasing: each level's area is summed on its own, so
        // an empty bin came out as -1e-16 (a triangle whose d = 2 - x, bins of 0.5). The bins then
        // telescope: they add up to the total area.
        std::vector<double> above(hist_edges.size());
        for (size_t k = 0; k < above.size(); ++k)
            above[k] = std::min(k ? above[k - 1] : out.area, std::max(0.0, area_at(levels, A, hist_edges[k])));
        for (int k = 0; k < opt.histogram_bins; ++k) out.histogram_area.push_back(above[k] - above[k + 1]);
        // What lies above the top edge (only when it is below the maximum) goes to the last bin.
        out.histogram_area.back() += above.back();
        // The first bin also holds the area where d = 0 exactly (touching or coincident surfaces).
        out.histogram_area.front() += out.area - above.front();
    }
    if (opt.tolerance >= 0) {
        out.area_above = area_at(levels, A, opt.tolerance);
        out.fraction_above = out.area > 0 ? out.area_above / out.area : 0;
    }
    const Box3 box = [&] { Box3 b = grid.mesh(0).bounds(); Box3 c = grid.mesh(1).bounds(); b.add(c.lo); b.add(c.hi); return b; }();
    out.percentile_tolerance = 1e-9 * box.diagonal();
    const auto t1 = Clock::now();
    out.seconds_first_pass = std::chrono::duration<double>(t1 - t0).count();
    if (!opt.percentiles.empty()) {
        const std::vector<double> est = estimate_levels(pass, percentile_goals(opt, out.area));
        for (TargetPass& p : pass) p.estimate = {};  // (one piece per domain: free it for the passes)
        percentiles(grid, side, pass, est, levels, A, std::max(dmax, out.max), opt, cache, out);
    }
    out.seconds_percentiles = std::chrono::duration<double>(Clock::now() - t1).count();
    return out;
}

namespace {
double largest_distance(const VoxelGrid& grid, int side, const StatsOptions& opt) {
    // The full construction of every target is run below anyway; here the maxima alone, by the
    // fast driver's culling, so the histogram's edges are known before the first pass.
    HausdorffOptions ho;
    ho.threads = opt.threads;
    ho.cancel = opt.cancel;
    return one_sided(grid, side, ho).distance;
}
}  // namespace

}  // namespace hlens
