#pragma once
// Does a surface cut through itself? A surface that does is not the boundary of a solid and
// TetGen refuses it, so the processing steps must never create one.
#include <cstddef>
#include <utility>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Pairs of triangles (i < j) that intersect although they share no edge: triangles sharing
// no vertex are tested edge-against-triangle both ways; triangles sharing one vertex are
// tested with the edges opposite it (any other crossing would have to pass through those).
// Coplanar overlaps are not detected (they do not arise from the processing steps, which
// keep neighbouring triangles from folding). Uses a BVH; parallel; sorted output.
std::vector<std::pair<int, int>> self_intersections(const SurfaceMesh& mesh);

inline std::size_t count_self_intersections(const SurfaceMesh& mesh) {
  return self_intersections(mesh).size();
}

}  // namespace molmesh
