#pragma once
#include <pybind11/pybind11.h>

#include <memory>

#include "types.hpp"

namespace molmesh::python {

// A molmesh.Hierarchy over `hierarchy` (shared, not copied).
pybind11::object make_hierarchy(std::shared_ptr<const Hierarchy> hierarchy,
                                pybind11::object report = pybind11::none());

}  // namespace molmesh::python
