// hlens-cli: the command-line front end of Hausdorff Lens.
//
//   hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld] [--verify]
//                          [--units NAME] [--stats] [--histogram N] [--tolerance T] [--export-errors PATH.ply]
//   hlens-cli trace A B --target I [--json] [--no-weld]
//   hlens-cli batch REFERENCE FILE... [--json] [--tolerance T] [--jobs N] [--units NAME] [--stats] ...
//   hlens-cli --help | help
//
// `distance` prints h(A,B), h(B,A) and the Hausdorff distance (core/hausdorff.h); `trace` runs one
// target triangle of A with core/target_solver.h and prints every event as it happens, one per line.
// `batch` compares one reference against many files (app/batch.h), one result line per pair.
// Exit codes: 0 success, 2 bad usage or bad input (one line "hlens-cli: <message>" on stderr),
// 3 --verify disagreement, 4 not within --tolerance (batch: a pair beyond it), 1 anything unexpected.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <hlens/bounds.h>
#include <hlens/certificate.h>
#include <hlens/hausdorff.h>
#include <hlens/mesh.h>
#include <hlens/mesh_io.h>
#include <hlens/parallel.h>
#include <hlens/surface_stats.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>

#include "batch.h"
#include "json_value.h"
#include "report.h"

using namespace hlens;

namespace {

const char* kUsage =
    "usage:\n"
    "  hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld] [--verify]\n"
    "                     [--units NAME] [--stats] [--histogram N] [--tolerance T] [--export-errors PATH.ply]\n"
    "  hlens-cli trace A B --target I [--json] [--no-weld]\n"
    "  hlens-cli batch REFERENCE FILE... [--json] [--tolerance T] [--jobs N] [--one-sided] [--mode paper|fast]\n"
    "                     [--threads N] [--no-weld] [--units NAME] [--stats] [--histogram N]\n"
    "  hlens-cli --help | help\n"
    "\n"
    "distance   exact Hausdorff distance between the triangle meshes A and B (Straub 2007):\n"
    "           h(A,B), h(B,A) and max of both, each with its witness points and a certified interval\n"
    "  --json        print one JSON object instead of the readable summary\n"
    "  --one-sided   compute h(A,B) only\n"
    "  --mode M      paper: solve every target triangle; fast (default): skip targets that provably\n"
    "                cannot hold the maximum (same result)\n"
    "  --threads N   worker threads, N >= 1 (default: all cores)\n"
    "  --no-weld     keep vertices as read (default: merge vertices with identical coordinates)\n"
    "  --verify      also bracket each one-sided distance independently, by Lipschitz subdivision of\n"
    "                the measured mesh (to 1e-4 of the bounding-box diagonal), and check that the\n"
    "                exact value lies in the bracket (exit code 3 if it does not)\n"
    "  --units NAME  a unit label, passed through to the output (\"units\"); \"relative\" values are\n"
    "                divided by the diagonal of the bounding box of both meshes together\n"
    "  --stats       exact surface statistics per direction: area, mean and RMS distance, the 50/90/95/99th\n"
    "                area-weighted percentiles (the full construction of every triangle: slower)\n"
    "  --histogram N with --stats: the area per distance bin, N bins from 0 to the largest distance\n"
    "  --tolerance T within_tolerance: is the distance at most T? (exit code 4 if not); with --stats also\n"
    "                the area and fraction of each surface farther than T; without, the run stops as soon\n"
    "                as a vertex farther than T is found\n"
    "  --export-errors PATH.ply  the measured mesh with its error map (per-face max/mean/RMS distance,\n"
    "                per-vertex distance, as PLY 'quality'): PATH-ab.ply and PATH-ba.ply, or PATH.ply\n"
    "                with --one-sided\n"
    "\n"
    "trace      run target triangle I of A against B and print every event of the solver as it\n"
    "           happens (one line each), then a final summary line\n"
    "  --target I    index of the target triangle of A (0-based), required\n"
    "  --json        one JSON object per line\n"
    "\n"
    "batch      compare REFERENCE (as A) with each FILE (as B), printing one line per pair as it\n"
    "           finishes (a file that fails gets a line with its error; the others go on), then a\n"
    "           summary line; --json, --one-sided, --mode, --threads, --no-weld, --units, --stats and\n"
    "           --histogram of distance apply to every pair, and\n"
    "  --tolerance T exit code 4 if the Hausdorff distance (h(A,B) with --one-sided) of a pair exceeds T\n"
    "                (\"exceeds\" in its line; every pair is computed in full; with --stats also the\n"
    "                area and fraction of each surface farther than T)\n"
    "  --jobs N      compare N pairs at the same time (default 1); --threads is then per pair\n"
    "                (default: all cores divided by N)\n"
    "\n"
    "formats: .obj .ply .stl .off .gltf .glb\n"
    "exit codes: 0 success, 2 bad usage or bad input (batch: a file failed), 3 --verify found a\n"
    "            disagreement, 4 not within --tolerance (batch: a pair exceeds it; 2 wins over 4),\n"
    "            1 unexpected error\n";

// Bad usage or bad input: exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void print_line(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
}

