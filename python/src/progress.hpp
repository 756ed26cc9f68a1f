#pragma once
// The bridge between the library's Reporter and Python: progress goes to a Python callable
// (or nowhere), warnings to Python's warnings module, and every report checks for Ctrl-C.
// The C++ work runs with the GIL released; a report takes the GIL only for its own
// duration. An exception raised by the callable (or a KeyboardInterrupt, or a warning
// turned into an error by a warnings filter) aborts the stage: the report throws a C++
// exception that unwinds through the library (and through TBB, which carries exceptions
// from worker threads to the caller), and the original Python exception is raised again
// once the GIL is back.
#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

#include "molmesh/core/reporter.hpp"

namespace molmesh::python {

namespace py = pybind11;

class PythonProgress {
 public:
  // `callback`: None (silent) or a callable taking (stage: str, fraction: float).
  explicit PythonProgress(py::object callback);

  // Runs `work(reporter)` with the GIL released and returns its result. Re-raises the
  // Python exception that aborted it, if any. Call with the GIL held.
  template <class Work>
  auto run(Work&& work) {
    try {
      py::gil_scoped_release release;
      return std::forward<Work>(work)(reporter_);
    } catch (const Aborted&) {
      // `release` is gone: the GIL is held again here.
      raise_stored();
    }
  }

  const Reporter& reporter() const { return reporter_; }

 private:
  // Thrown through the library when Python asked to stop. Deliberately not derived from
  // std::exception, so no library `catch (const std::exception&)` can swallow it.
  struct Aborted {};

  struct State {
    PyObject* callback = nullptr;  // borrowed from callback_ (which outlives every report)
    std::atomic<bool> aborted{false};
    std::mutex mutex;
    std::optional<py::error_already_set> error;  // the first exception raised
  };

  [[noreturn]] void raise_stored();
  static void report(State& state, std::string_view stage, double fraction);
  static void warn(State& state, std::string_view message);
  [[noreturn]] static void abort_with_python_error(State& state);

  py::object callback_;
  std::shared_ptr<State> state_;
  Reporter reporter_;
};

}  // namespace molmesh::python
