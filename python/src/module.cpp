// molmesh._core: the compiled half of the `molmesh` package (python/molmesh/__init__.py
// re-exports it). docs/python.md is the user's guide.
#include <pybind11/pybind11.h>
#include <tbb/global_control.h>

#include <map>
#include <memory>

#include "bindings.hpp"
#include "casters.hpp"
#include "errors.hpp"
#include "molmesh/core/version.hpp"
#include "options.hpp"

namespace molmesh::python {
namespace {

std::map<std::string, std::function<py::dict()>>& defaults_registry() {
  static std::map<std::string, std::function<py::dict()>> registry;
  return registry;
}

// `with molmesh.thread_limit(n):` caps TBB's worker threads (results do not depend on it).
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads) : threads_(threads) {
    if (threads < 1) throw py::value_error("thread_limit needs at least 1 thread");
  }
  void enter() {
    control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                     static_cast<std::size_t>(threads_));
  }
  void exit() { control_.reset(); }

 private:
  int threads_;
  std::unique_ptr<tbb::global_control> control_;
};

}  // namespace

void register_defaults(const std::string& function, std::function<py::dict()> defaults) {
  defaults_registry()[function] = std::move(defaults);
}

py::object json_to_python(const std::string& json_text) {
  return py::module_::import("json").attr("loads")(json_text);
}

void reject_unknown(const py::dict& kwargs, const char* function,
                    const std::vector<std::string>& accepted) {
  if (kwargs.empty()) return;
  std::string unknown;
  for (const auto& item : kwargs)
    unknown += (unknown.empty() ? "" : ", ") + std::string(py::str(item.first));
  std::string names;
  for (const auto& n : accepted) names += (names.empty() ? "" : ", ") + n;
  throw py::type_error(std::string(function) + "() got unexpected keyword argument(s) " + unknown +
                       "; accepted: " + names + ", progress");
}

}  // namespace molmesh::python

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  namespace mp = molmesh::python;
  m.doc() = "molmesh: molecules to adaptive surface and tetrahedral meshes (GAMer method)";
  m.attr("__version__") = molmesh::version();  // project(VERSION), as `molmesh --version`
  mp::bind_errors(m);
  mp::bind_atoms(m);
  mp::bind_surface(m);
  mp::bind_improve(m);
  mp::bind_tetmesh(m);
  mp::bind_hierarchy(m);
  mp::bind_solvers(m);
  mp::bind_io(m);

  m.def(
      "defaults",
      [](const std::string& function) {
        auto& registry = mp::defaults_registry();
        const auto it = registry.find(function);
        if (it == registry.end()) {
          std::string names;
          for (const auto& [name, _] : registry) names += (names.empty() ? "" : ", ") + name;
          throw py::value_error("no options for '" + function + "'; known: " + names);
        }
        return it->second();
      },
      py::arg("function"),
      "The keyword arguments of a molmesh function with their defaults, which are the "
      "library's (and the CLI's) defaults, e.g. molmesh.defaults('surface')['spacing'].");

  py::class_<mp::ThreadLimit>(m, "thread_limit",
                              "Context manager capping the worker threads: `with "
                              "molmesh.thread_limit(1): ...`. Results never depend on it.")
      .def(py::init<int>(), py::arg("threads"))
      .def(
          "__enter__",
          [](mp::ThreadLimit& t) {
            t.enter();
            return &t;
          },
          py::return_value_policy::reference)
      .def("__exit__", [](mp::ThreadLimit& t, py::args) { t.exit(); });
}