// ---------------------------------------------------------------- command line

struct Args {
    std::string command;
    std::vector<std::string> files;
    bool json = false, one_sided = false, weld = true, verify = false;
    bool stats = false;                  // distance: --stats, --histogram, --export-errors (issue 9)
    int histogram = 0;
    std::string export_errors;
    Mode mode = Mode::Fast;
    int threads = 0;          // 0: all cores
    int jobs = 1;             // batch: pairs at a time
    double tolerance = -1;    // < 0 when not given (distance: the verdict; batch: per pair)
    std::string units;
    long long target = -1;
    bool has_target = false;
    bool help = false;
};

long long parse_integer(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE)
        throw UsageError(option + " needs an integer, got '" + text + "'");
    return v;
}

double parse_number(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw UsageError(option + " needs a number, got '" + text + "'");
    return v;
}

// The options of issue 9 that only distance takes (statistics, error map); true if `w` is one of them.
template <class TakeValue>
bool parse_stats_option(Args& a, const std::string& w, bool has_value, TakeValue& take_value) {
    if (w == "--stats") {
        if (has_value) throw UsageError("--stats takes no value");
        a.stats = true;
    } else if (w == "--histogram") {
        long long n = parse_integer("--histogram", take_value());
        if (n < 1 || n > kMaxHistogramBins)
            throw UsageError("--histogram must be between 1 and " + std::to_string(kMaxHistogramBins) + ", got " +
                             std::to_string(n));
        a.histogram = (int)n;
    } else if (w == "--export-errors") {
        a.export_errors = take_value();
        const std::string& e = a.export_errors;
        if (e.size() < 5 || (e.substr(e.size() - 4) != ".ply" && e.substr(e.size() - 4) != ".PLY"))
            throw UsageError("--export-errors needs a path ending in .ply, got '" + e + "'");
    } else {
        return false;
    }
    return true;
}

