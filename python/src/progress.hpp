#pragma once
// Running a parallel sweep from Python: the GIL is released while the library computes and
// re-acquired only inside the progress callback, which the library calls from its worker
// threads (one call at a time). An exception raised by the Python callback (KeyboardInterrupt,
// a bug in it) aborts the sweep and is re-raised in the calling thread.

#include <pybind11/pybind11.h>

#include <exception>
#include <limits>
#include <memory>

#include "selfalign/analysis/sweep.hpp"

namespace selfalign::python {

namespace py = pybind11;

class PythonProgress {
 public:
  /// callback: a Python callable(done, total), or None. Needs the GIL.
  explicit PythonProgress(const py::object& callback);

  /// The library-side callback: calls the callable (if any) and checks for Ctrl-C (a
  /// KeyboardInterrupt stops the study). Its copies share state with this object; keep
  /// this object until the sweep has returned, so the last reference to the Python callable is
  /// dropped by the caller, under the GIL.
  ProgressCallback callback() const;

  /// Runs f() without the GIL; re-raises the callback's exception if it raised one.
  template <class F>
  auto run(F&& f) const -> decltype(f()) {
    try {
      py::gil_scoped_release release;
      return f();
    } catch (const Aborted&) {  // the GIL is held again here
      rethrow();
    }
  }

 private:
  struct Aborted {};  // thrown through the library to stop the sweep
  struct State {
    py::object function;
    bool failed = false;       // under the GIL
    std::exception_ptr error;  // the callback's exception (its destructor takes the GIL)
  };
  [[noreturn]] void rethrow() const;

  std::shared_ptr<State> state_;
};

/// The keyword arguments every sweep takes, turned into SweepOptions (law: every cell's
/// friction law; jerk: sweep_accelerations' jerk limit, +inf: jump accelerations).
SweepOptions sweep_options(int threads, const PythonProgress& progress,
                           const SteadyStateOptions& steady = {},
                           const FrictionLaw& law = {},
                           double jerk = std::numeric_limits<double>::infinity());

}  // namespace selfalign::python
