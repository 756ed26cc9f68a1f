#pragma once
// Edge flips that improve triangle angles without moving any vertex (GAMer §2.2 lists
// swapping as the second quality tool). A flip is only done where the two triangles are
// nearly coplanar, so the surface shape, and thus the molecule, is not changed.
#include <cstddef>

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
// Vertex positions and indices are unchanged; triangles are rewritten.
std::size_t flip_edges_for_angles(SurfaceMesh& mesh, const FlipOptions& options = {});
std::size_t flip_edges_for_angles(HalfedgeMesh& mesh, const FlipOptions& options = {});

// Flips edges that bring the valences of the four vertices involved closer to 6 (sum of
// squared deviations decreases) when the flip does not lower the minimum angle of the pair
// below `min_angle_deg` (nor below what it was) and passes the same ridge and topology
// tests. Valence near 6 is what lets vertex relocation reach ~60° angles.
std::size_t flip_edges_for_valence(HalfedgeMesh& mesh, const FlipOptions& options = {},
                                   double min_angle_deg = 25.0);

// Flip gate shared by both strategies: topologically legal and not across a ridge.
bool flip_is_geometrically_safe(const HalfedgeMesh& mesh, int h, double max_dihedral_deg);

}  // namespace molmesh
