#pragma once
// Keyword arguments mapped onto the library's own option structs, so every default comes
// from the struct the CLI also starts from (no second copy here or in the stubs). One line
// exposes a field:
//   table.field("spacing", MOLMESH_FIELD(blur.spacing), "grid spacing (Å)");
// The tables also produce the docstrings (with the defaults read from the struct) and
// molmesh.defaults(name).
#include <pybind11/pybind11.h>

#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "casters.hpp"

namespace molmesh::python {

namespace py = pybind11;

// A lambda returning a reference to the member at `path` of an options object.
#define MOLMESH_FIELD(path) \
  [](auto& o) -> auto& { return o.path; }

template <class Options>
class OptionTable {
 public:
  using Setter = std::function<void(Options&, py::handle)>;
  using Getter = std::function<py::object(const Options&)>;
  struct Entry {
    std::string name;
    std::string doc;
    Setter set;
    Getter get;
  };

  // A field converted by pybind11 (float, int, bool, str, list of float, None for optional).
  template <class Access>
  OptionTable& field(std::string name, Access access, std::string doc) {
    using T = std::remove_cvref_t<decltype(access(std::declval<Options&>()))>;
    return custom(
        std::move(name), [access](Options& o, py::handle v) { access(o) = py::cast<T>(v); },
        [access](const Options& o) { return py::cast(access(const_cast<Options&>(o))); },
        std::move(doc));
  }

  // An enum spelled as the CLI spells it ("exact", "fast").
  template <class Access, class Enum>
  OptionTable& choice(std::string name, Access access,
                      std::vector<std::pair<std::string, Enum>> names, std::string doc) {
    std::string spelled;
    for (const auto& [text, value] : names) spelled += (spelled.empty() ? "" : ", ") + text;
    doc += " (one of " + spelled + ")";
    return custom(
        name,
        [access, names, spelled, name](Options& o, py::handle v) {
          const std::string text = py::cast<std::string>(v);
          for (const auto& [candidate, value] : names) {
            if (candidate == text) {
              access(o) = value;
              return;
            }
          }
          throw py::value_error(name + "='" + text + "': expected one of " + spelled);
        },
        [access, names](const Options& o) -> py::object {
          for (const auto& [text, value] : names)
            if (access(const_cast<Options&>(o)) == value) return py::str(text);
          return py::none();
        },
        std::move(doc));
  }

  // Anything else: its own conversion both ways.
  OptionTable& custom(std::string name, Setter set, Getter get, std::string doc) {
    entries_.push_back({std::move(name), std::move(doc), std::move(set), std::move(get)});
    return *this;
  }

  // Every entry of `inner`, applied to the sub-struct `access(options)`.
  template <class Inner, class Access>
  OptionTable& nest(const OptionTable<Inner>& inner, Access access) {
    for (const auto& e : inner.entries()) {
      custom(
          e.name, [access, set = e.set](Options& o, py::handle v) { set(access(o), v); },
          [access, get = e.get](const Options& o) { return get(access(const_cast<Options&>(o))); },
          e.doc);
    }
    return *this;
  }

  // Moves the keyword arguments this table knows from `kwargs` into `options`.
  void take(py::dict& kwargs, Options& options) const {
    for (const auto& e : entries_) {
      if (!kwargs.contains(e.name)) continue;
      py::object value = kwargs.attr("pop")(e.name);
      try {
        e.set(options, value);
      } catch (const py::cast_error&) {
        throw py::type_error(e.name + "=" + std::string(py::repr(value)) +
                             ": wrong type (expected " + describe_type(e.get(options)) + ")");
      }
    }
  }

  // name -> value of every entry in `options` (the defaults for a default-constructed one).
  py::dict values(const Options& options) const {
    py::dict d;
    for (const auto& e : entries_) d[py::str(e.name)] = e.get(options);
    return d;
  }

  // Docstring lines "name (default): doc".
  std::string describe(const Options& defaults) const {
    std::string out;
    for (const auto& e : entries_) {
      out += "    " + e.name + " = " + std::string(py::repr(e.get(defaults))) + ": " + e.doc + "\n";
    }
    return out;
  }

  const std::vector<Entry>& entries() const { return entries_; }

 private:
  static std::string describe_type(const py::object& example) {
    if (example.is_none()) return "a value or None";
    return std::string(py::str(py::type::of(example).attr("__name__")));
  }

  std::vector<Entry> entries_;
};

// Raises TypeError for keyword arguments no table took, naming the accepted ones.
void reject_unknown(const py::dict& kwargs, const char* function,
                    const std::vector<std::string>& accepted);

// The accepted names of several tables, for reject_unknown.
template <class... Tables>
std::vector<std::string> names_of(const Tables&... tables) {
  std::vector<std::string> names;
  (
      [&] {
        for (const auto& e : tables.entries()) names.push_back(e.name);
      }(),
      ...);
  return names;
}

}  // namespace molmesh::python
