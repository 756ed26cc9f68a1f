#pragma once
// Marker values shared by the mesher, the writers, the hierarchy and the solvers. The
// table and its translation to MCSF boundary types is documented in docs/formats.md.
#include <algorithm>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/geometry/sphere_union.hpp"

namespace molmesh::markers {

// Region (cell) markers.
inline constexpr int kMoleculeRegion = 1;
inline constexpr int kSolventRegion = 2;

// Boundary-face markers (TetMesh::boundary_face_markers, SurfaceMesh::face_markers) and
// vertex markers (0 = not on a marked boundary). A face lies in the active site when all
// three of its vertices are inside the union of the active-site spheres.
inline constexpr int kNoMarker = 0;
inline constexpr int kMolecularSurface = 1;
inline constexpr int kOuterSphere = 2;
inline constexpr int kActiveSite = 3;

// The one active-site rule: triangle t of `points` is in the active site when all three
// of its vertices lie in the union of the spheres.
inline bool in_active_site(const std::vector<Vec3>& points, const Triangle& t,
                           const std::vector<Sphere>& spheres) {
  return std::all_of(t.begin(), t.end(),
                     [&](int v) { return in_any(spheres, points[static_cast<std::size_t>(v)]); });
}

// A vertex on faces with different markers carries the highest-ranked one: the active site
// wins over the molecular surface, which wins over the outer sphere. Markers outside this
// table rank like kNoMarker.
constexpr int vertex_marker_rank(int marker) {
  switch (marker) {
    case kActiveSite:
      return 3;
    case kMolecularSurface:
      return 2;
    case kOuterSphere:
      return 1;
    default:
      return 0;
  }
}

}  // namespace molmesh::markers
