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

#include "hausdorff.h"
#include "integrals.h"
#include "parallel.h"
#include "target_solver.h"

namespace hlens {

namespace {

// What the first pass keeps of one target: its integrals (world units), its distance range, and
// the area above each probe level inside that range (levels outside it are all or nothing).
struct TargetPass {
    TriangleStats tri;
    double dmin = 0;                              // a lower bound of d over the target
    std::vector<std::pair<int, double>> partial;  // (level index, area above it)
    bool sliver = false;
    double sliver_area = 0;
    std::array<double, 3> corner_d{{0, 0, 0}};
    double err_area = 0, err_d2 = 0, err_d = 0;   // quadrature bounds and estimate (world units)
};

double triangle_area(const std::array<Vec3, 3>& c) { return 0.5 * norm(cross(c[1] - c[0], c[2] - c[0])); }

// The area above each level (world distances, ascending) inside [dmin, dmax): the levels at or
// above the maximum have none, those below dmin the whole area; only the others are clipped.
std::vector<std::pair<int, double>> partial_areas(const DomainMesh& m, double scale, double dmin, double dmax,
                                                  const std::vector<double>& levels) {
    std::vector<double> t2;
    std::vector<int> index;
    for (size_t j = 0; j < levels.size(); ++j)
        if (levels[j] >= dmin && levels[j] < dmax) {
            t2.push_back(levels[j] * levels[j] / (scale * scale));
            index.push_back((int)j);
        }
    std::vector<double> a = area_above_levels(m, t2);
    std::vector<std::pair<int, double>> out;
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

TargetPass solve_target(const VoxelGrid& grid, int side, uint32_t t, const std::vector<double>& levels, MeshCache& cache) {
    TargetPass r;
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
    const DomainIntegrals di = domain_integrals(*dm);
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
std::vector<double> level_areas(const std::vector<TargetPass>& pass, const std::vector<double>& levels) {
    std::vector<double> A(levels.size(), 0.0);
    for (const TargetPass& p : pass) {
        if (p.sliver) continue;
        size_t k = 0;
        for (size_t j = 0; j < levels.size(); ++j) {
            while (k < p.partial.size() && p.partial[k].first < (int)j) ++k;
            if (k < p.partial.size() && p.partial[k].first == (int)j) A[j] += p.partial[k].second;
            else if (levels[j] < p.dmin) A[j] += p.tri.area;
        }
    }
    return A;
}

// The percentiles by bisection (second pass): each starts bracketed by two probe levels.
struct Bracket {
    double lo, hi, goal;       // A(lo) > goal >= A(hi): the percentile lies in (lo, hi]
    double alo, ahi;           // A(lo), A(hi)
    bool done;
    int kept_lo = 0, kept_hi = 0;  // passes in a row that moved only the other end (Illinois)
    double last_width = HUGE_VAL;  // hi - lo before the last pass
    // The next levels to clip at: either side (width/2, 32 width, ...) of the regula falsi point, with the
    // Illinois rule (an end kept twice in a row counts half as far from the goal) so the
    // convergence is superlinear, and the middle when the last pass did not halve the bracket.
    void levels(double width, std::vector<double>& out) const {
        double fl = alo - goal, fh = ahi - goal;  // > 0, <= 0
        if (kept_lo >= 2) fl *= std::pow(0.5, kept_lo - 1);
        if (kept_hi >= 2) fh *= std::pow(0.5, kept_hi - 1);
        const double mid = 0.5 * (lo + hi);
        const double guess = fl - fh > 0 ? lo + (hi - lo) * fl / (fl - fh) : mid;
        for (double step = 0.5 * width; step < hi - lo; step *= 64)  // a sparse ladder around it
            for (double t : {guess - step, guess + step})
                if (t > lo && t < hi) out.push_back(t);
        if (hi - lo > 0.5 * last_width && mid > lo && mid < hi) out.push_back(mid);
    }
    void update(const std::vector<double>& levels, const std::vector<double>& A) {
        const double old_lo = lo, old_hi = hi;
        last_width = hi - lo;
        for (size_t j = 0; j < levels.size(); ++j) {
            if (levels[j] <= lo || levels[j] >= hi) continue;
            if (A[j] > goal) { lo = levels[j]; alo = A[j]; }
            else { hi = levels[j]; ahi = A[j]; break; }
        }
        kept_lo = lo == old_lo ? kept_lo + 1 : 0;
        kept_hi = hi == old_hi ? kept_hi + 1 : 0;
    }
};

// Targets whose distance range meets an open bracket: only these can tell the brackets' ends apart.
std::vector<uint32_t> targets_in_brackets(const std::vector<TargetPass>& pass, const std::vector<Bracket>& br) {
    std::vector<uint32_t> rerun;
    for (uint32_t t = 0; t < pass.size(); ++t) {
        if (pass[t].sliver) continue;
        for (const Bracket& b : br)
            if (!b.done && pass[t].dmin < b.hi && pass[t].tri.max > b.lo) { rerun.push_back(t); break; }
    }
    return rerun;
}

// One refinement pass: the targets that meet an open bracket are re-run and clipped at the few
// levels Bracket::levels asks for (A is smooth but for small kinks, so the regula falsi point is
// close and the two levels either side of it usually close the bracket within a few passes; the
// middle, when a pass did not halve a bracket, bounds the number of passes whatever A looks like).
void refine_brackets(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass, std::vector<Bracket>& br,
                     const std::vector<uint32_t>& rerun, double width, const StatsOptions& opt, MeshCache& cache) {
    std::vector<double> levels;
    for (const Bracket& b : br)
        if (!b.done) b.levels(width, levels);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    std::vector<TargetPass> now = pass;  // the same targets, with partial areas at the new levels
    for (TargetPass& p : now) p.partial.clear();
    parallel_for(rerun.size(), resolve_threads(opt.threads), opt.cancel, [&](size_t i) {
        TargetPass& p = now[rerun[i]];
        cache.with_mesh(grid, side, rerun[i], [&](const DomainMesh& m, double scale) {
            p.partial = partial_areas(m, scale, p.dmin, p.tri.max, levels);
        });
    });
    const std::vector<double> A = level_areas(now, levels);
    for (Bracket& b : br)
        if (!b.done) b.update(levels, A);
}

void percentiles(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass, const std::vector<double>& probes,
                 const std::vector<double>& probe_area, const StatsOptions& opt, MeshCache& cache, SurfaceStats& out) {
    std::vector<Bracket> br;
    for (double p : opt.percentiles) {
        const double goal = (1 - p / 100) * out.area;  // the area that may lie above the percentile
        Bracket b{0, std::max(probes.back(), out.max), goal, out.area, 0, false};
        if (probe_area[0] <= goal) { b.hi = 0; b.done = true; }  // d = 0 on enough of the surface
        for (size_t j = 0; j < probes.size() && !b.done; ++j)
            if (probe_area[j] > goal) { b.lo = probes[j]; b.alo = probe_area[j]; }
            else { b.hi = probes[j]; b.ahi = probe_area[j]; break; }
        br.push_back(b);
    }
    // Narrow the brackets by passes over the targets that meet them.
    for (;;) {
        for (Bracket& b : br) b.done = b.done || b.hi - b.lo <= out.percentile_tolerance;
        const std::vector<uint32_t> rerun = targets_in_brackets(pass, br);
        if (rerun.empty() || (opt.cancel && opt.cancel->load())) break;
        out.rerun_targets += rerun.size();
        ++out.percentile_passes;
        refine_brackets(grid, side, pass, br, rerun, out.percentile_tolerance, opt, cache);
    }
    out.cancelled = opt.cancel && opt.cancel->load();
    for (const Bracket& b : br) out.percentiles.push_back(b.hi);
}

// The probe levels (ascending): uniform in [0, max], the histogram edges and the tolerance.
std::vector<double> probe_levels(double dmax, const StatsOptions& opt, std::vector<double>& hist_edges) {
    std::vector<double> levels;
    // Uniform, and geometric towards 0 (most of a surface is usually much nearer than the maximum).
    for (int k = 0; k <= opt.probes; ++k) levels.push_back(dmax * k / opt.probes);
    for (int k = 1; k <= 24; ++k) levels.push_back(dmax * std::pow(2.0, -0.5 * k));
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
    if (opt.probes < 1) throw std::invalid_argument("surface_stats: probes must be >= 1");
    for (double p : opt.percentiles)
        if (!(p >= 0 && p <= 100)) throw std::invalid_argument("surface_stats: percentiles must lie in [0, 100]");
    const TriangleMesh& M = grid.mesh(side);
    const size_t n = M.num_triangles();
    SurfaceStats out;
    const double dmax = opt.known_max >= 0 ? opt.known_max : largest_distance(grid, side, opt);
    std::vector<double> hist_edges;
    const std::vector<double> levels = probe_levels(dmax, opt, hist_edges);

    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    std::vector<TargetPass> pass(n);
    MeshCache cache(opt.percentiles.empty() ? 0 : n);
    ProgressTicker prog(opt.progress, n);
    parallel_for(n, resolve_threads(opt.threads), opt.cancel, [&](size_t t) {
        pass[t] = solve_target(grid, side, (uint32_t)t, levels, cache);
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
        for (int k = 0; k < opt.histogram_bins; ++k)
            out.histogram_area.push_back(area_at(levels, A, hist_edges[k]) - area_at(levels, A, hist_edges[k + 1]));
        // What lies above the top edge (only when it is below the maximum) goes to the last bin.
        out.histogram_area.back() += area_at(levels, A, hist_edges.back());
        // The first bin also holds the area where d = 0 exactly (touching or coincident surfaces).
        out.histogram_area.front() += out.area - area_at(levels, A, 0.0);
    }
    if (opt.tolerance >= 0) {
        out.area_above = area_at(levels, A, opt.tolerance);
        out.fraction_above = out.area > 0 ? out.area_above / out.area : 0;
    }
    const Box3 box = [&] { Box3 b = grid.mesh(0).bounds(); Box3 c = grid.mesh(1).bounds(); b.add(c.lo); b.add(c.hi); return b; }();
    out.percentile_tolerance = 1e-9 * box.diagonal();
    std::vector<double> probes, probe_area;
    for (size_t j = 0; j < levels.size(); ++j) { probes.push_back(levels[j]); probe_area.push_back(A[j]); }
    const auto t1 = Clock::now();
    out.seconds_first_pass = std::chrono::duration<double>(t1 - t0).count();
    if (!opt.percentiles.empty()) percentiles(grid, side, pass, probes, probe_area, opt, cache, out);
    out.seconds_percentiles = std::chrono::duration<double>(Clock::now() - t1).count();
    return out;
}

namespace {
double largest_distance(const VoxelGrid& grid, int side, const StatsOptions& opt) {
    // The full construction of every target is run below anyway; here the maxima alone, by the
    // fast driver's culling, so the probes span [0, h] before the first pass.
    HausdorffOptions ho;
    ho.threads = opt.threads;
    ho.cancel = opt.cancel;
    return one_sided(grid, side, ho).distance;
}
}  // namespace

}  // namespace hlens
