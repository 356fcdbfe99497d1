// hlens-cli: the command-line front end of Hausdorff Lens.
//
//   hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld]
//   hlens-cli trace A B --target I [--json] [--no-weld]
//   hlens-cli --help | help
//
// `distance` prints h(A,B), h(B,A) and the Hausdorff distance (core/hausdorff.h); `trace` runs one
// target triangle of A with core/target_solver.h and prints every event as it happens, one per line.
// Exit codes: 0 success, 2 bad usage or bad input (one line "hlens-cli: <message>" on stderr),
// 1 anything unexpected.
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
#include "target_solver.h"
#include "voxel_grid.h"

using namespace hlens;

namespace {

const char* kUsage =
    "usage:\n"
    "  hlens-cli distance A B [--json] [--one-sided] [--mode paper|fast] [--threads N] [--no-weld] [--verify]\n"
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
    "\n"
    "trace      run target triangle I of A against B and print every event of the solver as it\n"
    "           happens (one line each), then a final summary line\n"
    "  --target I    index of the target triangle of A (0-based), required\n"
    "  --json        one JSON object per line\n"
    "\n"
    "formats: .obj .ply .stl .off .gltf .glb\n"
    "exit codes: 0 success, 2 bad usage or bad input, 3 --verify found a disagreement, 1 unexpected error\n";

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

int run_distance(const Args& args) {
    LoadOptions lo;
    lo.weld = args.weld;
    TriangleMesh A = load_mesh(args.files[0], lo);
    TriangleMesh B = load_mesh(args.files[1], lo);

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
        v.add("a", mesh_json(A)).add("b", mesh_json(B)).add("a_to_b", with_check(one_sided_json(r.a_to_b), 0));
        if (!args.one_sided) v.add("b_to_a", with_check(one_sided_json(r.b_to_a), 1)).add("hausdorff", Value::number(r.hausdorff));
        v.add("seconds", Value::number(r.seconds))
            .add("mode", Value::string(mode_name(args.mode)))
            .add("threads", Value::integer(threads));
        std::string out;
        to_json(out, v);
        print_line(out);
        return verified ? 0 : 3;
    }
    print_mesh_summary("A", A);
    print_mesh_summary("B", B);
    std::printf("\n");
    print_one_sided("h(A,B)", "A", "B", r.a_to_b, A.num_triangles());
    if (!args.one_sided) {
        std::printf("\n");
        print_one_sided("h(B,A)", "B", "A", r.b_to_a, B.num_triangles());
        std::printf("\nHausdorff distance = %s\n", g(r.hausdorff).c_str());
    }
    std::printf("\nmode %s, %d thread%s, %.3f s\n", mode_name(args.mode), threads, threads == 1 ? "" : "s", r.seconds);
    for (size_t i = 0; i < checks.size(); ++i)
        std::printf("verify %s: Lipschitz bracket [%s, %s] %s\n", i == 0 ? "h(A,B)" : "h(B,A)", g(checks[i].bound.lower).c_str(),
                    g(checks[i].bound.upper).c_str(), checks[i].ok ? "holds the exact value" : "DOES NOT hold the exact value");
    return verified ? 0 : 3;
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
