#include "batch.h"

#include <algorithm>
#include <exception>
#include <utility>

#include "report.h"

namespace hlens {

BatchRunner::BatchRunner(const TriangleMesh& reference, std::vector<std::string> paths, const BatchOptions& opt)
    : reference_(reference), reference_grid_(std::make_shared<const MeshGrid>(reference)), paths_(std::move(paths)), opt_(opt) {
    const int jobs = (int)std::clamp<size_t>(opt.jobs < 1 ? 1 : (size_t)opt.jobs, 1, std::max<size_t>(1, paths_.size()));
    const int cores = (int)std::max(1u, std::thread::hardware_concurrency());
    threads_ = opt.threads > 0 ? opt.threads : std::max(1, cores / jobs);
    for (int j = 0; j < jobs && !paths_.empty(); ++j) workers_.emplace_back([this] { work(); });
}

BatchRunner::~BatchRunner() {
    cancel_ = true;
    for (std::thread& t : workers_) t.join();
}

void BatchRunner::work() {
    for (;;) {
        const size_t i = next_index_++;
        if (i >= paths_.size()) return;
        BatchItem item;
        if (cancel_) {
            item.reference = &reference_;
            item.index = i;
            item.path = paths_[i];
            item.error = paths_[i] + ": cancelled";
        } else {
            item = compare(i);
        }
        std::lock_guard<std::mutex> lock(mutex_);
        finished_.push_back(std::move(item));
        ready_.notify_all();
    }
}

BatchItem BatchRunner::compare(size_t index) const {
    BatchItem item;
    item.index = index;
    item.path = paths_[index];
    item.reference = &reference_;
    try {
        item.mesh = load_mesh(item.path, opt_.load);
        HausdorffOptions h;
        h.mode = opt_.mode;
        h.threads = threads_;
        h.cancel = &cancel_;
        const VoxelGrid grid(reference_grid_, std::make_shared<const MeshGrid>(item.mesh));
        item.result = hausdorff(grid, h, opt_.one_sided);
        item.ok = !item.result.a_to_b.cancelled && !item.result.b_to_a.cancelled;
        if (item.ok && opt_.stats) item.ok = add_stats(item, grid);
        if (!item.ok) item.error = item.path + ": cancelled";
    } catch (const MeshError& e) {
        item.error = e.what();
    } catch (const std::exception& e) {
        item.unexpected = true;
        item.error = item.path + ": unexpected error: " + e.what();
    }
    if (!item.ok) { item.mesh = TriangleMesh(); item.stats.clear(); }
    return item;
}

bool BatchRunner::add_stats(BatchItem& item, const VoxelGrid& grid) const {
    StatsOptions o = opt_.stats_options;
    o.threads = threads_;
    o.cancel = &cancel_;
    item.stats = direction_stats(grid, item.result, opt_.one_sided, o);
    return std::none_of(item.stats.begin(), item.stats.end(), [](const SurfaceStats& s) { return s.cancelled; });
}

bool BatchRunner::next(BatchItem& out, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!ready_.wait_for(lock, timeout, [this] { return !finished_.empty(); })) return false;
    out = std::move(finished_.front());
    finished_.pop_front();
    ++taken_;
    return true;
}

bool BatchRunner::done() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return taken_ == paths_.size();
}

}  // namespace hlens
