#include "molmesh/volume/level_set_projection.hpp"

#include <algorithm>
#include <cmath>

namespace molmesh {

double trilinear_value(const Grid& grid, const Vec3& p, Vec3* gradient) {
  int c[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - grid.origin[a]) / grid.spacing[a];
    c[a] = std::clamp(static_cast<int>(std::floor(u)), 0, std::max(0, grid.dims[a] - 2));
    t[a] = std::clamp(u - c[a], 0.0, 1.0);
  }
  const int i1 = std::min(c[0] + 1, grid.dims[0] - 1);
  const int j1 = std::min(c[1] + 1, grid.dims[1] - 1);
  const int k1 = std::min(c[2] + 1, grid.dims[2] - 1);
  const double v000 = grid.at(c[0], c[1], c[2]), v100 = grid.at(i1, c[1], c[2]);
  const double v010 = grid.at(c[0], j1, c[2]), v110 = grid.at(i1, j1, c[2]);
  const double v001 = grid.at(c[0], c[1], k1), v101 = grid.at(i1, c[1], k1);
  const double v011 = grid.at(c[0], j1, k1), v111 = grid.at(i1, j1, k1);
  const double x = t[0], y = t[1], z = t[2];
  const double v00 = v000 + x * (v100 - v000), v10 = v010 + x * (v110 - v010);
  const double v01 = v001 + x * (v101 - v001), v11 = v011 + x * (v111 - v011);
  const double v0 = v00 + y * (v10 - v00), v1 = v01 + y * (v11 - v01);
  if (gradient) {
    const double gx0 = (1 - y) * (v100 - v000) + y * (v110 - v010);
    const double gx1 = (1 - y) * (v101 - v001) + y * (v111 - v011);
    (*gradient)[0] = ((1 - z) * gx0 + z * gx1) / grid.spacing[0];
    (*gradient)[1] = ((1 - z) * (v10 - v00) + z * (v11 - v01)) / grid.spacing[1];
    (*gradient)[2] = (v1 - v0) / grid.spacing[2];
  }
  return v0 + z * (v1 - v0);
}

Vec3 newton_to_level(const ScalarField& field, double level, const Vec3& p, double max_step,
                     double tolerance, int max_iterations) {
  Vec3 x = p;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    Vec3 g;
    const double f = field(x, &g) - level;
    const double g2 = g.squaredNorm();
    if (f == 0.0 || !(g2 > 1e-20)) break;
    Vec3 step = -(f / g2) * g;
    const double length = step.norm();
    if (length > max_step) step *= max_step / length;
    x += step;
    if (length < tolerance) break;
  }
  return x;
}

Vec3 project_to_level(const Grid& grid, double level, const Vec3& p) {
  const double cell = grid.spacing.minCoeff();
  return newton_to_level([&grid](const Vec3& x, Vec3* g) { return trilinear_value(grid, x, g); },
                         level, p, cell, 1e-9 * cell);
}

std::function<Vec3(const Vec3&)> level_set_projection(std::shared_ptr<const Grid> grid,
                                                      double level) {
  return
      [grid = std::move(grid), level](const Vec3& p) { return project_to_level(*grid, level, p); };
}

}  // namespace molmesh
