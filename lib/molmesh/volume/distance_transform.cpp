#include "molmesh/volume/distance_transform.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <limits>

namespace molmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Scratch for one line: the envelope's parabola positions and boundaries, and the line's
// input copied out (the pass writes in place).
struct LineScratch {
  std::vector<int> v;
  std::vector<double> z;
  std::vector<double> f;
  std::vector<std::int64_t> feature;
  void resize(int n) {
    v.resize(static_cast<std::size_t>(n));
    z.resize(static_cast<std::size_t>(n) + 1);
    f.resize(static_cast<std::size_t>(n));
    feature.resize(static_cast<std::size_t>(n));
  }
};

// D(p) = min_q (s^2 (p - q)^2 + f(q)) along one line of n samples `stride` apart, starting
// at `first`; the feature of p becomes the feature of the minimising q.
void transform_line(double* d, std::int64_t* nearest, std::size_t first, std::size_t stride, int n,
                    double s, LineScratch& scratch) {
  const double s2 = s * s;
  for (int q = 0; q < n; ++q) {
    scratch.f[q] = d[first + q * stride];
    scratch.feature[q] = nearest[first + q * stride];
  }
  int k = -1;  // index of the rightmost parabola in the envelope
  for (int q = 0; q < n; ++q) {
    if (scratch.f[q] == kInf) continue;
    const double fq = scratch.f[q] + s2 * q * q;
    while (k >= 0) {
      const int vk = scratch.v[k];
      const double boundary = (fq - (scratch.f[vk] + s2 * vk * vk)) / (2.0 * s2 * (q - vk));
      if (boundary > scratch.z[k]) {
        ++k;
        scratch.v[k] = q;
        scratch.z[k] = boundary;
        break;
      }
      --k;
    }
    if (k < 0) {
      k = 0;
      scratch.v[0] = q;
      scratch.z[0] = -kInf;
    }
    scratch.z[k + 1] = kInf;
  }
  if (k < 0) return;  // no site on this line: everything stays infinite
  int j = 0;
  for (int p = 0; p < n; ++p) {
    while (scratch.z[j + 1] < p) ++j;
    const int q = scratch.v[j];
    d[first + p * stride] = s2 * (p - q) * (p - q) + scratch.f[q];
    nearest[first + p * stride] = scratch.feature[q];
  }
}

}  // namespace

DistanceTransform euclidean_distance_transform(const std::vector<char>& sites,
                                               const std::array<int, 3>& dims,
                                               const Vec3& spacing) {
  DistanceTransform result;
  const std::size_t size = sites.size();
  result.squared_distance.resize(size);
  result.nearest.resize(size);
  for (std::size_t n = 0; n < size; ++n) {
    result.squared_distance[n] = sites[n] ? 0.0 : kInf;
    result.nearest[n] = sites[n] ? static_cast<std::int64_t>(n) : -1;
  }
  const std::size_t nx = static_cast<std::size_t>(dims[0]);
  const std::size_t ny = static_cast<std::size_t>(dims[1]);
  const std::size_t strides[3] = {1, nx, nx * ny};
  for (int axis = 0; axis < 3; ++axis) {
    // Lines along `axis`, enumerated by the two other coordinates.
    const int a = axis == 0 ? 1 : 0;
    const int b = axis == 2 ? 1 : 2;
    const std::size_t na = static_cast<std::size_t>(dims[a]);
    const std::size_t lines = na * static_cast<std::size_t>(dims[b]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, lines, 256), [&](const auto& r) {
      LineScratch scratch;
      scratch.resize(dims[axis]);
      for (std::size_t line = r.begin(); line != r.end(); ++line) {
        const std::size_t first = (line % na) * strides[a] + (line / na) * strides[b];
        transform_line(result.squared_distance.data(), result.nearest.data(), first, strides[axis],
                       dims[axis], spacing[axis], scratch);
      }
    });
  }
  return result;
}

}  // namespace molmesh
