#pragma once
// Helpers shared by the bindings that produce or consume surfaces.
#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>

#include "types.hpp"

namespace molmesh::python {

// A molmesh.Surface over `mesh` (shared, not copied).
pybind11::object make_surface(std::shared_ptr<const SurfaceMesh> mesh,
                              pybind11::object raw = pybind11::none(),
                              pybind11::object report = pybind11::none());
// Surface.stats(): the --stats keys.
pybind11::object surface_stats(const SurfaceMesh& mesh);
// Surface.write and molmesh.write_surface: chosen by extension.
void write_surface(const std::filesystem::path& path, const SurfaceMesh& mesh);

}  // namespace molmesh::python
