#pragma once
// Feature-adaptive coarsening, GAMer §2.3 Eq. 6: a vertex x is deleted iff
//   L(x)^alpha * (lambda2(x) / lambda1(x))^beta < T0,
// with L the longest incident edge (Å) and lambda the local structure tensor eigenvalues
// (structure_tensor.hpp), and its hole re-triangulated. Flat, dense regions thin out;
// ridges, valleys and concavities (lambda2 ~ lambda1) stay dense. Vertices are never moved
// or created, only deleted, so the output is a subset of the input vertices.
#include <cstddef>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct CoarsenOptions {
  double t0 = 0.2;     // threshold T0 of Eq. 6; larger deletes more
  double alpha = 1.0;  // exponent on L(x): weight of sparseness
  double beta = 1.0;   // exponent on lambda2/lambda1: weight of curvature
  int rings = 2;       // k-ring of the structure tensor
  // No vertex inside the union of these balls is deleted (paper Fig. 5: dense active site).
  std::vector<Sphere> keep_spheres;
  // Each pass deletes an independent set (no two deleted vertices adjacent), then re-
  // evaluates Eq. 6. Stops earlier when a pass deletes nothing. Six passes approximate the
  // paper's single sequential sweep; run coarsen again (e.g. with another T0) for the
  // paper's repeated coarsening.
  int max_passes = 6;
  // After deleting, flip edges towards valence 6 on flat regions (never across ridges,
  // never inside keep-spheres), which gives the later angle relocation room to reach ~60°.
  bool equalize_valence = true;
};

struct CoarsenResult {
  SurfaceMesh mesh;
  std::vector<int> provenance;  // output vertex -> input vertex index
  std::size_t removed = 0;      // vertices deleted
  int passes = 0;               // passes that ran
};

// Throws molmesh::Error if the input is not a closed, oriented 2-manifold, or on invalid
// options (t0 <= 0 is allowed and deletes nothing). Keeps Euler characteristic and the
// number of connected components; no component drops below 4 vertices. Deterministic and
// independent of the thread count.
CoarsenResult coarsen(const SurfaceMesh& mesh, const CoarsenOptions& options,
                      const Reporter& reporter = {});

}  // namespace molmesh
