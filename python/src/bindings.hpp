#pragma once
// One bind_* function per source file, called in order by module.cpp.
#include <pybind11/pybind11.h>

#include <functional>
#include <string>

namespace molmesh::python {

void bind_atoms(pybind11::module_& m);
void bind_surface(pybind11::module_& m);
void bind_improve(pybind11::module_& m);
void bind_tetmesh(pybind11::module_& m);
void bind_hierarchy(pybind11::module_& m);
void bind_solvers(pybind11::module_& m);
void bind_io(pybind11::module_& m);

// molmesh.defaults(name): the keyword defaults of function `name`, registered by each
// binding from its option tables.
void register_defaults(const std::string& function, std::function<pybind11::dict()> defaults);

// A Python dict (via the json module) of a JSON document the library produced, so Python
// sees exactly the keys and values the CLI writes.
pybind11::object json_to_python(const std::string& json_text);

}  // namespace molmesh::python
