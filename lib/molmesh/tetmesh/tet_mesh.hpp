#pragma once
// The plain volume mesh type: positively oriented tetrahedra, a region marker per cell,
// and the boundary (and region-interface) faces with their markers. Marker meanings are in
// docs/formats.md.
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct TetMesh {
  std::vector<Vec3> points;
  std::vector<Tetrahedron> tetrahedra;   // det[v1-v0, v2-v0, v3-v0] > 0
  std::vector<int> cell_markers;         // one per tetrahedron: region id
  std::vector<int> vertex_markers;       // one per point
  std::vector<Triangle> boundary_faces;  // oriented outward from the region they bound
  std::vector<int> boundary_face_markers;
};

}  // namespace molmesh
