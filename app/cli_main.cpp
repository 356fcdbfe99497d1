// hlens-cli: the command-line front end of Hausdorff Lens.
//
//   hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld]
//                          [--stats] [--histogram N] [--tolerance T] [--export-errors PATH.ply]
//   hlens-cli trace A B --target I [--json] [--no-weld]
//   hlens-cli --help | help
//
// `distance` prints h(A,B), h(B,A) and the Hausdorff distance (core/hausdorff.h); `trace` runs one
// target triangle of A with core/target_solver.h and prints every event as it happens, one per line.
// Exit codes: 0 success, 2 bad usage or bad input (one line "hlens-cli: <message>" on stderr),
// 3 --verify disagrees, 4 not within --tolerance, 1 anything unexpected.
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
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "conic.h"
#include "domain_mesh.h"
#include "bounds.h"
#include "hausdorff.h"
#include "mesh.h"
#include "mesh_io.h"
#include "regions.h"
#include "surface_stats.h"
#include "target_solver.h"
#include "voxel_grid.h"

using namespace hlens;

namespace {

const char* kUsage =
    "usage:\n"
    "  hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld] [--verify]\n"
    "                         [--stats] [--histogram N] [--tolerance T] [--export-errors PATH.ply]\n"
    "  hlens-cli trace A B --target I [--json] [--no-weld]\n"
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
    "formats: .obj .ply .stl .off .gltf .glb\n"
    "exit codes: 0 success, 2 bad usage or bad input, 3 --verify found a disagreement, 4 not within --tolerance,\n"
    "            1 unexpected error\n";

// Bad usage or bad input: exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---------------------------------------------------------------- a tiny JSON value

struct Value {
    enum Kind { Null, Bool, Int, Num, Str, Arr, Obj } kind = Null;
    bool b = false;
    long long i = 0;
    double d = 0;
    std::string s;
    std::vector<Value> items;                            // Arr
    std::vector<std::pair<std::string, Value>> fields;   // Obj, in insertion order

    Value() = default;
    static Value boolean(bool v) { Value r; r.kind = Bool; r.b = v; return r; }
    static Value integer(long long v) { Value r; r.kind = Int; r.i = v; return r; }
    static Value number(double v) { Value r; r.kind = Num; r.d = v; return r; }   // non-finite: null
    static Value string(std::string v) { Value r; r.kind = Str; r.s = std::move(v); return r; }
    static Value array() { Value r; r.kind = Arr; return r; }
    static Value object() { Value r; r.kind = Obj; return r; }

    Value& add(const std::string& key, Value v) { fields.emplace_back(key, std::move(v)); return *this; }
    Value& push(Value v) { items.push_back(std::move(v)); return *this; }
};

Value vec2(Vec2 p) { return Value::array().push(Value::number(p.x)).push(Value::number(p.y)); }
Value vec3(const Vec3& p) {
    return Value::array().push(Value::number(p.x)).push(Value::number(p.y)).push(Value::number(p.z));
}

std::string format_double(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

void json_string(std::string& out, const std::string& s) {
    out += '"';
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20 || c == 0x7f) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += char(c);  // UTF-8 passes through unchanged
                }
        }
    }
    out += '"';
}

// Doubles with 17 significant digits so they read back bit-exactly; inf and NaN become null.
void to_json(std::string& out, const Value& v) {
    switch (v.kind) {
        case Value::Null: out += "null"; break;
        case Value::Bool: out += v.b ? "true" : "false"; break;
        case Value::Int: out += std::to_string(v.i); break;
        case Value::Num: out += std::isfinite(v.d) ? format_double(v.d, 17) : "null"; break;
        case Value::Str: json_string(out, v.s); break;
        case Value::Arr:
            out += '[';
            for (size_t k = 0; k < v.items.size(); ++k) {
                if (k) out += ", ";
                to_json(out, v.items[k]);
            }
            out += ']';
            break;
        case Value::Obj:
            out += '{';
            for (size_t k = 0; k < v.fields.size(); ++k) {
                if (k) out += ", ";
                json_string(out, v.fields[k].first);
                out += ": ";
                to_json(out, v.fields[k].second);
            }
            out += '}';
            break;
    }
}

