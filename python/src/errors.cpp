#include "errors.hpp"

#include <exception>
#include <string>

#include "casters.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/pipeline/all_option_specs.hpp"

namespace molmesh::python {
namespace {

namespace py = pybind11;

// Created once at import and kept for the life of the process (exception types are never
// unloaded), so the translator can use them without touching the module.
PyObject* g_error = nullptr;
PyObject* g_input_error = nullptr;
PyObject* g_output_error = nullptr;
PyObject* g_option_error = nullptr;
PyObject* g_warning = nullptr;

PyObject* new_type(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  py::dict namespace_;
  namespace_["__doc__"] = doc;
  namespace_["__module__"] = "molmesh";
  py::object type = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type))(
      name, bases, namespace_);
  m.attr(name) = type;
  return type.release().ptr();
}

void raise(PyObject* type, const char* message) { PyErr_SetString(type, message); }

}  // namespace

// The library names options by their struct members (core/error.hpp); a Python message
// names the keyword argument where the two differ.
std::string with_keywords(std::string_view message) {
  static const OptionSpellings kKeywords = [] {
    OptionSpellings keywords{
        {"max_levels", "`levels`"},
    };
    // The library's option tables, except surface's `coarsen`: its member `t0` is improve()'s
    // and hierarchy()'s keyword (surface() and tetmesh() respell it: tables.hpp).
    for (const OptionSpec* spec : all_option_specs())
      if (spec->member != spec->name && spec != &kSurfaceOptionSpecs.coarsen)
        keywords.emplace(std::string(spec->member), "`" + std::string(spec->name) + "`");
    return keywords;
  }();
  return spell_option_names(message, kKeywords);
}

PyObject* warning_type() { return g_warning; }

void bind_errors(py::module_& m) {
  py::handle exception(PyExc_Exception);
  g_error = new_type(m, "Error", py::make_tuple(exception),
                     "A molmesh request cannot be carried out (bad option value, impossible "
                     "geometry, a stage failed). Base of InputError, OutputError and OptionError.");
  py::handle error(g_error);
  g_input_error =
      new_type(m, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)),
               "An input file is missing, unreadable or malformed (or input arrays are invalid). "
               "Attributes: file (str or None) and line (int, 1-based, or None when the problem is "
               "not on one line).");
  g_output_error = new_type(m, "OutputError", py::make_tuple(error, py::handle(PyExc_OSError)),
                            "An output file could not be written; the target is left untouched.");
  g_option_error =
      new_type(m, "OptionError", py::make_tuple(error, py::handle(PyExc_ValueError)),
               "An option's value is outside its range or what the input allows (the message "
               "names the keyword).");
  g_warning = new_type(m, "Warning", py::make_tuple(py::handle(PyExc_UserWarning)),
                       "A warning from the library (zero radii, repaired input, ...).");

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object instance =
          py::reinterpret_borrow<py::object>(g_input_error)(with_keywords(e.what()));
      instance.attr("file") = e.file().empty() ? py::object(py::none()) : py::str(e.file());
      instance.attr("line") = e.line() == 0 ? py::object(py::none()) : py::int_(e.line());
      PyErr_SetObject(g_input_error, instance.ptr());
    } catch (const OutputError& e) {
      raise(g_output_error, with_keywords(e.what()).c_str());
    } catch (const OptionError& e) {
      raise(g_option_error, with_keywords(e.what()).c_str());
    } catch (const Error& e) {
      raise(g_error, with_keywords(e.what()).c_str());
    }
  });
}

}  // namespace molmesh::python
