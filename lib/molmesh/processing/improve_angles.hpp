#pragma once
// Angle-based vertex relocation, GAMer §2.2 Eqs. 4–5: each vertex moves towards the
// weighted mean of its projections onto the bisecting planes of the angles at its
// neighbours, filtered through the local structure tensor so that it slides along flat
// directions and barely moves across ridges. Topology is never changed.
#include <cstdint>
#include <vector>

#include "molmesh/core/reporter.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct ImproveOptions {
  int rings = 2;   // k-ring of the structure tensor
  int sweeps = 8;  // passes over all vertices (each Gauss–Seidel over a colouring)
  // Eq. 5 damps the move along eigenvector e_k by 1/(1 + feature_weight·λ_k), λ normalised
  // so λ1 = 1. 1 is the paper's form; larger values hold vertices closer to the surface.
  double feature_weight = 4.0;
  // A move that flips, folds or degenerates an incident triangle, turns its normal by more
  // than max_normal_turn_deg, or (require_quality) lowers the worst angle quality of the
  // star, is halved up to max_halvings times, then refused.
  double max_normal_turn_deg = 30.0;
  int max_halvings = 4;
  bool require_quality = true;
  // Stop early when a sweep moves fewer than this fraction of the vertices by more than
  // 1e-3 of their mean edge length.
  double converged_fraction = 0.002;
  // Work only where it is needed: after the first sweep, a vertex is revisited only if it
  // or a neighbour moved by more than 1e-3 of the mean edge in the previous sweep (a settled
  // neighbourhood proposes about the same move again). Off: every sweep visits every vertex.
  bool worklist = false;
  // Empty, or one flag per vertex: flagged vertices never move.
  std::vector<std::uint8_t> frozen;
};

// Moves the vertices of `mesh` in place. Works on any triangle mesh; vertices whose star is
// not a closed disc (boundary, non-manifold) stay put. Deterministic and independent of the
// thread count. Reports progress as "improve".
void improve_angles(SurfaceMesh& mesh, const ImproveOptions& options = {},
                    const Reporter& reporter = {});

}  // namespace molmesh