// The same value for people: numbers with 10 digits, number lists as (x, y), objects as k=v.
void to_text(std::string& out, const Value& v) {
    switch (v.kind) {
        case Value::Null: out += "-"; break;
        case Value::Bool: out += v.b ? "yes" : "no"; break;
        case Value::Int: out += std::to_string(v.i); break;
        case Value::Num: out += std::isfinite(v.d) ? format_double(v.d, 10) : (v.d > 0 ? "inf" : "nan"); break;
        case Value::Str: out += v.s; break;
        case Value::Arr: {
            bool numeric = !v.items.empty() && std::all_of(v.items.begin(), v.items.end(), [](const Value& x) {
                return x.kind == Value::Num || x.kind == Value::Int;
            });
            out += numeric ? '(' : '[';
            for (size_t k = 0; k < v.items.size(); ++k) {
                if (k) out += numeric ? ", " : " ";
                to_text(out, v.items[k]);
            }
            out += numeric ? ')' : ']';
            break;
        }
        case Value::Obj:
            out += '{';
            for (size_t k = 0; k < v.fields.size(); ++k) {
                if (k) out += ' ';
                out += v.fields[k].first + '=';
                to_text(out, v.fields[k].second);
            }
            out += '}';
            break;
    }
}

void print_line(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
}

// ---------------------------------------------------------------- command line