Args parse_args(int argc, char** argv) {
    Args a;
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty()) throw UsageError("missing command (see hlens-cli --help)");
    for (const std::string& w : words)
        if (w == "--help" || w == "-h") { a.help = true; return a; }
    a.command = words[0];
    if (a.command == "help") { a.help = true; return a; }
    if (a.command != "distance" && a.command != "trace" && a.command != "batch")
        throw UsageError("unknown command '" + a.command + "' (see hlens-cli --help)");
    const bool batch = a.command == "batch";
    const bool distance = a.command == "distance" || batch;  // batch takes distance's options

    for (size_t k = 1; k < words.size(); ++k) {
        std::string w = words[k], value;
        bool has_value = false;
        if (w.rfind("--", 0) == 0) {
            size_t eq = w.find('=');
            if (eq != std::string::npos) { value = w.substr(eq + 1); w = w.substr(0, eq); has_value = true; }
        }
        auto take_value = [&]() -> std::string {
            if (has_value) return value;
            if (k + 1 >= words.size()) throw UsageError(w + " needs a value");
            return words[++k];
        };
        auto no_value = [&] {
            if (has_value) throw UsageError(w + " takes no value");
        };
        if (w == "--json") { no_value(); a.json = true; }
        else if (w == "--no-weld") { no_value(); a.weld = false; }
        else if (distance && w == "--one-sided") { no_value(); a.one_sided = true; }
        else if (distance && w == "--verify") { no_value(); a.verify = true; }
        else if (distance && w == "--mode") {
            std::string m = take_value();
            if (m == "paper") a.mode = Mode::Paper;
            else if (m == "fast") a.mode = Mode::Fast;
            else throw UsageError("unknown --mode '" + m + "' (paper or fast)");
        } else if (distance && w == "--threads") {
            long long n = parse_integer("--threads", take_value());
            if (n < 1 || n > 4096) throw UsageError("--threads must be between 1 and 4096, got " + std::to_string(n));
            a.threads = (int)n;
        } else if (distance && w == "--units") {
            a.units = take_value();
        } else if (distance && w == "--tolerance") {
            a.tolerance = parse_number("--tolerance", take_value());
            if (a.tolerance < 0) throw UsageError("--tolerance must be >= 0, got " + format_double(a.tolerance, 17));
        } else if (batch && w == "--jobs") {
            long long n = parse_integer("--jobs", take_value());
            if (n < 1 || n > 4096) throw UsageError("--jobs must be between 1 and 4096, got " + std::to_string(n));
            a.jobs = (int)n;
        } else if (distance && parse_stats_option(a, w, has_value, take_value)) {
        } else if (!distance && w == "--target") {
            a.target = parse_integer("--target", take_value());
            a.has_target = true;
        } else if (w.size() > 1 && w[0] == '-') {
            throw UsageError("unknown option '" + w + "' for " + a.command + " (see hlens-cli --help)");
        } else {
            a.files.push_back(words[k]);
        }
    }
    if (a.histogram > 0 && !a.stats) throw UsageError("--histogram needs --stats");
    if (batch) {
        if (a.files.size() < 2)
            throw UsageError("batch needs a reference and at least one mesh file (see hlens-cli --help)");
        if (a.verify) throw UsageError("--verify is not available for batch");
        if (!a.export_errors.empty()) throw UsageError("--export-errors is not available for batch");
        return a;
    }
    if (a.files.size() != 2)
        throw UsageError(a.command + " needs two mesh files, got " + std::to_string(a.files.size()) +
                         " (see hlens-cli --help)");
    if (!distance && !a.has_target) throw UsageError("trace needs --target I");
    return a;
}

// ---------------------------------------------------------------- progress bar

// Drawn on stderr (a terminal) once a run takes over a second, at most 10 times a second.
// HausdorffOptions::progress is called from worker threads with the fraction of the current
// direction; a->b runs first, so a fraction falling back well below what was seen means b->a began.
class ProgressBar {
public:
    void update(double fraction) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (fraction < seen_ - 0.5) { direction_ = 1; seen_ = 0; }
        seen_ = std::max(seen_, fraction);
        auto now = Clock::now();
        double elapsed = seconds(start_, now);
        if (elapsed < 1.0 || (drawn_ && seconds(last_draw_, now) < 0.1)) return;
        last_draw_ = now;
        drawn_ = true;
        const int width = 30;
        int filled = std::clamp((int)std::lround(seen_ * width), 0, width);
        std::fprintf(stderr, "\r\033[K%s [%s%s] %5.1f%%  %.1f s", direction_ == 0 ? "a->b" : "b->a",
                     std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), 100.0 * seen_,
                     elapsed);
        std::fflush(stderr);
    }
    void clear() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (drawn_) std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
        drawn_ = false;
    }

private:
    using Clock = std::chrono::steady_clock;
    static double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
    std::mutex mutex_;
    Clock::time_point start_ = Clock::now(), last_draw_;
    bool drawn_ = false;
    int direction_ = 0;
    double seen_ = 0;
};

// ---------------------------------------------------------------- distance

std::string g(double v, int digits = 15) { return format_double(v, digits); }
std::string point_text(const Vec3& p) { return "(" + g(p.x, 10) + ", " + g(p.y, 10) + ", " + g(p.z, 10) + ")"; }

void print_mesh_summary(const char* name, const TriangleMesh& m) {
    std::printf("%s: %s\n   %zu vertices (%zu used), %zu triangles\n", name, m.path.c_str(), m.positions.size(),
                m.num_used_vertices(), m.num_triangles());
}

// "0.1494 (2.4% of the diagonal)": the relative value as report.h computes it.
std::string relative_text(double distance, double diagonal) {
    return diagonal > 0 ? " (" + g(100 * distance / diagonal, 4) + "% of the diagonal)" : "";
}

