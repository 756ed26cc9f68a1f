#pragma once
// Stanford PLY. Reads ascii, binary_little_endian and binary_big_endian files with any
// property types and extra elements; uses vertex x/y/z, face vertex_indices (or
// vertex_index), and the optional int properties "marker" on vertices and faces.
// Writes binary_little_endian (exact doubles, compact), with markers when the mesh has them.
#include <ostream>
#include <string>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

SurfaceMesh parse_ply(const std::string& bytes, const std::string& name);
void write_ply(std::ostream& out, const SurfaceMesh& mesh);

}  // namespace molmesh
