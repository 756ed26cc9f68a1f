#include "progress.hpp"

#include <string>

#include "casters.hpp"
#include "errors.hpp"

namespace molmesh::python {

PythonProgress::PythonProgress(py::object callback)
    : callback_(std::move(callback)), state_(std::make_shared<State>()) {
  if (!callback_.is_none()) {
    if (!PyCallable_Check(callback_.ptr()))
      throw py::type_error("progress must be None or a callable taking (stage, fraction)");
    state_->callback = callback_.ptr();
  }
  // The lambdas hold the state, not the Python objects: copies of the Reporter that the
  // library keeps on worker threads may be destroyed without the GIL.
  std::shared_ptr<State> state = state_;
  reporter_.on_progress = [state](std::string_view stage, double fraction) {
    report(*state, stage, fraction);
  };
  reporter_.on_warning = [state](std::string_view message) { warn(*state, message); };
}

void PythonProgress::abort_with_python_error(State& state) {
  // GIL held, a Python error set.
  {
    const std::lock_guard lock(state.mutex);
    if (!state.error) state.error.emplace();  // fetches (and clears) the Python error
  }
  PyErr_Clear();  // a later error (another thread) is dropped: the first one wins
  state.aborted = true;
  throw Aborted{};
}

void PythonProgress::report(State& state, std::string_view stage, double fraction) {
  if (state.aborted) throw Aborted{};
  py::gil_scoped_acquire gil;
  if (state.aborted) throw Aborted{};
  // Runs Python's signal handlers (on the main thread only; other threads return 0), so
  // Ctrl-C raises KeyboardInterrupt here even without a callback.
  if (PyErr_CheckSignals() != 0) abort_with_python_error(state);
  if (state.callback == nullptr) return;
  PyObject* name = PyUnicode_FromStringAndSize(stage.data(), static_cast<Py_ssize_t>(stage.size()));
  PyObject* value = PyFloat_FromDouble(fraction);
  PyObject* result =
      name && value ? PyObject_CallFunctionObjArgs(state.callback, name, value, nullptr) : nullptr;
  Py_XDECREF(name);
  Py_XDECREF(value);
  if (result == nullptr) abort_with_python_error(state);
  Py_DECREF(result);
}

void PythonProgress::warn(State& state, std::string_view message) {
  if (state.aborted) throw Aborted{};
  py::gil_scoped_acquire gil;
  const std::string text(message);
  // -1 when a warnings filter turned the warning into an exception.
  if (PyErr_WarnEx(warning_type(), text.c_str(), 1) != 0) abort_with_python_error(state);
}

void PythonProgress::raise_stored() {
  std::optional<py::error_already_set> error;
  {
    const std::lock_guard lock(state_->mutex);
    error.swap(state_->error);
  }
  if (!error) throw std::runtime_error("molmesh: stage aborted without a Python error");
  throw std::move(*error);
}

}  // namespace molmesh::python