void print_one_sided(const char* title, const char* from, const char* to, const OneSidedResult& r, size_t targets,
                     double diagonal) {
    std::printf("%s = %s%s\n", title, g(r.distance).c_str(), relative_text(r.distance, diagonal).c_str());
    std::printf("   certified interval [%s, %s]\n", g(r.lower).c_str(), g(r.upper).c_str());
    std::printf("   witness: triangle %u of %s, point %s\n", r.target, from, point_text(r.from_point).c_str());
    std::printf("            nearest point of %s %s\n", to, point_text(r.to_point).c_str());
    std::printf("   exact targets: %zu of %zu (%zu exact solves), %.3f s\n", r.exact_targets, targets, r.exact_solves, r.seconds);
}

DistanceReportOptions report_options(const Args& args, int threads) {
    DistanceReportOptions o;
    o.one_sided = args.one_sided;
    o.mode = args.mode;
    o.threads = threads;
    o.units = args.units;
    o.tolerance = args.tolerance;
    o.verdict = args.command == "distance";
    return o;
}

// ---------------------------------------------------------------- statistics (issue 9)

// The options of surface_stats() that --stats, --histogram and --tolerance give (distance and
// batch); the error map alone needs no percentiles and no tolerance.
StatsOptions stats_options(const Args& args) {
    StatsOptions o;
    o.threads = args.threads;
    o.histogram_bins = args.histogram;
    o.tolerance = args.stats ? args.tolerance : -1;
    if (!args.stats) o.percentiles.clear();
    return o;
}

// Exact surface statistics per direction (core/surface_stats.h), when --stats or --export-errors
// asks for them; empty otherwise.
std::vector<SurfaceStats> direction_stats(const Args& args, const VoxelGrid& grid, const HausdorffResult& r) {
    if (!args.stats && args.export_errors.empty()) return {};
    return hlens::direction_stats(grid, r, args.one_sided, stats_options(args));
}

void print_stats(const Args& args, const std::vector<SurfaceStats>& stats, size_t i) {
    if (!args.stats || i >= stats.size()) return;
    const SurfaceStats& s = stats[i];
    std::printf("   area %s, mean %s, RMS %s\n", g(s.area, 10).c_str(), g(s.mean(), 10).c_str(), g(s.rms(), 10).c_str());
    std::printf("   percentiles (by area):");
    const char* names[] = {"50", "90", "95", "99"};
    for (size_t k = 0; k < s.percentiles.size() && k < 4; ++k) std::printf(" %s%% %s", names[k], g(s.percentiles[k], 10).c_str());
    std::printf("\n");
    if (args.tolerance >= 0)
        std::printf("   farther than %s: area %s (%s%%)\n", g(args.tolerance, 10).c_str(), g(s.area_above, 10).c_str(),
                    g(100 * s.fraction_above, 6).c_str());
    for (size_t k = 0; k < s.histogram_area.size(); ++k)
        std::printf("   [%s, %s]: area %s\n", g(s.histogram_edges[k], 8).c_str(), g(s.histogram_edges[k + 1], 8).c_str(),
                    g(s.histogram_area[k], 8).c_str());
    if (s.sliver_targets)
        std::printf("   %zu sliver triangles (area %s) left out of the statistics\n", s.sliver_targets, g(s.sliver_area, 6).c_str());
}

void export_errors(const Args& args, const TriangleMesh& A, const TriangleMesh& B, const std::vector<SurfaceStats>& stats) {
    if (args.export_errors.empty()) return;
    try {
        write_error_maps(args.export_errors, A, B, stats, args.one_sided);
    } catch (const std::runtime_error& e) {
        throw UsageError(e.what());   // (exit code 2, as a bad path always was)
    }
}

// --tolerance without --stats: a verdict. A vertex farther than T proves h > T at once: report it
// and stop (-1: no such vertex, run the whole computation). Farther for certain: its distance from
// below, less the rounding (point_distance_lower), not the plain point-triangle distance, which
// put a vertex of a mesh compared with a copy of itself 2e-19 away and said "not within 0".
int early_tolerance_verdict(const Args& args, const VoxelGrid& grid) {
    const TriangleMesh &A = grid.mesh(0), &B = grid.mesh(1);
    for (int side = 0; side < (args.one_sided ? 1 : 2); ++side) {
        SampledBound sb = sampled_lower_bound(side == 0 ? A : B, grid, side, 1);
        if (!(sb.value > args.tolerance)) continue;
        sb.value = point_distance_lower(grid, side, sb.point);
        if (!(sb.value > args.tolerance)) continue;
        if (args.json) {
            print_line(to_json(stopped_early_json(A, B, side, sb, report_options(args, 1))));
        } else {
            std::printf("NOT within tolerance %s: the vertex %s of %s (triangle %u) is at least %s from %s,\n"
                        "so %s >= %s (stopped early, without computing the distance)\n",
                        g(args.tolerance).c_str(), point_text(sb.point).c_str(), side == 0 ? "A" : "B", sb.triangle,
                        g(sb.value).c_str(), side == 0 ? "B" : "A", side == 0 ? "h(A,B)" : "h(B,A)", g(sb.value).c_str());
        }
        return 4;
    }
    return -1;
}

