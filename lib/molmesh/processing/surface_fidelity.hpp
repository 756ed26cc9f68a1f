#pragma once
// The test that keeps a re-triangulation on the surface the mesh stands for, shared by the
// edits that replace triangles (valence removal, poor-triangle collapse).
#include <functional>
#include <span>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"

namespace molmesh {

// True when `project` is empty, or when every triangle's centroid lies within max_distance
// (Å) of its projection onto the surface: the expensive test, so callers run it last.
inline bool centroids_stay_on_surface(const HalfedgeMesh& mesh, std::span<const Triangle> triangles,
                                      const std::function<Vec3(const Vec3&)>& project,
                                      double max_distance) {
  if (!project) return true;
  for (const Triangle& t : triangles) {
    const Vec3 centroid = (mesh.position(t[0]) + mesh.position(t[1]) + mesh.position(t[2])) / 3.0;
    if ((project(centroid) - centroid).norm() > max_distance) return false;
  }
  return true;
}

}  // namespace molmesh
