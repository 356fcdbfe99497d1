// Running a long computation from Python without holding the interpreter.
//
// The work runs on a worker thread while the calling Python thread waits with the GIL released.
// Every 50 ms the calling thread takes the GIL back to check for signals: Ctrl-C sets the cancel
// flag the core polls (HausdorffOptions::cancel), waits for the worker to stop and raises
// KeyboardInterrupt. The `progress` callable, if any, is called from the calling thread too (the
// core's progress callback runs on worker threads, where Python must not be entered).
#pragma once
#include <pybind11/pybind11.h>

#include <atomic>
#include <functional>

namespace hlens::py_bindings {

namespace py = pybind11;

struct Job {
    std::atomic<bool> cancel{false};
    std::atomic<double> fraction{-1};   // < 0: nothing to report yet
};

// Runs work(job) to its end; rethrows what it threw, or the Python exception (KeyboardInterrupt,
// or one raised by `progress`) that stopped it. `progress` is None or a callable taking a float.
void run_blocking(const std::function<void(Job&)>& work, const py::object& progress);

}  // namespace hlens::py_bindings
