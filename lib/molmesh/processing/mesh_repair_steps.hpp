#pragma once
// The steps of repair_surface_mesh (processing/mesh_repair.hpp), in the order it runs them.
// Internal: each step works on the triangle soup being repaired and adds what it did or
// found to the report; only repair_surface_mesh and the tests call them.
#include <cstdint>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/mesh_repair.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh::repair_steps {

using EdgeKey = std::uint64_t;

// One side of an edge: the face and the corner the edge starts at (it runs from `corner`
// to corner + 1). Sorted by key then face, so the uses of one edge are adjacent.
struct EdgeUse {
  EdgeKey key;
  int face;
  int corner;
};

std::vector<EdgeUse> edge_uses(const std::vector<Triangle>& tris);

// Throws Error naming the first triangle that refers to a vertex the mesh does not have.
void check_vertex_indices(const SurfaceMesh& input);

// Maps every vertex to the lowest-numbered vertex within `tol` of it that is itself a
// representative, visiting vertices in input order (deterministic, no chaining drift: a
// representative never moves). Throws Error for a non-finite coordinate.
std::vector<int> merge_map(const std::vector<Vec3>& points, double tol);

// The input's triangles with vertices replaced by their representatives, without those
// that collapsed (two corners one vertex) or repeat an earlier one's three vertices.
std::vector<Triangle> drop_collapsed_and_duplicate_faces(const std::vector<Triangle>& input,
                                                         const std::vector<int>& rep,
                                                         MeshRepairReport& report);

// Counts (and locates) what cannot be repaired: non-manifold edges, boundary edges and
// the holes they bound.
void census_edges(const std::vector<Vec3>& points, const std::vector<Triangle>& tris,
                  const std::vector<EdgeUse>& uses, MeshRepairReport& report);

// Two fans of triangles touching at one vertex: each fan after the first gets its own copy
// of the vertex (appended to `points`). Only meaningful when every edge is manifold.
// Returns whether a vertex was split (then `uses` is stale).
bool split_pinched_vertices(std::vector<Vec3>& points, std::vector<Triangle>& tris,
                            const std::vector<EdgeUse>& uses, MeshRepairReport& report);

// Consistent orientation by breadth-first search over manifold edges; within a component
// the majority's orientation is kept so the fewest faces change. Returns the faces of each
// component.
std::vector<std::vector<int>> orient_components(const std::vector<Vec3>& points,
                                                std::vector<Triangle>& tris,
                                                const std::vector<EdgeUse>& uses,
                                                MeshRepairReport& report);

// Zero-area "caps" (a corner lying on the opposite edge): flipping that edge replaces the
// cap and its neighbour by two triangles covering the same area exactly.
void flip_zero_area_caps(const std::vector<Vec3>& points, std::vector<Triangle>& tris,
                         const std::vector<EdgeUse>& uses, double degenerate_ratio,
                         MeshRepairReport& report);

// A closed component is turned to enclose positive volume unless it is nested in an odd
// number of other components (a cavity wall), then negative.
void orient_outward(const std::vector<Vec3>& points, std::vector<Triangle>& tris,
                    const std::vector<std::vector<int>>& component_faces, MeshRepairReport& report);

// The mesh without unreferenced vertices, the rest in input order.
SurfaceMesh compact(const std::vector<Vec3>& points, const std::vector<Triangle>& tris,
                    MeshRepairReport& report);

}  // namespace molmesh::repair_steps
