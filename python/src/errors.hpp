#pragma once
// Python exception types for the library's errors (docs/python.md, "Errors"):
//   molmesh::InputError  -> molmesh.InputError(molmesh.Error, ValueError), .file / .line
//   molmesh::OutputError -> molmesh.OutputError(molmesh.Error, OSError)
//   molmesh::Error       -> molmesh.Error(Exception)
// and molmesh.Warning(UserWarning) for the library's warnings.
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

namespace molmesh::python {

void bind_errors(pybind11::module_& m);

// molmesh.Warning (valid after bind_errors).
PyObject* warning_type();

// A library message (or help text) with each backquoted struct member that has a keyword
// of another name spelled as that keyword (`max_radius_edge_ratio` -> `max_radius_edge`).
std::string with_keywords(std::string_view message);

}  // namespace molmesh::python
