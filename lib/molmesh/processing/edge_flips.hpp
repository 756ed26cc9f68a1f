#pragma once
// Edge flips that improve triangle angles without moving any vertex (GAMer §2.2 lists
// swapping as the second quality tool). A flip is only done where the two triangles are
// nearly coplanar, so the surface shape, and thus the molecule, is not changed.
#include <cstddef>
#include <cstdint>
#include <span>

#include "molmesh/processing/halfedge_mesh.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct FlipOptions {
  // Largest angle between the normals of the two triangles of an edge (and of the two
  // triangles after the flip) for the edge to be flippable. Above it the edge lies on a
  // ridge or valley of the molecular surface; flipping would cut or fill it.
  double max_dihedral_deg = 20.0;
  // A flip must raise the smaller minimum angle of the pair by at least this much, so
  // near-ties (cocircular quads) do not flip back and forth.
  double min_gain_deg = 0.5;
  // Sweeps over all edges; stops earlier when a sweep flips nothing.
  int max_passes = 3;
};

// Flips every edge whose flip raises the minimum angle of its two triangles, subject to the
// ridge test and the topology rules (no duplicate edge, valence >= 3, manifold). Sweeps
// edges in index order, so the result is deterministic. Returns the number of flips done.
// Vertex positions and indices are unchanged; triangles are rewritten. Throws
// molmesh::Error if the mesh is not a closed oriented manifold. `frozen` (empty, or one flag
// per vertex): no flip changes the star of a frozen vertex.
std::size_t flip_edges_for_angles(SurfaceMesh& mesh, const FlipOptions& options = {});
std::size_t flip_edges_for_angles(HalfedgeMesh& mesh, const FlipOptions& options = {},
                                  std::span<const std::uint8_t> frozen = {});

// Flips edges that bring the valences of the four vertices involved closer to 6 (the sum
// of squared deviations from 6 decreases), when the flip passes the ridge and topology
// tests and the smaller minimum angle of the pair after the flip is at least
// min(min_angle_deg, what it was before). Valence near 6 is what lets the vertex
// relocation of quality improvement reach ~60° angles.
std::size_t flip_edges_for_valence(HalfedgeMesh& mesh, const FlipOptions& options = {},
                                   double min_angle_deg = 30.0,
                                   std::span<const std::uint8_t> frozen = {});

// Smallest interior angle of a triangle in radians (0 for a degenerate one).
double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c);

// The gate shared by both strategies: the flip of the edge of halfedge h is topologically
// legal and both the old and the new pair of triangles bend by at most max_dihedral_deg
// (and the new pair does not fold over the old one).
bool flip_is_geometrically_safe(const HalfedgeMesh& mesh, int h, double max_dihedral_deg);

}  // namespace molmesh
