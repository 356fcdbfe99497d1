// One reference mesh against many files, for `hlens-cli batch` and hlens.batch().
//
// The reference is loaded once by the caller. Its voxel grid cannot be reused: core's VoxelGrid
// indexes both meshes of a pair together (one grid over their union), so every pair builds its own.
// `jobs` pairs run at a time, each with `threads` worker threads; results come out in the order
// the pairs finish. A file that cannot be read or compared becomes an item with its error and
// does not stop the others.
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <hlens/hausdorff.h>
#include <hlens/mesh.h>
#include <hlens/mesh_io.h>
#include <hlens/surface_stats.h>
#include <hlens/voxel_grid.h>

namespace hlens {

struct BatchOptions {
    Mode mode = Mode::Fast;
    int threads = 0;           // per pair; 0: all cores divided among the jobs
    int jobs = 1;              // pairs compared at the same time
    bool one_sided = false;    // h(reference, file) only
    LoadOptions load;
    // --stats: each pair also gets the surface statistics of each direction (report.h's
    // direction_stats with these options; threads and cancel are the runner's)
    bool stats = false;
    StatsOptions stats_options;
};

struct BatchItem {
    size_t index = 0;          // position of the file in the list
    std::string path;
    const TriangleMesh* reference = nullptr;  // the runner's reference (A of the pair)
    bool ok = false;
    bool unexpected = false;   // the error is not a problem of the input (an internal error)
    std::string error;         // when !ok: the message ("<path>: ...")
    TriangleMesh mesh;         // the file's mesh, when ok
    HausdorffResult result;
    std::vector<SurfaceStats> stats;  // with BatchOptions::stats: per direction (a_to_b, b_to_a)
};

class BatchRunner {
public:
    BatchRunner(const TriangleMesh& reference, std::vector<std::string> paths, const BatchOptions& opt);
    ~BatchRunner();            // stops the pairs still running and waits for them
    BatchRunner(const BatchRunner&) = delete;
    BatchRunner& operator=(const BatchRunner&) = delete;

    // The next finished pair, waiting at most `timeout`; false if none finished in that time or
    // every item was already taken (then done()).
    bool next(BatchItem& out, std::chrono::milliseconds timeout);
    bool done() const;
    void cancel() { cancel_ = true; }
    int threads_per_pair() const { return threads_; }

private:
    void work();
    BatchItem compare(size_t index) const;
    bool add_stats(BatchItem& item, const VoxelGrid& grid) const;  // false if cancelled

    const TriangleMesh& reference_;
    std::shared_ptr<const MeshGrid> reference_grid_;  // built once, shared by every pair
    const std::vector<std::string> paths_;
    BatchOptions opt_;
    int threads_ = 1;
    std::atomic<bool> cancel_{false};
    std::atomic<size_t> next_index_{0};
    mutable std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<BatchItem> finished_;
    size_t taken_ = 0;
    std::vector<std::thread> workers_;
};

}  // namespace hlens
