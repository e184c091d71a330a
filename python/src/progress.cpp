#include "progress.hpp"

#include <condition_variable>
#include <thread>

namespace selfalign::python {

PythonProgress::PythonProgress(const py::object& callback) : state_(std::make_shared<State>()) {
  if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
    throw py::type_error("progress must be callable or None");
  state_->function = callback;
}

void PythonProgress::State::cancel(std::exception_ptr e) {
  {
    std::lock_guard lock(mutex);
    if (!error) error = std::move(e);
  }
  cancelled = true;
}

ProgressCallback PythonProgress::callback() const {
  return [state = state_](std::size_t done, std::size_t total) {
    if (state->cancelled) throw Cancelled{};
    if (state->function.is_none()) return;  // a pointer comparison: no GIL needed
    py::gil_scoped_acquire gil;
    if (state->cancelled) throw Cancelled{};
    try {
      state->function(done, total);
    } catch (...) {
      state->cancel(std::current_exception());
      throw Cancelled{};
    }
  };
}

void PythonProgress::stop_if_cancelled() const {
  if (state_->cancelled) throw Cancelled{};
}

void PythonProgress::run_job(const std::function<void()>& job) const {
  std::exception_ptr failure;  // the job's own exception
  {
    py::gil_scoped_release release;
    std::mutex mutex;
    std::condition_variable finished_cv;
    bool finished = false;
    std::jthread worker([&] {
      try {
        job();
      } catch (const Cancelled&) {  // the reason is in state_->error
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard lock(mutex);
      finished = true;
      finished_cv.notify_one();
    });
    std::unique_lock lock(mutex);
    while (!finished_cv.wait_for(lock, kSignalPoll, [&] { return finished; })) {
      if (state_->cancelled) continue;  // already stopping: wait for the library to unwind
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) state_->cancel(std::make_exception_ptr(py::error_already_set()));
      }
      lock.lock();
    }
  }  // joined; the GIL is held again
  if (state_->error) std::rethrow_exception(state_->error);
  if (failure) std::rethrow_exception(failure);
}

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