// A and B, read at the same time when more than one thread may be used. A's error comes first,
// as when they are read one after the other.
std::pair<TriangleMesh, TriangleMesh> load_pair(const Args& args, const LoadOptions& lo) {
    if (resolve_threads(args.threads) < 2) return {load_mesh(args.files[0], lo), load_mesh(args.files[1], lo)};
    std::future<TriangleMesh> b = std::async(std::launch::async, [&] { return load_mesh(args.files[1], lo); });
    TriangleMesh A = load_mesh(args.files[0], lo);  // if this throws, b's destructor waits for it
    return {std::move(A), b.get()};
}

int run_distance(const Args& args) {
    LoadOptions lo;
    lo.weld = args.weld;
    auto [A, B] = load_pair(args, lo);
    const IndexedPair pair(A, B, args.threads);  // for the early verdict, the distance, --verify and --stats
    const VoxelGrid& grid = pair.grid;
    if (args.tolerance >= 0 && !args.stats && args.export_errors.empty()) {
        const int code = early_tolerance_verdict(args, grid);
        if (code >= 0) return code;
    }

    HausdorffOptions opt;
    opt.mode = args.mode;
    opt.threads = args.threads;
    const int threads = resolve_threads(args.threads);
    const double diagonal = report_diagonal(A, B);
    ProgressBar bar;
    if (isatty(2)) opt.progress = [&bar](double f) { bar.update(f); };
    HausdorffResult r;
    try {
        r = pair.distance(opt, args.one_sided);
    } catch (...) {
        bar.clear();
        throw;
    }
    bar.clear();

    // --verify: an independent bracket of each one-sided distance (core/bounds.h, built on exact
    // point-triangle distances only), which the exact value must lie in.
    struct Check { LipschitzBound bound; bool ok; };
    std::vector<Check> checks;
    if (args.verify) {
        const double diag = std::max(A.bounds().diagonal(), B.bounds().diagonal());
        for (int side = 0; side < (args.one_sided ? 1 : 2); ++side) {
            const OneSidedResult& o = side == 0 ? r.a_to_b : r.b_to_a;
            LipschitzBound lb = lipschitz_bounds(side == 0 ? A : B, grid, side, 1e-4 * diag);
            // Its ends are computed distances, each up to its rounding off (on a mesh against
            // itself the lower end was 1.9e-16 above the exact 0): the bracket reported, and the
            // one the exact value must lie in, is widened by 1e-12 of the diagonal at both ends.
            lb.lower = std::max(0.0, lb.lower - 1e-12 * diag);
            lb.upper += 1e-12 * diag;
            checks.push_back({lb, o.distance >= lb.lower && o.distance <= lb.upper});
        }
    }
    const bool verified = std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.ok; });
    const std::vector<SurfaceStats> stats = direction_stats(args, grid, r);
    export_errors(args, A, B, stats);
    const bool within = args.tolerance < 0 || reported_distance(r, args.one_sided) <= args.tolerance;
    const int code = !verified ? 3 : within ? 0 : 4;

    if (args.json) {
        DistanceReportOptions ro = report_options(args, threads);
        if (args.stats) ro.stats = &stats;
        Value v = distance_json(A, B, r, ro);
        for (size_t i = 0; i < checks.size(); ++i)
            find_field(v, i == 0 ? "a_to_b" : "b_to_a")
                ->add("verify", Value::object()
                                    .add("lower", Value::number(checks[i].bound.lower))
                                    .add("upper", Value::number(checks[i].bound.upper))
                                    .add("ok", Value::boolean(checks[i].ok)));
        print_line(to_json(v));
        return code;
    }
    print_mesh_summary("A", A);
    print_mesh_summary("B", B);
    std::printf("\n");
    print_one_sided("h(A,B)", "A", "B", r.a_to_b, A.num_triangles(), diagonal);
    print_stats(args, stats, 0);
    if (!args.one_sided) {
        std::printf("\n");
        print_one_sided("h(B,A)", "B", "A", r.b_to_a, B.num_triangles(), diagonal);
        print_stats(args, stats, 1);
        std::printf("\nHausdorff distance = %s%s\n", g(r.hausdorff).c_str(), relative_text(r.hausdorff, diagonal).c_str());
    }
    std::printf("\nbounding-box diagonal (both meshes) %s%s%s\n", g(diagonal).c_str(), args.units.empty() ? "" : " ",
                args.units.c_str());
    std::printf("\nmode %s, %d thread%s, %.3f s\n", mode_name(args.mode), threads, threads == 1 ? "" : "s", r.seconds);
    for (size_t i = 0; i < checks.size(); ++i)
        std::printf("verify %s: Lipschitz bracket [%s, %s] %s\n", i == 0 ? "h(A,B)" : "h(B,A)", g(checks[i].bound.lower).c_str(),
                    g(checks[i].bound.upper).c_str(), checks[i].ok ? "holds the exact value" : "DOES NOT hold the exact value");
    if (args.tolerance >= 0)
        std::printf("%s tolerance %s\n", within ? "within" : "NOT within", g(args.tolerance).c_str());
    return code;
}

