#include "compute.h"

#include <chrono>
#include <cmath>
#include <thread>

#include <hlens/mesh_io.h>

namespace hlens::gui {

Worker::~Worker() = default;

void Worker::launch(std::function<void()> body) {
    stop();
    cancel_.store(false);
    progress_.store(-1);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        phase_.clear();
    }
    start_ = std::chrono::steady_clock::now();
    running_.store(true);
    thread_ = std::thread([this, body = std::move(body)] {
        body();
        running_.store(false);
    });
}

void Worker::stop() {
    if (thread_.joinable()) {
        cancel_.store(true);
        thread_.join();
    }
}

std::string Worker::phase() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return phase_;
}

void Worker::set_phase(std::string s) {
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = std::move(s);
}

double Worker::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

// ---------------------------------------------------------------- ComputeJob

namespace {
LoadError to_load_error(int side, const std::string& path, const std::string& message) {
    LoadError e;
    e.side = side;
    e.file = path;
    const std::string prefix = path + ": ";
    e.reason = message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
    return e;
}
}  // namespace

void ComputeJob::start(const TriangleMesh& a, const TriangleMesh& b) { start_impl("", "", std::make_shared<std::array<TriangleMesh, 2>>(std::array<TriangleMesh, 2>{a, b})); }

void ComputeJob::start(const std::string& path_a, const std::string& path_b) { start_impl(path_a, path_b, nullptr); }

void ComputeJob::start_impl(const std::string& path_a, const std::string& path_b, std::shared_ptr<std::array<TriangleMesh, 2>> given) {
    launch([this, path_a, path_b, given] {
        ComputeOutput out;
        auto scene = std::make_shared<LoadedScene>();
        const std::string paths[2] = {path_a, path_b};
        if (given) {
            scene->mesh[0] = (*given)[0];
            scene->mesh[1] = (*given)[1];
        }
        for (int side = 0; side < 2 && !given; ++side) {   // both files, so both errors are reported
            set_phase(std::string("Loading ") + (side == 0 ? "A" : "B") + ": " + paths[side]);
            try {
                scene->mesh[side] = load_mesh(paths[side]);
            } catch (const MeshError& e) {
                out.errors.push_back(to_load_error(side, paths[side], e.what()));
            } catch (const std::exception& e) {
                out.errors.push_back(to_load_error(side, paths[side], std::string("unexpected error: ") + e.what()));
            }
        }
        try {
            if (out.errors.empty()) {
                set_phase("Building the voxel grid");
                scene->grid = std::make_unique<VoxelGrid>(scene->mesh[0], scene->mesh[1]);
                {
                    std::lock_guard<std::mutex> lock(mutex_);
                    scene_ = scene;
                }
                HausdorffOptions opt;
                opt.cancel = &cancel_flag();
                auto t0 = std::chrono::steady_clock::now();
                for (int side = 0; side < 2 && !cancel_flag().load(); ++side) {
                    set_phase(side == 0 ? "h(A,B)" : "h(B,A)");
                    set_progress(0.5 * side);
                    opt.progress = [this, side](double f) { set_progress(0.5 * side + 0.5 * f); };
                    OneSidedResult r = one_sided(*scene->grid, side, opt);
                    (side == 0 ? out.result.a_to_b : out.result.b_to_a) = std::move(r);
                }
                out.cancelled = cancel_flag().load();
                out.computed = !out.cancelled;
                out.result.hausdorff = std::max(out.result.a_to_b.distance, out.result.b_to_a.distance);
                out.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                set_progress(1);
            }
        } catch (const std::exception& e) {   // never let an exception escape the thread
            out.errors.push_back(LoadError{-1, "", std::string("computation failed: ") + e.what()});
        }
        set_phase(out.errors.empty() ? (out.cancelled ? "Cancelled" : "Done") : "Failed");
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(out);
    });
}

std::shared_ptr<const LoadedScene> ComputeJob::take_scene() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::move(scene_);
}

std::optional<ComputeOutput> ComputeJob::take_result() { return take_when_ended(result_); }

// ---------------------------------------------------------------- ExactMapJob

