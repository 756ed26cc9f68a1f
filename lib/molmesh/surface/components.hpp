#pragma once
// Connected components of a surface and the volume each encloses. With outward normals
// (towards lower F), the outer boundary of the molecule encloses a positive volume and an
// interior cavity a negative one: that sign is how cavities are recognised.
#include <cstddef>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct SurfaceComponent {
  std::vector<int> triangles;  // indices into mesh.triangles, ascending
  double signed_volume = 0.0;  // Å³; < 0 for a cavity
  double area = 0.0;           // Å²
  bool is_cavity() const { return signed_volume < 0.0; }
};

// Components connected through shared vertices, ordered by their smallest triangle index.
std::vector<SurfaceComponent> surface_components(const SurfaceMesh& mesh);

// Removes cavities enclosing less than min_volume (Å³) and the points only they used;
// keeps markers in step. Returns the number of cavities removed through `removed`.
SurfaceMesh drop_small_cavities(const SurfaceMesh& mesh, double min_volume,
                                std::size_t* removed = nullptr);

// Drops points no triangle references and renumbers (markers kept in step).
SurfaceMesh remove_unreferenced_points(const SurfaceMesh& mesh);

}  // namespace molmesh
