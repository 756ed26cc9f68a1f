#pragma once
// Wavefront OBJ: "v x y z [w | r g b]" and "f" records whose corners are "i", "i/t",
// "i//n" or "i/t/n" (1-based; negative = relative to the last vertex). Polygons are
// fan-triangulated; other records (vt, vn, g, o, s, usemtl, mtllib, l, ...) are ignored.
#include <ostream>
#include <string>
#include <string_view>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

SurfaceMesh parse_obj(std::string_view text, const std::string& name);
void write_obj(std::ostream& out, const SurfaceMesh& mesh);

}  // namespace molmesh
