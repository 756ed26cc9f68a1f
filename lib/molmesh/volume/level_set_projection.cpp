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

namespace {

// Catmull-Rom weights of the samples at -1, 0, 1, 2 for a point at t in [0, 1], and their
// derivatives in t. The cubic reproduces quadratics, so a smooth field's level set is placed
// to O(h^3), where the trilinear one sits O(h^2 / radius) inside every convex part (0.013 Å
// on a 3 Å sphere at h = 0.5).
void catmull_rom(double t, double w[4], double dw[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
  w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
  w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
  dw[0] = 0.5 * (-3.0 * t2 + 4.0 * t - 1.0);
  dw[1] = 0.5 * (9.0 * t2 - 10.0 * t);
  dw[2] = 0.5 * (-9.0 * t2 + 8.0 * t + 1.0);
  dw[3] = 0.5 * (3.0 * t2 - 2.0 * t);
}

}  // namespace

double tricubic_value(const Grid& grid, const Vec3& p, Vec3* gradient) {
  // Grids thinner than 4 samples along an axis have no cubic: the trilinear value.
  if (std::min({grid.dims[0], grid.dims[1], grid.dims[2]}) < 4)
    return trilinear_value(grid, p, gradient);
  int index[3][4];
  double w[3][4], dw[3][4];
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - grid.origin[a]) / grid.spacing[a];
    const int c = std::clamp(static_cast<int>(std::floor(u)), 0, grid.dims[a] - 2);
    catmull_rom(std::clamp(u - c, 0.0, 1.0), w[a], dw[a]);
    // At the grid's faces the outer samples repeat the last one (the field's value there is
    // far from any surface the pipeline meshes: grids are padded).
    for (int s = 0; s < 4; ++s) index[a][s] = std::clamp(c - 1 + s, 0, grid.dims[a] - 1);
  }
  double value = 0.0;
  Vec3 g = Vec3::Zero();
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      double row = 0.0, row_dx = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double v = grid.at(index[0][i], index[1][j], index[2][k]);
        row += w[0][i] * v;
        row_dx += dw[0][i] * v;
      }
      value += w[1][j] * w[2][k] * row;
      g[0] += w[1][j] * w[2][k] * row_dx;
      g[1] += dw[1][j] * w[2][k] * row;
      g[2] += w[1][j] * dw[2][k] * row;
    }
  if (gradient) *gradient = g.cwiseQuotient(grid.spacing);
  return value;
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
  return newton_to_level([&grid](const Vec3& x, Vec3* g) { return tricubic_value(grid, x, g); },
                         level, p, cell, 1e-9 * cell);
}

std::function<Vec3(const Vec3&)> level_set_projection(std::shared_ptr<const Grid> grid,
                                                      double level) {
  return
      [grid = std::move(grid), level](const Vec3& p) { return project_to_level(*grid, level, p); };
}

}  // namespace molmesh
