#pragma once
// Long library calls from Python, interruptible by Ctrl-C.
//
// run(f) computes f() on a helper thread without the GIL, while the calling thread waits and,
// every kSignalPoll, takes the GIL to run Python's signal handlers (PyErr_CheckSignals: only
// the main thread handles signals). When a handler raises (SIGINT: KeyboardInterrupt) the call
// is cancelled: the library learns of it through its own progress callback (callback()),
// which every long loop of the library calls at a bounded interval (parallel_cells,
// local_search, the planar analyses) and which then throws; the library unwinds, and the
// handler's exception is raised in the calling thread. Loops that report no progress but
// call back into the bindings (a step sink) poll stop_if_cancelled() instead.
//
// The Python progress callable, if any, is called from the library's callback (from worker
// threads, one call at a time, holding the GIL); an exception it raises cancels the call the
// same way and is re-raised as is. The library itself knows nothing of Python.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>

#include "selfalign/analysis/sweep.hpp"

namespace selfalign::python {

namespace py = pybind11;

/// How often the waiting thread runs Python's signal handlers: Ctrl-C is honoured within this
/// plus the library's reporting interval (kProgressInterval, src/analysis/parallel_cells.hpp).
inline constexpr std::chrono::milliseconds kSignalPoll{20};

class PythonProgress {
 public:
  /// callback: a Python callable(done, total), or None. Needs the GIL.
  explicit PythonProgress(const py::object& callback);

  /// The library-side callback: throws (to cancel) once the call is cancelled, else calls the
  /// Python callable (if any) under the GIL. Its copies share state with this object; keep
  /// this object until the call has returned, so that the last reference to the Python
  /// callable is dropped by the caller, under the GIL.
  ProgressCallback callback() const;

  /// Throws (to cancel) once the call is cancelled; no GIL needed (one atomic load).
  void stop_if_cancelled() const;

  /// Runs f() on a helper thread without the GIL (see the header comment) and returns its
  /// result; re-raises Ctrl-C's KeyboardInterrupt, the callable's exception, or f's own.
  /// Needs the GIL.
  template <class F>
  auto run(F&& f) const -> decltype(f()) {
    using R = decltype(f());
    std::optional<std::conditional_t<std::is_void_v<R>, bool, R>> result;
    run_job([&] {
      if constexpr (std::is_void_v<R>) {
        f();
        result.emplace(true);
      } else {
        result.emplace(f());
      }
    });
    if constexpr (!std::is_void_v<R>) return std::move(*result);
  }

 private:
  struct Cancelled {};  // thrown through the library to stop it
  struct State {
    py::object function;
    std::atomic<bool> cancelled{false};
    std::mutex mutex;          // guards error
    std::exception_ptr error;  // why: a signal handler's or the callable's exception
    void cancel(std::exception_ptr e);
  };
  void run_job(const std::function<void()>& job) const;

  std::shared_ptr<State> state_;
};

/// The keyword arguments every sweep takes, turned into SweepOptions (law: every cell's
/// friction law; jerk: sweep_accelerations' jerk limit, +inf: jump accelerations).
SweepOptions sweep_options(int threads, const PythonProgress& progress,
                           const SteadyStateOptions& steady = {},
                           const FrictionLaw& law = {},
                           double jerk = std::numeric_limits<double>::infinity());

}  // namespace selfalign::python
