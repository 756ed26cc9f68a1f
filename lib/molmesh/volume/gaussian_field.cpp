#include "molmesh/volume/gaussian_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace molmesh {

GaussianField::GaussianField(const Atoms& atoms, const BlurOptions& options) {
  check_blur_options(options);
  const double cutoff_value = options.truncation * options.isovalue;
  const std::vector<BlurredAtom> blurred = blurred_atoms(atoms, options.blobbyness);
  std::vector<Kernel> kernels;
  kernels.reserve(blurred.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
  double largest = 0.0;
  for (const BlurredAtom& atom : blurred) {
    const double rc = kernel_radius(atom.radius, atom.blobbyness, cutoff_value);
    if (!(rc > 0.0)) continue;
    kernels.push_back({atom.center, atom.blobbyness / (atom.radius * atom.radius),
                       std::exp(-atom.blobbyness), rc * rc});
    lo = lo.cwiseMin(atom.center);
    hi = hi.cwiseMax(atom.center);
    largest = std::max(largest, rc);
  }
  if (kernels.empty()) {
    cell_start_ = {0, 0};
    dims_ = {1, 1, 1};
    return;
  }
  // Cells of the largest cutoff; larger when the atoms are spread so far apart that the
  // cells would outnumber the atoms many times over.
  cell_ = largest;
  const auto cells_for = [&](double size) {
    double count = 1.0;
    for (int a = 0; a < 3; ++a) count *= std::floor((hi[a] - lo[a]) / size) + 1.0;
    return count;
  };
  while (cells_for(cell_) > 8.0 * static_cast<double>(kernels.size()) + 64.0) cell_ *= 2.0;
  origin_ = lo;
  for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>(std::floor((hi[a] - lo[a]) / cell_)) + 1;

  const auto cell_of = [&](const Vec3& p) {
    std::size_t c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = static_cast<std::size_t>(
          std::clamp(static_cast<int>(std::floor((p[a] - origin_[a]) / cell_)), 0, dims_[a] - 1));
    return c[0] +
           static_cast<std::size_t>(dims_[0]) * (c[1] + static_cast<std::size_t>(dims_[1]) * c[2]);
  };
  const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  cell_start_.assign(cells + 1, 0);
  for (const Kernel& k : kernels) ++cell_start_[cell_of(k.center) + 1];
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  kernels_.resize(kernels.size());
  std::vector<std::size_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (const Kernel& k : kernels) kernels_[fill[cell_of(k.center)]++] = k;
}

double GaussianField::value(const Vec3& p, Vec3* gradient) const {
  double f = 0.0;
  Vec3 g = Vec3::Zero();
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const double u = std::floor((p[a] - origin_[a]) / cell_);
    // Far outside the atoms' box no cell is within reach (and the casts stay in range).
    if (!(u >= -1.0 && u <= dims_[a])) {
      if (gradient) *gradient = g;
      return 0.0;
    }
    lo[a] = std::max(0, static_cast<int>(u) - 1);
    hi[a] = std::min(dims_[a] - 1, static_cast<int>(u) + 1);
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t c =
            static_cast<std::size_t>(i) +
            static_cast<std::size_t>(dims_[0]) *
                (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
        for (std::size_t n = cell_start_[c]; n < cell_start_[c + 1]; ++n) {
          const Kernel& kern = kernels_[n];
          const Vec3 d = p - kern.center;
          const double d2 = d.squaredNorm();
          if (d2 > kern.cutoff2) continue;
          const double term = kern.scale * std::exp(kern.a * d2);
          f += term;
          if (gradient) g += (2.0 * kern.a * term) * d;
        }
      }
  if (gradient) *gradient = g;
  return f;
}

}  // namespace molmesh
