#pragma once
// A scalar field sampled on a regular, axis-aligned grid: value(i,j,k) sits at
// origin + (i*spacing.x, j*spacing.y, k*spacing.z). Any size (no 2^n+1 restriction).
#include <array>
#include <cstddef>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct Grid {
  Vec3 origin = Vec3::Zero();
  Vec3 spacing = Vec3::Ones();
  std::array<int, 3> dims{0, 0, 0};  // samples along x, y, z
  std::vector<double> values;        // x fastest: index = i + nx*(j + ny*k)

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
  }
  double& at(int i, int j, int k) { return values[index(i, j, k)]; }
  double at(int i, int j, int k) const { return values[index(i, j, k)]; }
  Vec3 position(int i, int j, int k) const {
    return origin + Vec3(i * spacing.x(), j * spacing.y(), k * spacing.z());
  }
  std::size_t size() const {
    return static_cast<std::size_t>(dims[0]) * dims[1] * static_cast<std::size_t>(dims[2]);
  }
};

}  // namespace molmesh