struct Args {
    std::string command;
    std::vector<std::string> files;
    bool json = false, one_sided = false, weld = true, verify = false;
    bool stats = false;                  // issue 9: --stats, --histogram, --tolerance, --export-errors
    int histogram = 0;
    double tolerance = -1;               // < 0: none
    std::string export_errors;
    Mode mode = Mode::Fast;
    int threads = 0;          // 0: all cores
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

// The options of issue 9 (statistics, tolerance, error map); true if `w` is one of them.
template <class TakeValue>
bool parse_stats_option(Args& a, const std::string& w, bool has_value, TakeValue& take_value) {
    if (w == "--stats") {
        if (has_value) throw UsageError("--stats takes no value");
        a.stats = true;
    } else if (w == "--histogram") {
        long long n = parse_integer("--histogram", take_value());
        if (n < 1 || n > 100000) throw UsageError("--histogram must be between 1 and 100000, got " + std::to_string(n));
        a.histogram = (int)n;
    } else if (w == "--tolerance") {
        a.tolerance = parse_number("--tolerance", take_value());
        if (a.tolerance < 0) throw UsageError("--tolerance must be >= 0, got " + format_double(a.tolerance, 17));
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
    if (a.command != "distance" && a.command != "trace")
        throw UsageError("unknown command '" + a.command + "' (see hlens-cli --help)");
    const bool distance = a.command == "distance";

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
    if (a.files.size() != 2)
        throw UsageError(a.command + " needs two mesh files, got " + std::to_string(a.files.size()) +
                         " (see hlens-cli --help)");
    if (!distance && !a.has_target) throw UsageError("trace needs --target I");
    if (a.histogram > 0 && !a.stats) throw UsageError("--histogram needs --stats");
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

Value mesh_json(const TriangleMesh& m) {
    return Value::object()
        .add("path", Value::string(m.path))
        .add("vertices", Value::integer((long long)m.num_used_vertices()))
        .add("triangles", Value::integer((long long)m.num_triangles()));
}

Value one_sided_json(const OneSidedResult& r) {
    return Value::object()
        .add("distance", Value::number(r.distance))
        .add("lower", Value::number(r.lower))
        .add("upper", Value::number(r.upper))
        .add("target", Value::integer(r.target))
        .add("from_point", vec3(r.from_point))
        .add("to_point", vec3(r.to_point))
        .add("exact_targets", Value::integer((long long)r.exact_targets))
        .add("exact_solves", Value::integer((long long)r.exact_solves))
        .add("seconds", Value::number(r.seconds));
}

std::string g(double v, int digits = 15) { return format_double(v, digits); }
std::string point_text(const Vec3& p) { return "(" + g(p.x, 10) + ", " + g(p.y, 10) + ", " + g(p.z, 10) + ")"; }

void print_mesh_summary(const char* name, const TriangleMesh& m) {
    std::printf("%s: %s\n   %zu vertices (%zu used), %zu triangles\n", name, m.path.c_str(), m.positions.size(),
                m.num_used_vertices(), m.num_triangles());
}

void print_one_sided(const char* title, const char* from, const char* to, const OneSidedResult& r, size_t targets) {
    std::printf("%s = %s\n", title, g(r.distance).c_str());
    std::printf("   certified interval [%s, %s]\n", g(r.lower).c_str(), g(r.upper).c_str());
    std::printf("   witness: triangle %u of %s, point %s\n", r.target, from, point_text(r.from_point).c_str());
    std::printf("            nearest point of %s %s\n", to, point_text(r.to_point).c_str());
    std::printf("   exact targets: %zu of %zu (%zu exact solves), %.3f s\n", r.exact_targets, targets, r.exact_solves, r.seconds);
}

// ---------------------------------------------------------------- statistics (issue 9)

// Exact surface statistics per direction (core/surface_stats.h), when --stats or --export-errors
// asks for them; empty otherwise.
std::vector<SurfaceStats> direction_stats(const Args& args, const TriangleMesh& A, const TriangleMesh& B,
                                          const HausdorffResult& r) {
    std::vector<SurfaceStats> out;
    if (!args.stats && args.export_errors.empty()) return out;
    VoxelGrid grid(A, B);
    for (int side = 0; side < (args.one_sided ? 1 : 2); ++side) {
        StatsOptions o;
        o.threads = args.threads;
        o.histogram_bins = args.histogram;
        o.tolerance = args.stats ? args.tolerance : -1;
        if (!args.stats) o.percentiles.clear();  // the error map needs no percentiles
        o.known_max = (side == 0 ? r.a_to_b : r.b_to_a).distance;
        out.push_back(surface_stats(grid, side, o));
    }
    return out;
}

Value numbers_json(const std::vector<double>& v) {
    Value a = Value::array();
    for (double x : v) a.push(Value::number(x));
    return a;
}

// The fields --stats adds to one direction's object.
Value with_stats(Value v, const Args& args, const std::vector<SurfaceStats>& stats, size_t i) {
    if (!args.stats || i >= stats.size()) return v;
    const SurfaceStats& s = stats[i];
    Value pct = Value::object();
    const char* names[] = {"50", "90", "95", "99"};
    for (size_t k = 0; k < s.percentiles.size() && k < 4; ++k) pct.add(names[k], Value::number(s.percentiles[k]));
    v.add("area", Value::number(s.area)).add("mean", Value::number(s.mean())).add("rms", Value::number(s.rms()))
        .add("percentiles", pct);
    if (args.histogram > 0)
        v.add("histogram", Value::object().add("edges", numbers_json(s.histogram_edges)).add("area", numbers_json(s.histogram_area)));
    if (args.tolerance >= 0)
        v.add("area_above", Value::number(s.area_above)).add("fraction_above", Value::number(s.fraction_above));
    v.add("stats_error", Value::object()
                             .add("area", Value::number(s.err_area))
                             .add("integral_d2", Value::number(s.err_d2))
                             .add("integral_d_estimate", Value::number(s.err_d))
                             .add("percentile", Value::number(s.percentile_tolerance)));
    v.add("stats_seconds", Value::object()
                               .add("first_pass", Value::number(s.seconds_first_pass))
                               .add("percentiles", Value::number(s.seconds_percentiles))
                               .add("percentile_passes", Value::integer(s.percentile_passes))
                               .add("rerun_targets", Value::integer((long long)s.rerun_targets)));
    if (s.sliver_targets) v.add("sliver_triangles", Value::integer((long long)s.sliver_targets)).add("sliver_area", Value::number(s.sliver_area));
    return v;
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

// The error map of one direction as PLY: every vertex with its distance, every face with its
// max, mean and RMS distance; "quality" (max on faces) is the scalar field MeshLab reads.
void write_error_ply(const std::string& path, const TriangleMesh& M, const SurfaceStats& s) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw UsageError("cannot write " + path + ": " + std::strerror(errno));
    std::fprintf(f, "ply\nformat ascii 1.0\ncomment hlens-cli error map: distance from this mesh to the other\n");
    std::fprintf(f, "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\nproperty float quality\n"
                 "property double distance\n", M.positions.size());
    std::fprintf(f, "element face %zu\nproperty list uchar int vertex_indices\nproperty float quality\n"
                 "property double max_distance\nproperty double mean_distance\nproperty double rms_distance\nend_header\n",
                 M.num_triangles());
    for (size_t v = 0; v < M.positions.size(); ++v) {
        const double d = std::max(0.0, s.vertex_distance[v]);  // a vertex no triangle uses: 0
        std::fprintf(f, "%.17g %.17g %.17g %.9g %.17g\n", M.positions[v].x, M.positions[v].y, M.positions[v].z, d, d);
    }
    for (size_t t = 0; t < M.num_triangles(); ++t) {
        const TriangleStats& ts = s.triangles[t];
        std::fprintf(f, "3 %u %u %u %.9g %.17g %.17g %.17g\n", M.triangles[t][0], M.triangles[t][1], M.triangles[t][2], ts.max,
                     ts.max, ts.mean(), ts.rms());
    }
    if (std::fclose(f) != 0) throw UsageError("cannot write " + path);
}

void export_errors(const Args& args, const TriangleMesh& A, const TriangleMesh& B, const std::vector<SurfaceStats>& stats) {
    if (args.export_errors.empty()) return;
    if (args.one_sided) { write_error_ply(args.export_errors, A, stats[0]); return; }
    const std::string stem = args.export_errors.substr(0, args.export_errors.size() - 4);
    write_error_ply(stem + "-ab.ply", A, stats[0]);
    write_error_ply(stem + "-ba.ply", B, stats[1]);
}

// --tolerance without --stats: a verdict. A vertex farther than T (exact point-mesh distance)
// proves h > T at once: report it and stop (-1: no such vertex, run the whole computation).
int early_tolerance_verdict(const Args& args, const TriangleMesh& A, const TriangleMesh& B) {
    VoxelGrid grid(A, B);
    for (int side = 0; side < (args.one_sided ? 1 : 2); ++side) {
        const SampledBound sb = sampled_lower_bound(side == 0 ? A : B, grid, side, 1);
        if (!(sb.value > args.tolerance)) continue;
        const char* dir = side == 0 ? "a_to_b" : "b_to_a";
        if (args.json) {
            Value v = Value::object();
            v.add("a", mesh_json(A)).add("b", mesh_json(B)).add("tolerance", Value::number(args.tolerance))
                .add("within_tolerance", Value::boolean(false)).add("stopped_early", Value::boolean(true))
                .add("direction", Value::string(dir)).add("point", vec3(sb.point))
                .add("triangle", Value::integer(sb.triangle)).add("lower", Value::number(sb.value));
            std::string out;
            to_json(out, v);
            print_line(out);
        } else {
            std::printf("NOT within tolerance %s: the vertex %s of %s (triangle %u) is at distance %s from %s,\n"
                        "so %s >= %s (stopped early, without computing the distance)\n",
                        g(args.tolerance).c_str(), point_text(sb.point).c_str(), side == 0 ? "A" : "B", sb.triangle,
                        g(sb.value).c_str(), side == 0 ? "B" : "A", side == 0 ? "h(A,B)" : "h(B,A)", g(sb.value).c_str());
        }
        return 4;
    }
    return -1;
}

void add_tolerance_json(Value& v, const Args& args, bool within) {
    if (args.tolerance < 0) return;
    v.add("tolerance", Value::number(args.tolerance)).add("within_tolerance", Value::boolean(within));
    if (!args.stats) v.add("stopped_early", Value::boolean(false));
}

int run_distance(const Args& args) {
    LoadOptions lo;
    lo.weld = args.weld;
    TriangleMesh A = load_mesh(args.files[0], lo);
    TriangleMesh B = load_mesh(args.files[1], lo);
    if (args.tolerance >= 0 && !args.stats && args.export_errors.empty()) {
        const int code = early_tolerance_verdict(args, A, B);
        if (code >= 0) return code;
    }

    HausdorffOptions opt;
    opt.mode = args.mode;
    opt.threads = args.threads;
    const int threads = args.threads > 0 ? args.threads : (int)std::max(1u, std::thread::hardware_concurrency());
    ProgressBar bar;
    if (isatty(2)) opt.progress = [&bar](double f) { bar.update(f); };
    HausdorffResult r;
    try {
        r = hausdorff(A, B, opt, args.one_sided);
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
        VoxelGrid grid(A, B);
        const double diag = std::max(A.bounds().diagonal(), B.bounds().diagonal());
        for (int side = 0; side < (args.one_sided ? 1 : 2); ++side) {
            const OneSidedResult& o = side == 0 ? r.a_to_b : r.b_to_a;
            LipschitzBound lb = lipschitz_bounds(side == 0 ? A : B, grid, side, 1e-4 * diag);
            checks.push_back({lb, o.distance >= lb.lower - 1e-12 * diag && o.distance <= lb.upper + 1e-12 * diag});
        }
    }
    const bool verified = std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.ok; });
    const std::vector<SurfaceStats> stats = direction_stats(args, A, B, r);
    export_errors(args, A, B, stats);
    const bool within = args.tolerance < 0 || (args.one_sided ? r.a_to_b.distance : r.hausdorff) <= args.tolerance;
    const int code = !verified ? 3 : within ? 0 : 4;
    auto with_check = [&](Value v, size_t i) {
        if (i < checks.size())
            v.add("verify", Value::object()
                                .add("lower", Value::number(checks[i].bound.lower))
                                .add("upper", Value::number(checks[i].bound.upper))
                                .add("ok", Value::boolean(checks[i].ok)));
        return v;
    };

    if (args.json) {
        Value v = Value::object();
        v.add("a", mesh_json(A)).add("b", mesh_json(B)).add("a_to_b", with_stats(with_check(one_sided_json(r.a_to_b), 0), args, stats, 0));
        if (!args.one_sided)
            v.add("b_to_a", with_stats(with_check(one_sided_json(r.b_to_a), 1), args, stats, 1)).add("hausdorff", Value::number(r.hausdorff));
        add_tolerance_json(v, args, within);
        v.add("seconds", Value::number(r.seconds))
            .add("mode", Value::string(mode_name(args.mode)))
            .add("threads", Value::integer(threads));
        std::string out;
        to_json(out, v);
        print_line(out);
        return code;
    }
    print_mesh_summary("A", A);
    print_mesh_summary("B", B);
    std::printf("\n");
    print_one_sided("h(A,B)", "A", "B", r.a_to_b, A.num_triangles());
    print_stats(args, stats, 0);
    if (!args.one_sided) {
        std::printf("\n");
        print_one_sided("h(B,A)", "B", "A", r.b_to_a, B.num_triangles());
        print_stats(args, stats, 1);
        std::printf("\nHausdorff distance = %s\n", g(r.hausdorff).c_str());
    }
    std::printf("\nmode %s, %d thread%s, %.3f s\n", mode_name(args.mode), threads, threads == 1 ? "" : "s", r.seconds);
    for (size_t i = 0; i < checks.size(); ++i)
        std::printf("verify %s: Lipschitz bracket [%s, %s] %s\n", i == 0 ? "h(A,B)" : "h(B,A)", g(checks[i].bound.lower).c_str(),
                    g(checks[i].bound.upper).c_str(), checks[i].ok ? "holds the exact value" : "DOES NOT hold the exact value");
    if (args.tolerance >= 0)
        std::printf("%s tolerance %s\n", within ? "within" : "NOT within", g(args.tolerance).c_str());
    return code;
}

// ---------------------------------------------------------------- trace

Value label_json(const DomainLabel& l) {
    return Value::object()
        .add("source", Value::integer(l.source))
        .add("region", l.source < 0 ? Value() : Value::string(region_name(l.region)));
}

Value curve_json(const Quadratic2& q) {
    return Value::object()
        .add("a", Value::number(q.a)).add("b", Value::number(q.b)).add("c", Value::number(q.c))
        .add("d", Value::number(q.d)).add("e", Value::number(q.e)).add("f", Value::number(q.f))
        .add("type", Value::string(conic_type_name(decompose_conic(q).type)));
}

// One event with the fields meaningful for its kind. Every event has event, step, insertion (sources
// inserted so far) and radius (the search radius at that moment, null while infinite).
Value event_json(const Event& e, const TargetFrame& frame, long long target) {
    Value v = Value::object();
    v.add("event", Value::string(event_name(e.kind)))
        .add("step", Value::integer(e.step))
        .add("insertion", Value::integer(e.insertion))
        .add("radius", Value::number(e.radius));
    auto point = [&] { v.add("point", vec2(e.point)).add("world", vec3(e.world)); };
    switch (e.kind) {
        case EventKind::TargetBegun: {
            Value corners = Value::array();
            for (Vec2 c : frame.corners) corners.push(vec2(c));
            v.add("target", Value::integer(target)).add("corners", corners)
                .add("degenerate", Value::boolean(frame.degenerate)).add("world", vec3(e.world));
            break;
        }
        case EventKind::VoxelVisited:
        case EventKind::VoxelCulled:
            v.add("voxel", Value::integer(e.voxel)).add("distance", Value::number(e.distance));
            break;
        case EventKind::SourceChosen:
        case EventKind::SourceCulled:
            v.add("source", Value::integer(e.source)).add("voxel", Value::integer(e.voxel))
                .add("distance", Value::number(e.distance));
            break;
        case EventKind::RegionsProjected: {
            Value regions = Value::array();
            for (const RegionPolygon& r : e.regions) {
                Value poly = Value::array();
                for (Vec2 p : r.polygon) poly.push(vec2(p));
                regions.push(Value::object().add("region", Value::string(region_name(r.kind))).add("polygon", poly));
            }
            v.add("source", Value::integer(e.source)).add("regions", regions);
            break;
        }
        case EventKind::DomainSplit: {
            Value faces = Value::array();
            for (int f : e.faces) faces.push(Value::integer(f));
            v.add("source", Value::integer(e.source)).add("face", Value::integer(e.face)).add("faces", faces)
                .add("curve", curve_json(e.curve));
            break;
        }
        case EventKind::DomainCreated:
            v.add("source", Value::integer(e.source)).add("face", Value::integer(e.face))
                .add("label", label_json(e.label)).add("old_label", label_json(e.old_label));
            break;
        case EventKind::DomainMerged:
            v.add("source", Value::integer(e.source)).add("face", Value::integer(e.face))
                .add("other", Value::integer(e.other));
            break;
        case EventKind::ArcMaximum:
            v.add("edge", Value::integer(e.other));
            point();
            v.add("value", Value::number(e.value));
            break;
        case EventKind::MaximumRaised:
        case EventKind::SearchRadiusShrunk:
        case EventKind::TargetFinished:
            point();
            v.add("value", Value::number(e.value));
            break;
    }
    return v;
}

// Readable form: "  step  event  key=value ..." (the step and event name lead the line).
std::string event_text(const Value& v) {
    char head[96];
    std::snprintf(head, sizeof head, "%6lld  %-22s", v.fields[1].second.i, v.fields[0].second.s.c_str());
    std::string out = head;
    for (size_t k = 2; k < v.fields.size(); ++k) {
        out += ' ';
        out += v.fields[k].first + '=';
        to_text(out, v.fields[k].second);
    }
    return out;
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
            std::string out;
            to_json(out, v);
            print_line(out);
        } else {
            print_line(event_text(v));
        }
        steps = e.step + 1;
    });
    ts.run();

    const DomainMesh* dm = ts.domain_mesh();  // null for a degenerate target
    const int domains = dm ? dm->num_live_faces() : 0, arcs = dm ? dm->num_live_edges() : 0,
              vertices = dm ? dm->num_live_vertices() : 0;
    Value fin = Value::object();
    fin.add("event", Value::string("final"))
        .add("step", Value::integer(steps))
        .add("target", Value::integer(target))
        .add("max_sq", Value::number(ts.max_sq()))
        .add("max", Value::number(std::sqrt(ts.max_sq())))
        .add("max_point", vec3(ts.max_point()))
        .add("domains", Value::integer(domains))
        .add("arcs", Value::integer(arcs))
        .add("vertices", Value::integer(vertices))
        .add("insertions", Value::integer(ts.insertions()))
        .add("degenerate", Value::boolean(dm == nullptr));
    if (args.json) {
        std::string out;
        to_json(out, fin);
        print_line(out);
    } else {
        std::printf("\ntarget %u of %s against %s: %ld events, %d sources inserted%s\n", target, A.path.c_str(),
                    B.path.c_str(), steps, ts.insertions(), dm ? "" : " (degenerate target)");
        std::printf("   max distance %s (squared %s) at %s\n", g(std::sqrt(ts.max_sq())).c_str(),
                    g(ts.max_sq()).c_str(), point_text(ts.max_point()).c_str());
        std::printf("   domain mesh: %d domains, %d arcs, %d vertices\n", domains, arcs, vertices);
    }
    return 0;
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
        int code = args.command == "distance" ? run_distance(args) : run_trace(args);
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
