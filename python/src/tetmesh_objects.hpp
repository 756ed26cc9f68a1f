#pragma once
#include <pybind11/pybind11.h>

#include <memory>

#include "types.hpp"

namespace molmesh::python {

// A molmesh.TetMesh over `mesh` (shared, not copied).
pybind11::object make_tetmesh(std::shared_ptr<const TetMesh> mesh,
                              pybind11::object report = pybind11::none());

}  // namespace molmesh::python