int run_trace(const Args& args) {
    LoadOptions lo;
    lo.weld = args.weld;
    TriangleMesh A = load_mesh(args.files[0], lo);
    TriangleMesh B = load_mesh(args.files[1], lo);
    if (args.target < 0 || args.target >= (long long)A.num_triangles())
        throw UsageError("--target " + std::to_string(args.target) + " is out of range: " + A.path + " has " +
                         std::to_string(A.num_triangles()) + " triangles (0.." +
                         std::to_string(A.num_triangles() - 1) + ")");
    const uint32_t target = (uint32_t)args.target;

    VoxelGrid grid(A, B);
    TargetSolver ts(grid, 0, target);
    long steps = 0;
    ts.on_event([&](const Event& e) {
        Value v = event_json(e, ts.frame(), args.target);
        if (args.json) {
            print_line(to_json(v));
        } else {
            print_line(event_text(v));
        }
        steps = e.step + 1;
    });
    ts.run();

    const DomainMesh* dm = ts.domain_mesh();  // null for a degenerate target
    const Value fin = trace_final_json(ts, steps);
    if (args.json) {
        print_line(to_json(fin));
    } else {
        auto count = [&](const char* key) { return (int)find_field(fin, key)->i; };
        std::printf("\ntarget %u of %s against %s: %ld events, %d sources inserted%s\n", target, A.path.c_str(),
                    B.path.c_str(), steps, ts.insertions(), dm ? "" : " (degenerate target)");
        std::printf("   max distance %s (squared %s) at %s\n", g(std::sqrt(ts.max_sq())).c_str(),
                    g(ts.max_sq()).c_str(), point_text(ts.max_point()).c_str());
        std::printf("   domain mesh: %d domains, %d arcs, %d vertices\n", count("domains"), count("arcs"), count("vertices"));
    }
    return 0;
}

// ---------------------------------------------------------------- batch

// What the summary line of a batch says.
struct BatchTally {
    size_t compared = 0, failed = 0, exceeding = 0;
    bool unexpected = false;
    double largest = -1;      // the largest reported distance, and its file
    std::string largest_path;

    void add(const BatchItem& item, const Args& args) {
        if (!item.ok) {
            ++failed;
            unexpected |= item.unexpected;
            return;
        }
        ++compared;
        const double d = reported_distance(item.result, args.one_sided);
        if (args.tolerance >= 0 && d > args.tolerance) ++exceeding;
        if (d > largest) { largest = d; largest_path = item.path; }
    }
    // Failures first: a file that could not be compared may hide a pair beyond the tolerance.
    int exit_code() const { return unexpected ? 1 : failed ? 2 : exceeding ? 4 : 0; }
};

