#pragma once
// Repair of user-supplied triangle meshes (GAMer §4.2) before they enter surface processing:
// what can be fixed without guessing geometry is fixed, what cannot (non-manifold edges,
// holes, non-orientable pieces) is counted and located so the user can fix the source.
#include <cstddef>
#include <string>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct MeshRepairOptions {
  // Vertices closer than this (Å) become one. Exporters that write each face's corners
  // separately (STL, many PLYs) agree to far better than 1e-4 Å; atoms are ~1 Å apart.
  double merge_tolerance = 1e-4;
  // A triangle whose area is below this fraction of its longest edge squared is degenerate.
  double degenerate_ratio = 1e-10;
  // Orient each closed component so normals point out of the region it bounds (cavity
  // walls, nested an odd number of times, point into the cavity).
  bool orient_outward = true;
  // Throw molmesh::Error (with counts and example locations) when the result is not a
  // closed, orientable 2-manifold; otherwise only the report tells.
  bool require_closed_manifold = true;
};

struct MeshRepairReport {
  // Fixed:
  std::size_t merged_vertices = 0;        // removed as duplicates of a nearby vertex
  std::size_t unreferenced_vertices = 0;  // removed, used by no triangle
  std::size_t collapsed_faces = 0;        // dropped: two corners the same vertex
  std::size_t duplicate_faces = 0;        // dropped: same three vertices as an earlier face
  std::size_t flipped_cap_faces = 0;      // zero-area faces with a corner on the opposite edge,
                                          // removed by flipping that edge
  std::size_t remaining_degenerate_faces = 0;  // zero-area faces that could not be flipped
  std::size_t split_vertices = 0;         // vertices where separate fans touched, made one per fan
  std::size_t reoriented_faces = 0;       // flipped to agree with their neighbours
  std::size_t reoriented_components = 0;  // flipped as a whole to face outward
  std::size_t components = 0;
  // Not fixable here:
  std::size_t non_manifold_edges = 0;  // shared by three or more triangles
  std::size_t boundary_edges = 0;      // used by one triangle
  std::size_t holes = 0;               // connected boundary curves
  std::size_t non_orientable_components = 0;
  std::vector<Vec3> non_manifold_edge_examples;  // edge midpoints (at most 5)
  std::vector<Vec3> hole_examples;               // one point on each of up to 5 holes
  std::vector<Vec3> non_orientable_examples;

  bool closed_manifold() const {
    return non_manifold_edges == 0 && boundary_edges == 0 && non_orientable_components == 0;
  }
  // Each problem with counts and example coordinates, '; '-separated; empty when
  // closed_manifold().
  std::string problems() const;
  // One line summarising what was fixed ("nothing to repair" when nothing).
  std::string repairs() const;
};

// Returns the repaired mesh (markers are dropped: faces and vertices are renumbered).
// Throws molmesh::Error for indices out of range, and (require_closed_manifold) for what
// cannot be repaired; `report` is filled either way.
SurfaceMesh repair_surface_mesh(const SurfaceMesh& input, const MeshRepairOptions& options,
                                MeshRepairReport& report, const Reporter& reporter = {});

}  // namespace molmesh
