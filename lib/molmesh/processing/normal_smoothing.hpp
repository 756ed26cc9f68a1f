#pragma once
// Normal-based, feature-preserving smoothing (GAMer §2.3, after refs. 35/49): face normals
// are first diffused anisotropically (a neighbour's normal counts only if it is close to
// this one, so ridges and valleys do not blur), then the vertices are moved so the faces
// take the smoothed normals (Sun et al. 2007 vertex update). Finally the enclosed volume
// is restored by a uniform offset along the vertex normals, so smoothing does not shrink
// the molecule. Topology is never changed.
#include <cstdint>
#include <vector>

#include "molmesh/core/reporter.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct NormalSmoothingOptions {
  // Diffusion of face normals over the faces sharing a vertex, weight
  // area · exp(-((1 - n_f·n_g) / sigma)²). sigma = 0.2 keeps neighbours within ~30° nearly
  // fully and ignores those beyond ~60°, so features sharper than that survive.
  int normal_iterations = 3;
  double sigma = 0.2;
  // Gauss–Seidel passes of the vertex update x += Σ A_f n_f (n_f·(c_f - x)) / Σ A_f.
  int vertex_iterations = 1;
  // The same move guards as improve_angles (no flip, fold, degenerate triangle).
  double max_normal_turn_deg = 30.0;
  bool restore_volume = true;
  // Empty, or one flag per vertex: flagged vertices never move.
  std::vector<std::uint8_t> frozen;
};

// Smooths `mesh` in place. Deterministic and independent of the thread count. Reports
// progress as "smooth".
void smooth_normals(SurfaceMesh& mesh, const NormalSmoothingOptions& options = {},
                    const Reporter& reporter = {});

}  // namespace molmesh
