#include "stats_flow.h"

#include <cstdio>

#include "report.h"

namespace hlens::gui {

const char* colour_by_name(ColourBy c) { return c == ColourBy::Mean ? "mean" : c == ColourBy::Rms ? "rms" : "max"; }

namespace {
void start(AppState& s, StatsJob& job) {
    StatsView& v = s.stats;
    v.dir = {};
    v.cancelled = false;
    v.failed.clear();
    const double distance[2] = {s.result.a_to_b.distance, s.result.b_to_a.distance};
    job.start(s.scene, distance, s.tolerance);
}
}  // namespace

bool update_stats(AppState& s, const Requests& req, StatsJob& job) {
    StatsView& v = s.stats;
    const bool current = s.scene && job.scene() == s.scene.get();
    if (req.stats_cancel && job.running()) {
        job.cancel();
        v.cancelled = true;
    }
    bool arrived = false;
    if (auto out = job.take_result(); out && current && s.computed) {
        if (out->dir[0]) {
            v.dir = out->dir;
            v.tolerance = out->tolerance;
            arrived = true;
        } else if (!out->error.empty()) {
            v.failed = out->error;
            std::fprintf(stderr, "hlens: statistics: %s\n", v.failed.c_str());
        }
    }
    if (req.stats_start) {   // (again: at the current tolerance)
        v.wanted = true;
        if (s.computed && s.scene && s.scene->grid) start(s, job);
    }
    if (job.running() && !current && !job.cancelling()) job.cancel();   // older meshes
    const bool missing = v.wanted && s.computed && s.scene && s.scene->grid && !v.ready() && !v.cancelled && v.failed.empty();
    if (missing && !job.running()) start(s, job);
    v.running = job.running() && current;
    v.progress = job.progress();
    v.phase = job.phase();
    v.elapsed = job.elapsed_seconds();
    return arrived;
}

std::vector<double> colour_values(const AppState& s, int d) {
    const SurfaceStats* st = s.stats.dir[d].get();
    if (s.colour_by == ColourBy::Max || !st || st->triangles.size() != s.exact[d].value.size()) return s.exact[d].value;
    std::vector<double> v(st->triangles.size());
    for (size_t t = 0; t < v.size(); ++t) v[t] = s.colour_by == ColourBy::Mean ? st->triangles[t].mean() : st->triangles[t].rms();
    return v;
}

bool export_error_maps(AppState& s) {
    if (!s.stats.ready()) {
        s.errors_pending = true;
        s.stats.wanted = true;
        return true;
    }
    s.errors_pending = false;
    s.errors_written.clear();
    s.errors_ok = false;
    const std::string& p = s.errors_path;
    if (p.size() < 5 || p.compare(p.size() - 4, 4, ".ply") != 0) {
        s.errors_status = "the error map's path must end in .ply, got '" + p + "'";
        return false;
    }
    try {
        s.errors_written = write_error_maps(p, s.scene->mesh[0], s.scene->mesh[1], {*s.stats.dir[0], *s.stats.dir[1]}, false);
        s.errors_status = "wrote " + s.errors_written[0] + "\nand " + s.errors_written[1];
        s.errors_ok = true;
    } catch (const std::exception& e) {
        s.errors_status = std::string("export failed: ") + e.what();
    }
    return s.errors_ok;
}

MeshAbove mesh_above(const AppState& s, int d) {
    MeshAbove r;
    if (!s.scene || s.tolerance < 0) return r;
    const TriangleMesh& m = s.scene->mesh[d];
    const std::vector<double>& mx = s.exact[d].value;
    for (size_t t = 0; t < m.num_triangles(); ++t) {
        const auto c = m.corners(t);
        const double a = 0.5 * norm(cross(c[1] - c[0], c[2] - c[0]));
        r.area += a;
        if (t < mx.size() && mx[t] > s.tolerance) ++r.triangles, r.bound += a;
    }
    const SurfaceStats* st = s.stats.dir[d].get();
    if (st && s.stats.tolerance == s.tolerance) r.exact = st->area_above, r.fraction = st->fraction_above;
    return r;
}

}  // namespace hlens::gui
