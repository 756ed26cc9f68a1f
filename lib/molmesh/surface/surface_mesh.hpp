#pragma once
// The plain surface type that flows between stages and to the writers: shared vertices and
// triangles oriented counter-clockwise seen from outside (outward normals). Editing
// algorithms build their own connectivity from it (processing/), and hand back a new one.
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct SurfaceMesh {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  // Optional per-vertex and per-face integer markers (empty, or one per vertex/face).
  // Meaning is set by the producer; docs/formats.md has the table.
  std::vector<int> vertex_markers;
  std::vector<int> face_markers;
};

}  // namespace molmesh
