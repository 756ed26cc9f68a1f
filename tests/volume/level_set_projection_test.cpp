// The interpolants behind the level-set projection: the tricubic reproduces quadratics and
// places a sphere's distance-field surface to a small fraction of the trilinear's error.
#include "molmesh/volume/level_set_projection.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace molmesh {
namespace {

Grid sampled(const std::array<int, 3>& dims, const Vec3& origin, double h,
             double (*f)(const Vec3&)) {
  Grid grid;
  grid.origin = origin;
  grid.spacing = Vec3::Constant(h);
  grid.dims = dims;
  grid.values.resize(grid.size());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) grid.at(i, j, k) = f(grid.position(i, j, k));
  return grid;
}

double quadratic(const Vec3& p) {
  return 0.3 * p.x() * p.x() - 1.1 * p.y() * p.z() + 0.7 * p.z() * p.z() + 2.0 * p.x() - 1.0;
}

// The lone 3 Å atom's SES: minus the distance to the sphere (positive inside).
double sphere(const Vec3& p) { return 3.0 - p.norm(); }

TEST(TricubicValue, ReproducesAQuadraticAndItsGradient) {
  const Grid grid = sampled({9, 8, 7}, Vec3(-2.0, -1.5, -1.0), 0.5, quadratic);
  for (const Vec3& p : {Vec3(0.1, 0.2, 0.3), Vec3(-0.77, 0.41, 0.9), Vec3(1.3, 0.0, 0.25)}) {
    Vec3 g;
    EXPECT_NEAR(tricubic_value(grid, p, &g), quadratic(p), 1e-12);
    const Vec3 exact(0.6 * p.x() + 2.0, -1.1 * p.z(), -1.1 * p.y() + 1.4 * p.z());
    EXPECT_LT((g - exact).norm(), 1e-11) << p.transpose();
  }
}

TEST(TricubicValue, SphereLevelSetIsPlacedFarCloserThanTrilinear) {
  const double h = 0.5;
  const Grid grid = sampled({21, 21, 21}, Vec3::Constant(-5.0), h, sphere);
  double worst_cubic = 0.0, worst_linear = 0.0;
  const auto trilinear = [&grid](const Vec3& x, Vec3* g) { return trilinear_value(grid, x, g); };
  for (int n = 0; n < 200; ++n) {
    // Directions spread over the sphere (a Fibonacci lattice), started 0.2 Å outside.
    const double z = 1.0 - (n + 0.5) / 100.0, phi = 2.399963229728653 * n;
    const Vec3 d(std::sqrt(1.0 - z * z) * std::cos(phi), std::sqrt(1.0 - z * z) * std::sin(phi), z);
    const Vec3 start = 3.2 * d;
    worst_cubic = std::max(worst_cubic, std::abs(project_to_level(grid, 0.0, start).norm() - 3.0));
    worst_linear = std::max(worst_linear,
                            std::abs(newton_to_level(trilinear, 0.0, start, h, 1e-9).norm() - 3.0));
  }
  EXPECT_GT(worst_linear, 0.01);  // the trilinear sits inside by O(h^2 / radius)
  EXPECT_LT(worst_cubic, 0.004);
  EXPECT_LT(worst_cubic, 0.25 * worst_linear);
}

}  // namespace
}  // namespace molmesh
