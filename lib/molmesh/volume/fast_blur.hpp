#pragma once
// The fast Gaussian blur of GAMer §4.1: with one decay rate kappa for all atoms (Eq. 2),
//   G(x) = sum_i exp(kappa (|x - c_i|^2 - r_i^2)) = sum_i w_i exp(-|x - c_i|^2 / (2 sigma^2)),
//   w_i = exp(-kappa r_i^2), sigma^2 = -1 / (2 kappa),
// is one Gaussian convolution of the atom weights, so the atoms are splatted onto the grid
// and the grid is filtered by the separable recursive Gaussian (recursive_gaussian.hpp) at a
// cost independent of the number of atoms and of sigma. docs/inputs.md has the measurements.
#include <array>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "molmesh/volume/grid.hpp"
#include "molmesh/volume/recursive_gaussian.hpp"

namespace molmesh {

// How the pipeline evaluates the blurred volume: Eq. 1 summed atom by atom (blur_atoms), or
// Eq. 2 by splatting and recursive filtering (fast_blur).
enum class BlurMethod { kExact, kFast };

// Every method, for the front ends that spell them (CLI --blur, Python blur=).
inline constexpr std::array<BlurMethod, 2> kBlurMethods{BlurMethod::kExact, BlurMethod::kFast};

// "exact", "fast": the spelling of --blur, Python's blur= and the parameters JSON.
inline const char* blur_method_name(BlurMethod method) {
  return method == BlurMethod::kFast ? "fast" : "exact";
}

enum class SplatMethod {
  kTrilinear,  // weight shared among the 8 surrounding nodes (sub-voxel position kept)
  kNearest,    // whole weight on the nearest node, as the paper describes
};

struct FastBlurOptions {
  double kappa = 0.0;  // the constant decay rate of Eq. 2 (1/Å², negative)
  SplatMethod splat = SplatMethod::kTrilinear;
  // Splatting widens the kernel (trilinear: a tent of variance h^2/6 per axis; nearest:
  // h^2/12 on average); when set, the filter's sigma is narrowed by as much so the total
  // width is the intended one.
  bool compensate_splat_width = true;
  RecursiveGaussianDesign design = RecursiveGaussianDesign::kDeriche4;
};

// kappa = B / r_ref^2 with r_ref the mean radius of the atoms with r > 0: the decay rate
// Eq. 1 gives a typical atom (docs/inputs.md explains the choice). Throws molmesh::Error if
// B >= 0 or no atom has a positive radius.
double constant_decay_rate(const Atoms& atoms, double blobbyness);

// Copies of the atoms whose per-atom blobbyness B_i = kappa r_i^2 makes Eq. 1 equal Eq. 2,
// so the exact summation can be compared with the fast one like for like.
Atoms with_constant_decay(const Atoms& atoms, double kappa);

// Evaluates Eq. 2 on `grid`, whose origin, spacing and dims are kept and whose values are
// replaced. Atoms of zero radius add nothing (as in Eq. 1). Deterministic and independent
// of the thread count. Throws molmesh::Error for kappa >= 0, a sigma under half a voxel,
// or an atom outside the grid.
void fast_blur_onto(const Atoms& atoms, const FastBlurOptions& options, Grid& grid,
                    const Reporter& reporter = {});

// Eq. 2 with kappa = constant_decay_rate(atoms, options.blobbyness) on the grid blur_atoms
// would choose for the same atoms with B_i = kappa r_i^2 (origin on multiples of the
// spacing, margin_cells beyond each atom's isovalue reach, enlarged while the field still
// reaches the isovalue on the boundary). Per-atom blobbyness cannot be honoured (one kappa
// for all is the point) and is ignored with a warning. Throws as fast_blur_onto.
Grid fast_blur(const Atoms& atoms, const BlurOptions& options,
               SplatMethod splat = SplatMethod::kTrilinear, const Reporter& reporter = {});

}  // namespace molmesh
