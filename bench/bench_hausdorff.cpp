// Benchmarks of the whole-mesh driver: paper mode against fast mode.
//
// Each pair is a shared mesh A and a copy B whose every vertex is moved along its vertex normal by a
// deterministic pseudo-random offset in [-1, 1] * 1e-3 of the bounding-box diagonal, so the distance
// is small but not trivial. Pairs:
//   nefertiti  about 100k triangles each (minutes; not run in CI)
//   spot       about 6k triangles each (seconds): hlens_bench --benchmark_filter=spot
// Reported: wall time (one iteration), and counters distance, exact_targets (both directions),
// triangles, and peak_MB: the peak resident set (VmHWM) of the run, reset before it when the kernel
// allows (/proc/self/clear_refs), otherwise the process peak so far.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include <hlens/hausdorff.h>
#include <hlens/mesh_io.h>
#include <hlens/surface_stats.h>
#include <hlens/target_solver.h>

#include "../tests/test_meshes.h"  // sliver_arc

using namespace hlens;

namespace {

const std::string kShared = HLENS_SHARED_MESHES;

uint64_t splitmix64(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Moves every used vertex along its (area-weighted) normal by u * 1e-3 * diagonal, u in [-1, 1].
TriangleMesh perturbed(const TriangleMesh& m) {
    TriangleMesh out = m;
    out.path = m.path + " (perturbed)";
    std::vector<Vec3> normal(m.positions.size());
    for (size_t t = 0; t < m.num_triangles(); ++t) {
        auto c = m.corners(t);
        Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
        for (uint32_t i : m.triangles[t]) normal[i] += n;
    }
    const double amplitude = 1e-3 * m.bounds().diagonal();
    for (size_t v = 0; v < m.positions.size(); ++v) {
        double len = norm(normal[v]);
        if (!(len > 0)) continue;
        double u = (double)(splitmix64(v) >> 11) * 0x1.0p-53 * 2.0 - 1.0;
        out.positions[v] += (amplitude * u / len) * normal[v];
    }
    return out;
}

struct Pair {
    TriangleMesh a, b;
};

// Loaded once per process and shared by both modes.
const Pair* pair_for(const std::string& file) {
    static std::map<std::string, std::unique_ptr<Pair>> cache;
    auto it = cache.find(file);
    if (it != cache.end()) return it->second.get();
    std::unique_ptr<Pair> p;
    try {
        TriangleMesh a = load_mesh(kShared + "/" + file);
        TriangleMesh b = perturbed(a);
        p = std::make_unique<Pair>(Pair{std::move(a), std::move(b)});
    } catch (const MeshError&) {
        p = nullptr;
    }
    return (cache[file] = std::move(p)).get();
}

// The kernel resets VmHWM when "5" is written to clear_refs (Linux 4.0+).
void reset_peak_memory() {
    std::ofstream f("/proc/self/clear_refs");
    if (f) f << "5";
}

double peak_memory_mb() {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;  // kB
    return 0;
}

void bench_pair(benchmark::State& state, const std::string& file, Mode mode) {
    const Pair* p = pair_for(file);
    if (!p) {
        state.SkipWithError(("cannot load " + kShared + "/" + file).c_str());
        return;
    }
    HausdorffOptions opt;
    opt.mode = mode;
    HausdorffResult r;
    reset_peak_memory();
    for (auto _ : state) {
        r = hausdorff(p->a, p->b, opt);
        benchmark::DoNotOptimize(r.hausdorff);
    }
    state.counters["peak_MB"] = peak_memory_mb();
    state.counters["distance"] = r.hausdorff;
    state.counters["exact_targets"] = (double)(r.a_to_b.exact_targets + r.b_to_a.exact_targets);
    state.counters["triangles"] = (double)(p->a.num_triangles() + p->b.num_triangles());
}

// The cost of the observer hooks: the full construction of the first 300 targets of spot against
// its perturbed copy, with no observer attached (no event is even built) and with one that only
// counts events (every event is built and delivered).
void bench_observer(benchmark::State& state, bool observe) {
    const Pair* p = pair_for("spot.obj");
    if (!p) {
        state.SkipWithError("spot.obj not found");
        return;
    }
    VoxelGrid grid(p->a, p->b);
    long events = 0;
    for (auto _ : state) {
        for (uint32_t t = 0; t < 300; ++t) {
            TargetSolver ts(grid, 0, t);
            if (observe) ts.on_event([&](const Event&) { ++events; });
            ts.run();
            benchmark::DoNotOptimize(ts.max_sq());
        }
    }
    state.counters["events_per_iteration"] = observe ? (double)events / state.iterations() : 0.0;
}

void register_pair(const std::string& name, const std::string& file) {
    for (Mode mode : {Mode::Paper, Mode::Fast}) {
        benchmark::RegisterBenchmark((name + "/" + mode_name(mode)).c_str(),
                                     [file, mode](benchmark::State& s) { bench_pair(s, file, mode); })
            ->UseRealTime()
            ->Unit(benchmark::kSecond)
            ->Iterations(1);
    }
}

// ---- exact surface statistics (issue 9): bunny against its 10% simplification, both directions.
// The simplified copy is made by bench/make_pairs.cpp (OpenMesh's quadric decimater):
//   hlens_make_pairs simplify ../shared/meshes/bunny.ply PAIRS/bunny-10.ply 0.1
// with PAIRS from $HLENS_BENCH_PAIRS (default: the current directory). Three runs of the same pair:
// the plain distance (fast mode), paper mode (every target's full construction, what the
// statistics need) and the statistics (percentiles, a 10-bin histogram and a tolerance).
const Pair* simplified_bunny() {
    static std::unique_ptr<Pair> p;
    static bool tried = false;
    if (tried) return p.get();
    tried = true;
    const char* dir = std::getenv("HLENS_BENCH_PAIRS");
    try {
        TriangleMesh a = load_mesh(kShared + "/bunny.ply");
        TriangleMesh b = load_mesh(std::string(dir ? dir : ".") + "/bunny-10.ply");
        p = std::make_unique<Pair>(Pair{std::move(a), std::move(b)});
    } catch (const MeshError&) {
        p = nullptr;
    }
    return p.get();
}

void bench_stats(benchmark::State& state, int what) {  // 0 plain (fast), 1 paper, 2 statistics
    const Pair* p = simplified_bunny();
    if (!p) {
        state.SkipWithError("bunny-10.ply not found: run hlens_make_pairs simplify (see bench_hausdorff.cpp)");
        return;
    }
    reset_peak_memory();
    double mean_ab = 0, mean_ba = 0;
    for (auto _ : state) {
        if (what < 2) {
            HausdorffOptions opt;
            opt.mode = what == 0 ? Mode::Fast : Mode::Paper;
            benchmark::DoNotOptimize(hausdorff(p->a, p->b, opt).hausdorff);
            continue;
        }
        const HausdorffResult r = hausdorff(p->a, p->b);
        VoxelGrid grid(p->a, p->b);
        for (int side = 0; side < 2; ++side) {
            StatsOptions o;
            o.histogram_bins = 10;
            o.known_max = (side == 0 ? r.a_to_b : r.b_to_a).distance;
            o.tolerance = 0.5 * o.known_max;
            (side == 0 ? mean_ab : mean_ba) = surface_stats(grid, side, o).mean();
        }
    }
    state.counters["peak_MB"] = peak_memory_mb();
    if (what == 2) {
        state.counters["mean_ab"] = mean_ab;
        state.counters["mean_ba"] = mean_ba;
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_pair("spot", "spot.obj");
    register_pair("nefertiti", "nefertiti.obj");
    benchmark::RegisterBenchmark("observer/none", [](benchmark::State& s) { bench_observer(s, false); })->Unit(benchmark::kMillisecond)->MinTime(2.0);
    benchmark::RegisterBenchmark("observer/counting", [](benchmark::State& s) { bench_observer(s, true); })->Unit(benchmark::kMillisecond)->MinTime(2.0);
    const char* stats_names[] = {"stats/bunny-10/plain", "stats/bunny-10/paper", "stats/bunny-10/stats"};
    for (int what = 0; what < 3; ++what)
        benchmark::RegisterBenchmark(stats_names[what], [what](benchmark::State& s) { bench_stats(s, what); })
            ->UseRealTime()
            ->Unit(benchmark::kSecond)
            ->Iterations(1);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

// Building the voxel grid of a pair (both meshes): the time VoxelGrid.BuildTwoLargeMeshes (tests/)
// no longer asserts. hlens_bench --benchmark_filter=voxel_grid
static void voxel_grid(benchmark::State& state, const char* file) {
    const Pair* p = pair_for(file);
    if (!p) {
        state.SkipWithError((std::string("cannot load ") + kShared + "/" + file).c_str());
        return;
    }
    size_t voxels = 0, assignments = 0;
    for (auto _ : state) {
        VoxelGrid grid(p->a, p->b);
        voxels = grid.of(0).num_voxels() + grid.of(1).num_voxels();
        assignments = grid.of(0).num_assignments() + grid.of(1).num_assignments();
        benchmark::DoNotOptimize(grid);
    }
    state.counters["voxels"] = (double)voxels;
    state.counters["assignments"] = (double)assignments;
    state.counters["triangles"] = (double)(p->a.num_triangles() + p->b.num_triangles());
}
BENCHMARK_CAPTURE(voxel_grid, nefertiti, "nefertiti.obj")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(voxel_grid, spot, "spot.obj")->Unit(benchmark::kMillisecond)->UseRealTime();

// A degenerate target's maximum (TargetSolver::degenerate_maximum): a segment 9 from a strip of n
// slivers on a circle, every one within the search radius, its maximum flat (the configuration of
// tests/test_solver.cpp, SolverRandom.SegmentUnderManySliversIsNotCubic). Minutes at n = 2,500
// before the envelope's bins and the doubling schedule. hlens_bench --benchmark_filter=degenerate
static void degenerate_segment(benchmark::State& state) {
    const int n = (int)state.range(0);
    const double R = 18, cz = 9, span = 2.5 / R;
    const TriangleMesh A = make_mesh({{-1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}, "segment");
    const TriangleMesh B = hlens_test::sliver_arc(n, R, cz, span);
    const VoxelGrid grid(A, B);
    size_t evaluations = 0;
    for (auto _ : state) {
        TargetSolver ts(grid, 0, 0);
        ts.run();
        evaluations = ts.distance_evaluations();
        benchmark::DoNotOptimize(ts.max_sq());
    }
    state.counters["distance_evaluations"] = (double)evaluations;
}
BENCHMARK(degenerate_segment)->Arg(250)->Arg(2500)->Unit(benchmark::kMillisecond)->UseRealTime();
