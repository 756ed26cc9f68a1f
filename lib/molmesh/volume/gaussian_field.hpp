#pragma once
// Eq. 1 evaluated exactly at any point, with its gradient: the same sum blur_atoms samples on
// its grid (the same B_i, the same per-atom cutoff at truncation * isovalue), for measuring
// and projecting onto the level set between the grid's samples. The atoms are binned in
// cells as large as the largest cutoff, so a point costs only the atoms of its 27
// neighbouring cells: O(1) per point for a molecule of any size.
#include <array>
#include <cstddef>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/geometry.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh {

class GaussianField {
 public:
  // Throws as blur_atoms for invalid options or atoms (check_blur_options, blurred_atoms).
  GaussianField(const Atoms& atoms, const BlurOptions& options);

  // F(p), and its gradient when `gradient` is given. Thread-safe; the sum runs over the atoms
  // in a fixed order, so the result does not depend on the caller's threads.
  double value(const Vec3& p, Vec3* gradient = nullptr) const;

 private:
  struct Kernel {
    Vec3 center;
    double a = 0.0;      // B_i / r_i^2
    double scale = 0.0;  // exp(-B_i)
    double cutoff2 = 0.0;
  };
  std::vector<Kernel> kernels_;          // grouped by cell
  std::vector<std::size_t> cell_start_;  // kernels of cell c: [cell_start_[c], cell_start_[c+1])
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{0, 0, 0};
};

}  // namespace molmesh
