#include "progress.hpp"

namespace selfalign::python {

PythonProgress::PythonProgress(const py::object& callback) : state_(std::make_shared<State>()) {
  if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
    throw py::type_error("progress must be callable or None");
  state_->function = callback;
}

ProgressCallback PythonProgress::callback() const {
  // Also without a Python callable: a long study must stop on Ctrl-C like any Python call.
  return [state = state_](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire gil;
    if (state->failed) throw Aborted{};
    try {
      if (!state->function.is_none()) state->function(done, total);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C (main thread)
    } catch (...) {
      state->failed = true;
      state->error = std::current_exception();
      throw Aborted{};
    }
  };
}

void PythonProgress::rethrow() const { std::rethrow_exception(state_->error); }

SweepOptions sweep_options(int threads, const PythonProgress& progress,
                           const SteadyStateOptions& steady, const FrictionLaw& law,
                           double jerk) {
  SweepOptions o;
  o.threads = threads;
  o.progress = progress.callback();
  o.steady = steady;
  o.law = law;
  o.jerk = jerk;
  return o;
}

}  // namespace selfalign::python