void print_batch_item(const Args& args, const BatchItem& item, int threads) {
    if (!item.ok) {
        if (args.json)
            print_line(to_json(Value::object()
                                   .add("index", Value::integer((long long)item.index))
                                   .add("path", Value::string(item.path))
                                   .add("error", Value::string(item.error))));
        else
            std::printf("[%zu] %s: error: %s\n", item.index, item.path.c_str(), item.error.c_str());
        return;
    }
    DistanceReportOptions ro = report_options(args, threads);
    if (args.stats) ro.stats = &item.stats;
    Value v = distance_json(*item.reference, item.mesh, item.result, ro);
    if (args.json) {
        v.fields.insert(v.fields.begin(), {"index", Value::integer((long long)item.index)});
        print_line(to_json(v));
        return;
    }
    const double d = reported_distance(item.result, args.one_sided);
    std::printf("[%zu] %s: %s = %s%s%s\n", item.index, item.path.c_str(), args.one_sided ? "h(A,B)" : "Hausdorff",
                g(d).c_str(), relative_text(d, find_field(v, "diagonal")->d).c_str(),
                args.tolerance >= 0 && d > args.tolerance ? "  EXCEEDS the tolerance" : "");
    for (size_t i = 0; i < item.stats.size(); ++i) {
        std::printf("   %s:\n", i == 0 ? "h(A,B)" : "h(B,A)");
        print_stats(args, item.stats, i);
    }
}

void print_batch_summary(const Args& args, const BatchTally& t, size_t files, double seconds) {
    if (args.json) {
        Value s = Value::object();
        s.add("reference", Value::string(args.files[0]))
            .add("files", Value::integer((long long)files))
            .add("compared", Value::integer((long long)t.compared))
            .add("failed", Value::integer((long long)t.failed));
        if (args.tolerance >= 0)
            s.add("tolerance", Value::number(args.tolerance)).add("exceeding", Value::integer((long long)t.exceeding));
        s.add("largest", t.compared ? Value::number(t.largest) : Value())
            .add("largest_path", t.compared ? Value::string(t.largest_path) : Value())
            .add("seconds", Value::number(seconds));
        print_line(to_json(Value::object().add("summary", s)));
        return;
    }
    std::printf("batch: %zu files against %s: %zu compared, %zu failed", files, args.files[0].c_str(), t.compared, t.failed);
    if (args.tolerance >= 0) std::printf(", %zu beyond the tolerance %s", t.exceeding, g(args.tolerance).c_str());
    if (t.compared) std::printf("; largest %s (%s)", g(t.largest).c_str(), t.largest_path.c_str());
    std::printf(", %.3f s\n", seconds);
}

// The reference is read once (a bad reference stops everything: exit 2); each pair's line is
// printed as soon as it finishes.
int run_batch(const Args& args) {
    const auto t0 = std::chrono::steady_clock::now();
    LoadOptions lo;
    lo.weld = args.weld;
    const TriangleMesh reference = load_mesh(args.files[0], lo);
    BatchOptions bo;
    bo.mode = args.mode;
    bo.threads = args.threads;
    bo.jobs = args.jobs;
    bo.one_sided = args.one_sided;
    bo.load = lo;
    bo.stats = args.stats;
    bo.stats_options = stats_options(args);
    const std::vector<std::string> files(args.files.begin() + 1, args.files.end());
    BatchRunner runner(reference, files, bo);
    BatchTally tally;
    BatchItem item;
    while (!runner.done()) {
        if (!runner.next(item, std::chrono::milliseconds(500))) continue;
        print_batch_item(args, item, runner.threads_per_pair());
        std::fflush(stdout);
        tally.add(item, args);
    }
    print_batch_summary(args, tally, files.size(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return tally.exit_code();
}

// One line on stderr, whatever the message holds.
void report(const std::string& message) {
    std::string m = message;
    std::replace(m.begin(), m.end(), '\n', ' ');
    std::replace(m.begin(), m.end(), '\r', ' ');
    std::fprintf(stderr, "hlens-cli: %s\n", m.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    try {
        Args args = parse_args(argc, argv);
        if (args.help) {
            std::fputs(kUsage, stdout);
            return 0;
        }
        int code = args.command == "distance" ? run_distance(args)
                   : args.command == "batch"  ? run_batch(args)
                                              : run_trace(args);
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            report("cannot write the output");
            return 1;
        }
        return code;
    } catch (const UsageError& e) {
        report(e.what());
        return 2;
    } catch (const MeshError& e) {
        report(e.what());
        return 2;
    } catch (const std::exception& e) {
        report(std::string("unexpected error: ") + e.what());
        return 1;
    } catch (...) {
        report("unexpected error");
        return 1;
    }
}
