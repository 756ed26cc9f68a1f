#include "molmesh/surface/marching_cubes.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "molmesh/surface/components.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "support/atoms.hpp"

namespace molmesh {
namespace {

using testing::make_atom;

Grid random_grid(int n, unsigned seed) {
  Grid g;
  g.dims = {n, n + 1, n + 2};
  g.spacing = Vec3(0.5, 0.7, 0.3);
  g.origin = Vec3(-1.0, 2.0, 3.0);
  g.values.resize(g.size());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dist(0.0, 2.0);
  for (double& v : g.values) v = dist(rng);
  return g;
}

// Every ambiguous face and cube configuration appears many times in white noise; the
// surface must still be a closed, consistently oriented manifold.
TEST(MarchingCubes, WhiteNoiseGivesClosedOrientedManifold) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Grid g = random_grid(14, seed);
    const SurfaceMesh mesh = marching_cubes(g, 1.0);
    const SurfaceStats s = compute_surface_stats(mesh);
    EXPECT_GT(s.triangles, 1000u);
    EXPECT_TRUE(s.manifold) << "seed " << seed;
    EXPECT_TRUE(s.closed) << "seed " << seed;
    EXPECT_GT(s.min_angle_deg, 0.0);
    // The inside touches the grid boundary, and is closed one cell beyond it: every
    // component encloses something, and the total is positive.
    EXPECT_GT(s.volume, 0.0);
  }
}

TEST(MarchingCubes, ValuesExactlyAtIsovalueGiveNoDegenerateTriangles) {
  Grid g;
  g.dims = {12, 12, 12};
  g.spacing = Vec3::Constant(1.0);
  g.values.resize(g.size());
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, 2);
  for (double& v : g.values) v = 0.5 * pick(rng);  // 0, 0.5 or 1.0 with isovalue 0.5
  const SurfaceMesh mesh = marching_cubes(g, 0.5);
  const SurfaceStats s = compute_surface_stats(mesh);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_GT(s.min_angle_deg, 0.0);
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.points[t[0]];
    const Vec3& b = mesh.points[t[1]];
    const Vec3& c = mesh.points[t[2]];
    EXPECT_GT((b - a).cross(c - a).norm(), 1e-9);
  }
}

// F = 1 exactly at distance r. Linear interpolation along an edge of length h misplaces
// the crossing by at most h^2 |F''| / (8 |F'|); projected on the radius this is at most
// h^2 (1 + 2|B|) / (8 r) (docs/surface.md), plus the node gap of 1e-3 h.
TEST(MarchingCubes, SingleAtomSphere) {
  const double r = 2.0, b = -0.5;
  const Vec3 c(0.3, -0.2, 0.1);
  for (double h : {0.1, 0.25, 0.5}) {
    BlurOptions options;
    options.spacing = h;
    const Grid g = blur_atoms({make_atom(c.x(), c.y(), c.z(), r)}, options);
    const SurfaceMesh mesh = marching_cubes(g, 1.0);
    const SurfaceStats s = compute_surface_stats(mesh);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.manifold);
    EXPECT_EQ(s.components, 1);
    EXPECT_EQ(s.euler_characteristic, 2);
    EXPECT_GT(s.volume, 0.0);  // outward normals
    double worst = 0.0;
    for (const Vec3& p : mesh.points) worst = std::max(worst, std::abs((p - c).norm() - r));
    EXPECT_LE(worst, h * h * (1 + 2 * std::abs(b)) / (8 * r) + 1e-3 * h) << "h = " << h;
    if (h == 0.1) {
      EXPECT_NEAR(s.area, 4 * M_PI * r * r, 0.01 * 4 * M_PI * r * r);
      EXPECT_NEAR(s.volume, 4.0 / 3.0 * M_PI * r * r * r, 0.01 * 4.0 / 3.0 * M_PI * r * r * r);
    }
  }
}

TEST(MarchingCubes, OverlappingAtomsMakeOneGenusZeroSurface) {
  const std::vector<Atoms> cases = {
      {make_atom(0, 0, 0, 1.6), make_atom(2.0, 0.3, 0, 1.4)},
      {make_atom(0, 0, 0, 1.6), make_atom(2.0, 0.3, 0, 1.4), make_atom(1.0, 1.9, 0.5, 1.8)}};
  for (const Atoms& atoms : cases) {
    const SurfaceMesh mesh = marching_cubes(blur_atoms(atoms, {}), 1.0);
    const SurfaceStats s = compute_surface_stats(mesh);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.manifold);
    EXPECT_EQ(s.components, 1);
    EXPECT_EQ(s.euler_characteristic, 2);  // genus 0
    EXPECT_GT(s.volume, 0.0);
  }
}

TEST(MarchingCubes, InsideOnTheGridBoundaryIsClosedAndWarned) {
  Grid g;
  g.dims = {6, 7, 8};
  g.values.assign(g.size(), 2.0);  // everything inside
  int warnings = 0;
  Reporter reporter;
  reporter.on_warning = [&](std::string_view) { ++warnings; };
  const SurfaceMesh mesh = marching_cubes(g, 1.0, reporter);
  const SurfaceStats s = compute_surface_stats(mesh);
  EXPECT_EQ(warnings, 1);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_GT(s.volume, 5.0 * 6.0 * 7.0);  // the box, closed beyond the last samples
}

TEST(MarchingCubes, SameMeshWithOneAndTwoThreads) {
  const Grid g = random_grid(20, 9);
  SurfaceMesh one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = marching_cubes(g, 1.0);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = marching_cubes(g, 1.0);
  }
  EXPECT_TRUE(one.points == two.points);
  EXPECT_TRUE(one.triangles == two.triangles);
}

}  // namespace
}  // namespace molmesh
