#include "molmesh/surface/components.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/surface/point_in_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh {
namespace {

// A closed shell of atoms (Fibonacci sphere, radius 6 Å) around an empty centre.
Atoms atom_shell() {
  Atoms atoms;
  const int n = 220;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
    const double s = std::sqrt(1.0 - z * z);
    Atom a;
    a.center = 6.0 * Vec3(s * std::cos(phi), s * std::sin(phi), z);
    a.radius = 1.6;
    atoms.push_back(a);
  }
  return atoms;
}

TEST(Components, ShellHasOuterSurfaceAndCavity) {
  const SurfaceMesh mesh = marching_cubes(blur_atoms(atom_shell(), {}), 1.0);
  const SurfaceStats stats = compute_surface_stats(mesh);
  EXPECT_TRUE(stats.closed);
  EXPECT_TRUE(stats.manifold);
  EXPECT_EQ(stats.components, 2);
  EXPECT_EQ(stats.euler_characteristic, 4);

  const auto components = surface_components(mesh);
  ASSERT_EQ(components.size(), 2u);
  int cavities = 0;
  double total = 0.0;
  for (const auto& c : components) {
    cavities += c.is_cavity();
    total += c.signed_volume;
    EXPECT_GT(c.area, 0.0);
  }
  EXPECT_EQ(cavities, 1);
  EXPECT_NEAR(total, stats.volume, 1e-6 * std::abs(stats.volume));

  const PointInMesh inside(mesh);
  EXPECT_FALSE(inside.inside(Vec3::Zero()));  // the empty centre is in the cavity
  EXPECT_EQ(inside.winding_number(Vec3(0.1, 0.2, 0.05)), 0);
  EXPECT_TRUE(inside.inside(Vec3(6.0, 0.0, 0.0)));
  EXPECT_FALSE(inside.inside(Vec3(9.5, 0.0, 0.0)));

  std::size_t removed = 0;
  const SurfaceMesh kept = drop_small_cavities(mesh, 1.0, &removed);
  EXPECT_EQ(removed, 0u);
  EXPECT_EQ(kept.triangles.size(), mesh.triangles.size());

  const double cavity = -(components[0].is_cavity() ? components[0] : components[1]).signed_volume;
  const SurfaceMesh dropped = drop_small_cavities(mesh, cavity * 1.01, &removed);
  EXPECT_EQ(removed, 1u);
  const SurfaceStats after = compute_surface_stats(dropped);
  EXPECT_EQ(after.components, 1);
  EXPECT_TRUE(after.closed);
  EXPECT_EQ(after.euler_characteristic, 2);
  EXPECT_NEAR(after.volume, stats.volume + cavity, 1e-6 * after.volume);
  EXPECT_EQ(after.vertices, dropped.points.size());  // unreferenced points removed
}

TEST(PointInMesh, SphereInsideOutside) {
  Atom a;
  a.radius = 2.0;
  const SurfaceMesh mesh = marching_cubes(blur_atoms({a}, {}), 1.0);
  const PointInMesh tester(mesh);
  EXPECT_EQ(tester.winding_number(Vec3::Zero()), 1);
  EXPECT_EQ(tester.winding_number(Vec3(1.8, 0.1, -0.2)), 1);
  EXPECT_EQ(tester.winding_number(Vec3(2.3, 0.0, 0.0)), 0);
  EXPECT_EQ(tester.winding_number(Vec3(0.0, 5.0, 0.0)), 0);
  EXPECT_EQ(tester.winding_number(Vec3(-3.0, 0.0, 0.0)), 0);
  // A ray through mesh vertices is nudged, not miscounted.
  const Vec3 v = mesh.points[mesh.triangles[0][0]];
  EXPECT_EQ(tester.winding_number(Vec3(v.x() - 0.5 * v.x(), v.y(), v.z())), 1);
}

}  // namespace
}  // namespace molmesh
