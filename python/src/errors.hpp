#pragma once
// Python exception types for the library's errors (docs/python.md, "Errors"):
//   molmesh::InputError  -> molmesh.InputError(molmesh.Error, ValueError), .file / .line
//   molmesh::OutputError -> molmesh.OutputError(molmesh.Error, OSError)
//   molmesh::Error       -> molmesh.Error(Exception)
// and molmesh.Warning(UserWarning) for the library's warnings.
#include <pybind11/pybind11.h>

namespace molmesh::python {

void bind_errors(pybind11::module_& m);

// molmesh.Warning (valid after bind_errors).
PyObject* warning_type();

}  // namespace molmesh::python
