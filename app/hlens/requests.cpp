#include "requests.h"

#include <cstdio>
#include <filesystem>

#include <hlens/case_export.h>
#include "cases.h"
#include "exact_map.h"
#include "stats_flow.h"

namespace fs = std::filesystem;

namespace hlens::gui {

namespace {

// What belonged to the previous pair: its errors, selections, traces and meshes.
void forget_pair(AppState& s) {
    s.errors.clear();
    s.selected[0] = s.selected[1] = -1;
    s.trace[0].reset();
    s.trace[1].reset();
    s.scene.reset();
}

// Cancel the computation; stop or continue the exact colour map's fill-in.
void job_requests(AppState& s, const Requests& req, Jobs& jobs) {
    if (req.cancel) jobs.compute.cancel();
    if (req.exact_cancel && jobs.exact.running()) {
        jobs.exact.cancel();
        s.exact[jobs.exact.side()].stopped = true;
    }
    if (req.exact_resume) {
        s.exact[s.direction].stopped = false;
        s.exact[s.direction].failed.clear();
    }
}

// A new pair from the file panel or dropped files, or a built-in case: sets req.recompute.
void pair_requests(AppState& s, Requests& req, Scene& scene) {
    if (req.load) {
        for (int side = 0; side < 2; ++side) {
            s.path[side] = s.edit_path[side] = req.load_path[side];
            s.name[side] = fs::path(s.path[side]).filename().string();
        }
        s.demo = s.path[0] == s.demo_path[0] && s.path[1] == s.demo_path[1];
        s.case_loaded = false;
        forget_pair(s);
        scene.clear();
        req.recompute = true;
    }
    if (!req.load_case.empty() && load_builtin_case(s, req.load_case, req.case_eps)) {
        scene.clear();
        set_direction(s, 0);
        s.selected[0] = 0;   // target 0 of A
        req.recompute = true;
    }
}

}  // namespace

bool act_on_requests(AppState& s, Jobs& jobs, View3D& view, const Options& opt, int& exit_code) {
    Scene& scene = *view.scene;
    Requests req = s.req;
    s.req = Requests{};
    s.req.screenshot = req.screenshot;   // handled after rendering
    job_requests(s, req, jobs);
    pair_requests(s, req, scene);
    if (req.export_case) export_selected(s);
    if (update_stats(s, req, jobs.stats) || req.colours)
        for (int d = 0; d < 2 && s.computed; ++d) show_values(s, scene, d, true);
    if ((req.export_errors || (s.errors_pending && s.stats.ready())) && s.computed && !export_error_maps(s)) {
        std::fprintf(stderr, "hlens: %s\n", s.errors_status.c_str());
        if (s.headless && !opt.export_errors.empty()) {
            exit_code = 2;
            return false;
        }
    }
    if (req.recompute) {
        s.computed = s.cancelled = false;
        s.range[0].valid = s.range[1].valid = false;   // (start_compute clears the exact maps)
        jobs.compute_done = false;
        jobs.start_compute(s);
    }
    frame_camera(view, s, req.home, req.focus);
    if (req.clear_errors) s.errors.clear();
    if (req.set_direction >= 0) set_direction(s, req.set_direction);
    if (req.select >= -1) s.selected[s.direction] = req.select;
    return true;
}

void set_direction(AppState& s, int d) {
    s.direction = d;
    // The measured mesh solid, the other one a wireframe that does not tint the colour map,
    // unless the user set them.
    if (!s.style[d].touched) {
        s.style[d].mode = DrawMode::SolidEdges;
        s.style[d].opacity = 1.0f;
    }
    if (!s.style[1 - d].touched) {
        s.style[1 - d].mode = DrawMode::Wireframe;
        s.style[1 - d].opacity = 0.6f;
    }
}

bool load_builtin_case(AppState& s, const std::string& name, double eps) {
    TriangleMesh a, b;
    double hand = 0;
    if (!make_case(name, eps, a, b, hand)) return false;
    s.case_loaded = true;
    s.case_name = name;
    s.case_eps = eps;
    s.case_mesh[0] = std::move(a);
    s.case_mesh[1] = std::move(b);
    for (int side = 0; side < 2; ++side) {
        s.path[side] = s.edit_path[side] = "";
        s.name[side] = "case " + name + (side == 0 ? " A" : " B");
    }
    s.demo = false;
    forget_pair(s);
    return true;
}

bool export_selected(AppState& s) {
    const int d = s.direction;
    const long t = s.selected[d];
    s.export_ok = false;
    if (t < 0 || !s.scene || !s.scene->grid) {
        s.export_status = "no target selected";
        return false;
    }
    const fs::path dir = s.export_dir.empty() ? fs::path(".") : fs::path(s.export_dir);
    const std::string base = "hlens-case-" + std::to_string(t);
    const std::string tp = (dir / (base + "-target.obj")).string(), sp = (dir / (base + "-sources.obj")).string();
    try {
        export_case(*s.scene->grid, d, (uint32_t)t, tp, sp);
        s.export_status = "wrote " + tp + "\nand " + sp;
        s.export_ok = true;
    } catch (const std::exception& e) {
        s.export_status = std::string("export failed: ") + e.what();
    }
    return s.export_ok;
}

}  // namespace hlens::gui
