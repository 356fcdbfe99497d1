// Surface statistics of the distance field (issue 9; Straub 2007 §5, "future work"): every
// target's full domain mesh integrated (integrals.h), percentiles by bisection on the exact area
// above t (surface_stats.h describes the two passes).
#include "surface_stats.h"

#include <algorithm>
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

TargetPass solve_target(const VoxelGrid& grid, int side, uint32_t t, const std::vector<double>& levels) {
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
    r.partial = partial_areas(*dm, s, r.dmin, r.tri.max, levels);
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
struct Bracket { double lo, hi, goal; bool done; };

void bisect_percentiles(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass, std::vector<Bracket>& br,
                        double width, const StatsOptions& opt, SurfaceStats& out) {
    // Targets whose range meets an open bracket: re-run, their domain meshes kept.
    std::vector<uint32_t> rerun;
    for (uint32_t t = 0; t < pass.size(); ++t) {
        if (pass[t].sliver) continue;
        for (const Bracket& b : br)
            if (!b.done && pass[t].dmin < b.hi && pass[t].tri.max > b.lo) { rerun.push_back(t); break; }
    }
    out.rerun_targets = rerun.size();
    std::vector<std::unique_ptr<TargetSolver>> kept(rerun.size());
    parallel_for(rerun.size(), resolve_threads(opt.threads), opt.cancel, [&](size_t i) {
        kept[i] = std::make_unique<TargetSolver>(grid, side, rerun[i]);
        kept[i]->run();
    });
    if (opt.cancel && opt.cancel->load()) { out.cancelled = true; return; }
    std::vector<double> above(rerun.size());
    for (Bracket& b : br) {
        while (!b.done && b.hi - b.lo > width) {
            const double mid = 0.5 * (b.lo + b.hi);
            double A = 0;  // the targets wholly above mid, then the kept ones clipped at mid
            for (const TargetPass& p : pass)
                if (!p.sliver && p.dmin > mid && !(p.dmin < b.hi && p.tri.max > b.lo)) A += p.tri.area;
            parallel_for(rerun.size(), resolve_threads(opt.threads), nullptr, [&](size_t i) {
                const TargetPass& p = pass[rerun[i]];
                above[i] = 0;
                if (!(p.dmin < b.hi && p.tri.max > b.lo)) return;  // counted above (or zero)
                const double s = kept[i]->frame().scale;
                auto part = partial_areas(*kept[i]->domain_mesh(), s, p.dmin, p.tri.max, {mid});
                above[i] = part.empty() ? (mid < p.dmin ? p.tri.area : 0.0) : part[0].second;
            });
            for (double a : above) A += a;
            (A > b.goal ? b.lo : b.hi) = mid;
        }
    }
}

void percentiles(const VoxelGrid& grid, int side, const std::vector<TargetPass>& pass, const std::vector<double>& probes,
                 const std::vector<double>& probe_area, const StatsOptions& opt, SurfaceStats& out) {
    std::vector<Bracket> br;
    for (double p : opt.percentiles) {
        const double goal = (1 - p / 100) * out.area;  // the area that may lie above the percentile
        Bracket b{0, probes.back(), goal, false};
        if (probe_area[0] <= goal) { b.hi = 0; b.done = true; }  // d = 0 on enough of the surface
        for (size_t j = 0; j < probes.size() && !b.done; ++j)
            if (probe_area[j] > goal) b.lo = probes[j];
            else { b.hi = probes[j]; break; }
        br.push_back(b);
    }
    bisect_percentiles(grid, side, pass, br, out.percentile_tolerance, opt, out);
    for (const Bracket& b : br) out.percentiles.push_back(b.hi);
}

// The probe levels (ascending): uniform in [0, max], the histogram edges and the tolerance.
std::vector<double> probe_levels(double dmax, const StatsOptions& opt, std::vector<double>& hist_edges) {
    std::vector<double> levels;
    for (int k = 0; k <= opt.probes; ++k) levels.push_back(dmax * k / opt.probes);
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
    const double dmax = largest_distance(grid, side, opt);
    std::vector<double> hist_edges;
    const std::vector<double> levels = probe_levels(dmax, opt, hist_edges);

    std::vector<TargetPass> pass(n);
    ProgressTicker prog(opt.progress, n);
    parallel_for(n, resolve_threads(opt.threads), opt.cancel, [&](size_t t) {
        pass[t] = solve_target(grid, side, (uint32_t)t, levels);
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
    if (!opt.percentiles.empty()) percentiles(grid, side, pass, probes, probe_area, opt, out);
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
