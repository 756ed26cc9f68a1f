#pragma once
// Triangle surface meshes in the common exchange formats, chosen by extension:
// .off, .ply (ascii or binary little/big endian when reading; binary little endian when
// writing), .obj, .stl (ascii or binary). Details in docs/formats.md.
#include <filesystem>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Polygons are fan-triangulated; STL's repeated corner coordinates are merged exactly.
// Throws InputError (file:line: what) for missing files and malformed content.
SurfaceMesh read_surface_mesh(const std::filesystem::path& path);

// Atomic (temporary file + rename). Markers are written where the format allows (PLY).
void write_surface_mesh(const std::filesystem::path& path, const SurfaceMesh& mesh);

// True when the extension names a surface format this module reads and writes.
bool is_surface_mesh_path(const std::filesystem::path& path);

}  // namespace molmesh