void ExactMapJob::start(std::shared_ptr<const LoadedScene> scene, int side, std::vector<uint32_t> order, int pace_ms) {
    stop();   // the previous run's thread is joined before its state is reset
    {
        std::lock_guard<std::mutex> lock(mutex_);
        values_.clear();
        ended_ = false;
    }
    scene_ = scene;
    side_ = side;
    total_ = order.size();
    solved_.store(0);
    launch([this, scene, side, pace_ms, order = std::move(order)]() mutable {
        set_phase("exact colour map");
        try {
            TargetMaximaOptions opt;
            opt.cancel = &cancel_flag();
            opt.order = std::move(order);
            opt.progress = [this](double f) { set_progress(f); };
            opt.on_target = [this, pace_ms](uint32_t t, double d) {
                {
                    std::lock_guard<std::mutex> lock(mutex_);
                    values_.emplace_back(t, d);
                    solved_.fetch_add(1);
                }
                if (pace_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(pace_ms));
            };
            if (!opt.order.empty()) exact_target_maxima(*scene->grid, side, opt);
            set_phase(cancel_flag().load() ? "Cancelled" : "Done");
        } catch (const std::exception& e) {   // never let an exception escape the thread
            set_phase(std::string("failed: ") + e.what());
        }
        std::lock_guard<std::mutex> lock(mutex_);
        ended_ = true;
    });
}

std::vector<std::pair<uint32_t, double>> ExactMapJob::take_values() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<uint32_t, double>> v;
    v.swap(values_);
    return v;
}

bool ExactMapJob::take_ended() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!ended_ || !values_.empty()) return false;
    ended_ = false;
    return true;
}

// ---------------------------------------------------------------- StatsJob

void StatsJob::start(std::shared_ptr<const LoadedScene> scene, const double distance[2], double tolerance) {
    stop();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        result_.reset();
    }
    scene_ = scene;
    const double known[2] = {distance[0], distance[1]};
    launch([this, scene, known, tolerance] {
        StatsOutput out;
        out.tolerance = tolerance;
        try {
            std::array<std::shared_ptr<const SurfaceStats>, 2> dir;
            for (int side = 0; side < 2 && !cancel_flag().load(); ++side) {
                set_phase(side == 0 ? "statistics of h(A,B)" : "statistics of h(B,A)");
                StatsOptions opt;
                opt.histogram_bins = kStatsBins;
                opt.tolerance = tolerance;
                opt.known_max = known[side];
                opt.cancel = &cancel_flag();
                opt.progress = [this, side](double f) { set_progress(0.5 * side + 0.5 * f); };
                auto st = std::make_shared<SurfaceStats>(surface_stats(*scene->grid, side, opt));
                if (st->cancelled) break;
                dir[side] = std::move(st);
            }
            if (dir[0] && dir[1] && !cancel_flag().load()) out.dir = dir;
            set_phase(out.dir[0] ? "Done" : "Cancelled");
        } catch (const std::exception& e) {   // never let an exception escape the thread
            out.error = e.what();
            set_phase(std::string("failed: ") + e.what());
        }
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(out);
    });
}

std::optional<StatsOutput> StatsJob::take_result() { return take_when_ended(result_); }

// ---------------------------------------------------------------- TraceJob

void TraceJob::start(std::shared_ptr<const LoadedScene> scene, int side, uint32_t target) {
    side_ = side;
    target_ = target;
    scene_ = scene;
    launch([this, scene, side, target] {
        TraceSummary s;
        s.side = side;
        s.target = target;
        auto t0 = std::chrono::steady_clock::now();
        try {
            auto ts = std::make_shared<TargetSolver>(*scene->grid, side, target);
            ts->record_events();   // the whole stream, for the event log
            while (!cancel_flag().load() && ts->step())
                if (ts->insertions() % 16 == 0) set_phase("insertion " + std::to_string(ts->insertions()));
            s.cancelled = !ts->finished();
            s.insertions = ts->insertions();
            if (const DomainMesh* dm = ts->domain_mesh()) {
                s.domains = dm->num_live_faces();
                s.arcs = dm->num_live_edges();
                s.vertices = dm->num_live_vertices();
            }
            s.max = std::sqrt(ts->max_sq());
            s.max_point = ts->max_point();
            s.degenerate = ts->frame().degenerate;
            s.solver = std::move(ts);
        } catch (const std::exception& e) {
            s.error = e.what();
        }
        s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(s);
    });
}

std::optional<TraceSummary> TraceJob::take_result() { return take_when_ended(result_); }

}  // namespace hlens::gui
