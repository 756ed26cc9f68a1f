#pragma once
// Geomview OFF: "OFF" header (optionally with the counts on the same line), "nv nf ne",
// nv lines "x y z [extras]", nf lines "n i0 ... i(n-1) [colour]"; '#' comments.
// COFF/NOFF/STOFF variants are read (extra per-vertex fields ignored).
#include <ostream>
#include <string>
#include <string_view>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

SurfaceMesh parse_off(std::string_view text, const std::string& name);
void write_off(std::ostream& out, const SurfaceMesh& mesh);

}  // namespace molmesh
