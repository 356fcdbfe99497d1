#include "report.h"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <hlens/conic.h>
#include <hlens/domain_mesh.h>
#include <hlens/regions.h>
#include <hlens/voxel_grid.h>

namespace hlens {

double report_diagonal(const TriangleMesh& A, const TriangleMesh& B) {
    Box3 box = A.bounds();
    box.add(B.bounds());
    return box.diagonal();
}

double reported_distance(const HausdorffResult& r, bool one_sided) {
    return one_sided ? r.a_to_b.distance : r.hausdorff;
}

static double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

IndexedPair::IndexedPair(const TriangleMesh& A, const TriangleMesh& B, int threads)
    : IndexedPair(A, B, threads, std::chrono::steady_clock::now()) {}

IndexedPair::IndexedPair(const TriangleMesh& A, const TriangleMesh& B, int threads, std::chrono::steady_clock::time_point start)
    : grid(A, B, 1.0, threads), grid_seconds(seconds_since(start)) {}

HausdorffResult IndexedPair::distance(const HausdorffOptions& opt, bool one_sided) const {
    HausdorffResult r = hausdorff(grid, opt, one_sided);
    r.seconds += grid_seconds;
    return r;
}

std::vector<SurfaceStats> direction_stats(const VoxelGrid& grid, const HausdorffResult& r, bool one_sided,
                                          const StatsOptions& base) {
    std::vector<SurfaceStats> out;
    const int sides = one_sided ? 1 : 2;
    for (int side = 0; side < sides; ++side) {
        StatsOptions o = base;
        o.known_max = (side == 0 ? r.a_to_b : r.b_to_a).distance;
        if (base.progress) o.progress = [&base, side, sides](double f) { base.progress((side + f) / sides); };
        out.push_back(surface_stats(grid, side, o));
    }
    return out;
}

// distance / diagonal; null (NaN) when the meshes are one point.
static Value relative(double distance, double diagonal) {
    return Value::number(diagonal > 0 ? distance / diagonal : NAN);
}

Value mesh_json(const TriangleMesh& m) {
    return Value::object()
        .add("path", Value::string(m.path))
        .add("vertices", Value::integer((long long)m.num_used_vertices()))
        .add("triangles", Value::integer((long long)m.num_triangles()));
}


Value one_sided_json(const OneSidedResult& r, double diagonal) {
    return Value::object()
        .add("distance", Value::number(r.distance))
        .add("relative", relative(r.distance, diagonal))
        .add("lower", Value::number(r.lower))
        .add("upper", Value::number(r.upper))
        .add("target", Value::integer(r.target))
        .add("from_point", vec3(r.from_point))
        .add("to_point", vec3(r.to_point))
        .add("exact_targets", Value::integer((long long)r.exact_targets))
        .add("exact_solves", Value::integer((long long)r.exact_solves))
        .add("seconds", Value::number(r.seconds));
}

static Value numbers_json(const std::vector<double>& v) {
    Value a = Value::array();
    for (double x : v) a.push(Value::number(x));
    return a;
}

void add_stats_json(Value& v, const SurfaceStats& s, double tolerance) {
    Value pct = Value::object();
    const char* names[] = {"50", "90", "95", "99"};
    for (size_t k = 0; k < s.percentiles.size() && k < 4; ++k) pct.add(names[k], Value::number(s.percentiles[k]));
    v.add("area", Value::number(s.area)).add("mean", Value::number(s.mean())).add("rms", Value::number(s.rms()))
        .add("percentiles", pct);
    if (!s.histogram_area.empty())
        v.add("histogram", Value::object().add("edges", numbers_json(s.histogram_edges)).add("area", numbers_json(s.histogram_area)));
    if (tolerance >= 0)
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
}

// One direction's object, with its statistics when there are any.
static Value direction_json(const OneSidedResult& r, double diagonal, const DistanceReportOptions& opt, size_t side) {
    Value v = one_sided_json(r, diagonal);
    if (opt.stats && side < opt.stats->size()) add_stats_json(v, (*opt.stats)[side], opt.tolerance);
    return v;
}

Value distance_json(const TriangleMesh& A, const TriangleMesh& B, const HausdorffResult& r,
                    const DistanceReportOptions& opt) {
    const double diag = report_diagonal(A, B);
    Value v = Value::object();
    v.add("a", mesh_json(A)).add("b", mesh_json(B)).add("a_to_b", direction_json(r.a_to_b, diag, opt, 0));
    if (!opt.one_sided)
        v.add("b_to_a", direction_json(r.b_to_a, diag, opt, 1))
            .add("hausdorff", Value::number(r.hausdorff))
            .add("relative", relative(r.hausdorff, diag));
    v.add("seconds", Value::number(r.seconds))
        .add("mode", Value::string(mode_name(opt.mode)))
        .add("threads", Value::integer(opt.threads))
        .add("diagonal", Value::number(diag));
    if (!opt.units.empty()) v.add("units", Value::string(opt.units));
    if (opt.tolerance >= 0) {
        const double d = reported_distance(r, opt.one_sided);
        v.add("tolerance", Value::number(opt.tolerance));
        if (!opt.verdict) {
            v.add("exceeds", Value::boolean(d > opt.tolerance));
        } else {
            v.add("within_tolerance", Value::boolean(d <= opt.tolerance));
            if (!opt.stats) v.add("stopped_early", Value::boolean(false));
        }
    }
    return v;
}

Value stopped_early_json(const TriangleMesh& A, const TriangleMesh& B, int side, const SampledBound& sb,
                         const DistanceReportOptions& opt) {
    Value v = Value::object();
    v.add("a", mesh_json(A)).add("b", mesh_json(B)).add("tolerance", Value::number(opt.tolerance))
        .add("within_tolerance", Value::boolean(false)).add("stopped_early", Value::boolean(true))
        .add("direction", Value::string(side == 0 ? "a_to_b" : "b_to_a")).add("point", vec3(sb.point))
        .add("triangle", Value::integer(sb.triangle)).add("lower", Value::number(sb.value))
        .add("diagonal", Value::number(report_diagonal(A, B)));
    if (!opt.units.empty()) v.add("units", Value::string(opt.units));
    return v;
}

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

Value trace_final_json(const TargetSolver& ts, long steps) {
    const DomainMesh* dm = ts.domain_mesh();  // null for a degenerate target
    return Value::object()
        .add("event", Value::string("final"))
        .add("step", Value::integer(steps))
        .add("target", Value::integer(ts.target()))
        .add("max_sq", Value::number(ts.max_sq()))
        .add("max", Value::number(std::sqrt(ts.max_sq())))
        .add("max_point", vec3(ts.max_point()))
        .add("domains", Value::integer(dm ? dm->num_live_faces() : 0))
        .add("arcs", Value::integer(dm ? dm->num_live_edges() : 0))
        .add("vertices", Value::integer(dm ? dm->num_live_vertices() : 0))
        .add("insertions", Value::integer(ts.insertions()))
        .add("degenerate", Value::boolean(dm == nullptr));
}

// The error map of one direction as PLY: every vertex with its distance, every face with its
// max, mean and RMS distance; "quality" (max on faces) is the scalar field MeshLab reads.
void write_error_ply(const std::string& path, const TriangleMesh& M, const SurfaceStats& s) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
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
    if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path);
}

std::vector<std::string> write_error_maps(const std::string& path, const TriangleMesh& A, const TriangleMesh& B,
                                          const std::vector<SurfaceStats>& stats, bool one_sided) {
    if (one_sided) {
        write_error_ply(path, A, stats.at(0));
        return {path};
    }
    const std::string stem = path.size() > 4 ? path.substr(0, path.size() - 4) : path;
    write_error_ply(stem + "-ab.ply", A, stats.at(0));
    write_error_ply(stem + "-ba.ply", B, stats.at(1));
    return {stem + "-ab.ply", stem + "-ba.ply"};
}

}  // namespace hlens
