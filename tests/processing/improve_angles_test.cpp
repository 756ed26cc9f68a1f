#include "molmesh/processing/improve_angles.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "molmesh/processing/vertex_moves.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/improve_meshes.hpp"

namespace molmesh {
namespace {

SurfaceMesh jittered_sphere(double amount, unsigned seed) {
  SurfaceMesh mesh = icosphere(Vec3::Zero(), 10.0, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  // Tangential jitter only, so the surface is still the sphere but the angles are poor.
  for (Vec3& p : mesh.points) {
    const Vec3 n = p.normalized();
    Vec3 d(u(rng), u(rng), u(rng));
    d -= d.dot(n) * n;
    p = 10.0 * (p + d).normalized();
  }
  return mesh;
}

// The rim of an open fan has no closed ring and stays put; only the centre may move.
TEST(ImproveAngles, RegularPlanarFanStaysInPlace) {
  for (int m : {4, 5, 6, 7, 8}) {
    SurfaceMesh mesh = improve_test::planar_fan(m);
    improve_angles(mesh);
    EXPECT_LT(mesh.points[0].norm(), 1e-12) << "valence " << m;
  }
}

TEST(ImproveAngles, OffCentreFanVertexMovesBackTowardsCentre) {
  SurfaceMesh mesh = improve_test::planar_fan(6);
  mesh.points[0] = Vec3(0.45, 0.2, 0.0);
  const double before =
      star_quality_deg(mesh.points[0], std::vector<std::int32_t>{1, 2, 3, 4, 5, 6}, mesh.points);
  ImproveOptions options;
  options.sweeps = 30;
  options.converged_fraction = 0;
  improve_angles(mesh, options);
  EXPECT_LT(mesh.points[0].head<2>().norm(), 0.05);
  EXPECT_NEAR(mesh.points[0].z(), 0.0, 1e-9);  // flat star: no motion off the plane
  const double after =
      star_quality_deg(mesh.points[0], std::vector<std::int32_t>{1, 2, 3, 4, 5, 6}, mesh.points);
  EXPECT_GT(after, before + 10.0);
}

TEST(ImproveAngles, RaisesAnglesOnJitteredSphereAndStaysOnIt) {
  SurfaceMesh mesh = jittered_sphere(0.4, 3);
  const SurfaceStats before = compute_surface_stats(mesh);
  improve_angles(mesh);
  const SurfaceStats after = compute_surface_stats(mesh);
  EXPECT_GT(after.min_angle_deg, before.min_angle_deg + 5.0);
  EXPECT_LT(after.max_angle_deg, before.max_angle_deg - 5.0);
  EXPECT_GT(after.fraction_angles_40_80, before.fraction_angles_40_80);
  double worst = 0;
  for (const Vec3& p : mesh.points) worst = std::max(worst, std::abs(p.norm() - 10.0));
  EXPECT_LT(worst, 0.05);  // edge length ≈ 0.9: vertices slide along, not off, the sphere
  EXPECT_EQ(after.euler_characteristic, 2);
  EXPECT_TRUE(after.manifold);
}

TEST(ImproveAngles, FrozenVerticesDoNotMove) {
  SurfaceMesh mesh = jittered_sphere(0.06, 4);
  ImproveOptions options;
  options.frozen.assign(mesh.points.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size(); v += 3) options.frozen[v] = 1;
  const SurfaceMesh before = mesh;
  improve_angles(mesh, options);
  for (std::size_t v = 0; v < mesh.points.size(); v += 3) {
    EXPECT_EQ(mesh.points[v], before.points[v]);
  }
}

TEST(ImproveAngles, SameBitsWithOneOrTwoThreads) {
  SurfaceMesh one = jittered_sphere(0.06, 5);
  SurfaceMesh two = one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    improve_angles(one);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    improve_angles(two);
  }
  ASSERT_EQ(one.points.size(), two.points.size());
  for (std::size_t v = 0; v < one.points.size(); ++v) EXPECT_EQ(one.points[v], two.points[v]);
}

}  // namespace
}  // namespace molmesh
