#pragma once
// Removal of valence-3 and valence-4 vertices on flat parts of the surface. Edge flips
// cannot fix such a vertex when its neighbours already have valence 6 (every flip that
// would raise it lowers two neighbours as much), and a valence-4 vertex's four angles
// average 90°, so relocation cannot bring them into [40°, 80°] either. Removing the vertex
// and re-triangulating its hole moves the irregularity onto neighbours that can take it
// (issue 13: most angles above 80° on mAChE sit at vertices of valence 4 or 5).
#include <cstddef>
#include <functional>
#include <span>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"

namespace molmesh {

struct LowValenceRemovalOptions {
  // The star of a removed vertex and its re-triangulation must be this flat: every old and
  // new triangle's normal within this angle of the star's area-weighted normal. Looser than
  // the flips' ridge test (20°) because the height test below bounds how far the surface
  // moves (mAChE: 20° → 30.8° / 95.1 %, 45° → 31.3° / 95.3 %, 70° as 45°).
  double max_normal_deviation_deg = 45.0;
  // No new triangle with a smaller angle than this (relocation then evens them out).
  double min_new_angle_deg = 20.0;
  // The removed vertex may lie at most this fraction of the star's mean edge length away
  // from the new triangles' planes: a bound on how far the surface moves.
  double max_height_ratio = 0.1;
  // When set (ProcessingOptions::project), no new triangle's centroid may lie farther than
  // max_centroid_distance (Å) from its projection onto the surface the mesh stands for.
  std::function<Vec3(const Vec3&)> project;
  // 0.05 rather than 0.1: the worst centroid mean of eleven proteins 0.0301 → 0.0299 Å.
  double max_centroid_distance = 0.05;
  // No vertex inside one of these is removed (ProcessingOptions::keep_spheres).
  std::span<const Sphere> keep_spheres;
};

// Removes, in vertex-index order (deterministic), every live vertex of valence 3 or 4 whose
// removal lowers the sum of squared deviations from valence 6 of it and its neighbours and
// passes the flatness, angle and height tests; for valence 4 the better of the two diagonals
// is taken. Every edit goes through HalfedgeMesh::remove_vertex. Returns the number removed.
std::size_t remove_low_valence_vertices(HalfedgeMesh& mesh,
                                        const LowValenceRemovalOptions& options = {});

}  // namespace molmesh
