#include "solvers/physics/grid_interpolation.hpp"

#include <algorithm>
#include <cmath>

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {

InterpolatedField interpolate_trilinear(const Grid& grid, std::span<const Vec3> points) {
  if (grid.dims[0] < 2 || grid.dims[1] < 2 || grid.dims[2] < 2 ||
      grid.values.size() != grid.size()) {
    throw Error("potential grid must have at least 2 samples along each axis");
  }
  InterpolatedField out;
  out.values.resize(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::array<int, 3> i0{};
    std::array<double, 3> f{};
    bool outside = false;
    for (int d = 0; d < 3; ++d) {
      const auto du = static_cast<std::size_t>(d);
      double s = (points[p][d] - grid.origin[d]) / grid.spacing[d];
      const double top = grid.dims[du] - 1;
      if (s < 0.0 || s > top) {
        outside = true;
        s = std::clamp(s, 0.0, top);
      }
      i0[du] = std::min(static_cast<int>(std::floor(s)), grid.dims[du] - 2);
      f[du] = s - i0[du];
    }
    if (outside) ++out.outside;
    double value = 0.0;
    for (int c = 0; c < 8; ++c) {
      const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      const double w =
          (dx ? f[0] : 1.0 - f[0]) * (dy ? f[1] : 1.0 - f[1]) * (dz ? f[2] : 1.0 - f[2]);
      value += w * grid.at(i0[0] + dx, i0[1] + dy, i0[2] + dz);
    }
    out.values[p] = value;
  }
  return out;
}

}  // namespace molmesh::solvers
