#pragma once
// STL, ascii ("solid ... facet normal ... outer loop vertex x y z ...") and binary (80-byte
// header, uint32 count, 50 bytes per triangle). STL repeats every corner; corners with
// bit-identical coordinates are merged into one vertex, which restores the connectivity a
// mesh had when it was written. Written as binary (float32, as the format defines).
#include <ostream>
#include <string>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

SurfaceMesh parse_stl(const std::string& bytes, const std::string& name);
void write_stl(std::ostream& out, const SurfaceMesh& mesh);

}  // namespace molmesh
