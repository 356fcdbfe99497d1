// A minimal parallel loop for the drivers: indices taken in order by a pool of threads.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace hlens {

// Run body(i) for i in [0, n) on `threads` workers (the caller is one of them), taking indices in
// increasing order. The first exception stops the loop and is rethrown; `cancel` stops it too.
template <class F>
void parallel_for(size_t n, int threads, const std::atomic<bool>* cancel, F&& body) {
    std::atomic<size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&] {
        for (;;) {
            if (cancel && cancel->load()) return;
            size_t i = next.fetch_add(1);
            if (i >= n) return;
            try {
                body(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                next = n;
            }
        }
    };
    int t = std::max(1, std::min<int>(threads, (int)std::max<size_t>(n, 1)));
    std::vector<std::thread> pool;
    for (int k = 1; k < t; ++k) pool.emplace_back(work);
    work();
    for (auto& th : pool) th.join();
    if (error) std::rethrow_exception(error);
}

// Raise `a` to at least v.
inline void atomic_max(std::atomic<double>& a, double v) {
    double cur = a.load();
    while (v > cur && !a.compare_exchange_weak(cur, v)) {}
}

// Threads for a request: n > 0 as asked, 0 = all cores.
inline int resolve_threads(int n) { return n > 0 ? n : (int)std::max(1u, std::thread::hardware_concurrency()); }

// Counts finished items and calls `callback(fraction)` at most every 100 ms (and at the end), from
// whichever worker thread finishes an item.
struct ProgressTicker {
    const std::function<void(double)>& callback;
    size_t total;
    std::atomic<size_t> done{0};
    std::atomic<long long> last_ms{-1000};
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    ProgressTicker(const std::function<void(double)>& cb, size_t n) : callback(cb), total(n) {}
    void tick() {
        size_t d = ++done;
        if (!callback) return;
        using namespace std::chrono;
        long long ms = duration_cast<milliseconds>(steady_clock::now() - start).count();
        long long prev = last_ms.load();
        if ((ms - prev >= 100 || d == total) && last_ms.compare_exchange_strong(prev, ms)) callback((double)d / total);
    }
};

}  // namespace hlens
