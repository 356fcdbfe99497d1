#include "blocking.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace hlens::py_bindings {

namespace {

// One look from the Python thread, GIL held: false if a Python exception is now pending (it stays
// set in this thread's state until the worker has stopped).
bool poll(Job& job, const py::object& progress, double& reported) {
    if (PyErr_CheckSignals() != 0) return false;
    const double f = job.fraction.load();
    if (progress.is_none() || f < 0 || f == reported) return true;
    reported = f;
    try {
        progress(f);
    } catch (py::error_already_set& e) {
        e.restore();
        return false;
    }
    return true;
}

}  // namespace

void run_blocking(const std::function<void(Job&)>& work, const py::object& progress) {
    Job job;
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false, python_error = false;
    double reported = -1;
    {
        py::gil_scoped_release nogil;
        std::thread worker([&] {
            try {
                work(job);
            } catch (...) {
                error = std::current_exception();
            }
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_all();
        });
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                if (finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) break;
            }
            py::gil_scoped_acquire gil;
            if (!poll(job, progress, reported)) {
                python_error = true;
                job.cancel = true;
                break;
            }
        }
        worker.join();
    }
    if (python_error) throw py::error_already_set();
    if (error) std::rethrow_exception(error);
    if (!progress.is_none() && reported < 1) progress(1.0);
}

}  // namespace hlens::py_bindings
