#include "molmesh/surface/surface_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace molmesh {
namespace {

// Unit cube, 12 triangles, outward.
SurfaceMesh unit_cube(const Vec3& shift = Vec3::Zero()) {
  SurfaceMesh m;
  for (int c = 0; c < 8; ++c) m.points.push_back(shift + Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

TEST(SurfaceStats, UnitCube) {
  const SurfaceStats s = compute_surface_stats(unit_cube(Vec3(10, -3, 7)));
  EXPECT_EQ(s.vertices, 8u);
  EXPECT_EQ(s.triangles, 12u);
  EXPECT_NEAR(s.area, 6.0, 1e-12);
  EXPECT_NEAR(s.volume, 1.0, 1e-12);
  EXPECT_NEAR(s.min_angle_deg, 45.0, 1e-9);
  EXPECT_NEAR(s.max_angle_deg, 90.0, 1e-9);
  // 24 angles of 45 deg (bin 4) and 12 of 90 deg (bin 9).
  EXPECT_NEAR(s.angle_histogram_percent[4], 200.0 / 3.0, 1e-9);
  EXPECT_NEAR(s.angle_histogram_percent[9], 100.0 / 3.0, 1e-9);
  EXPECT_NEAR(s.fraction_angles_40_80, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
}

TEST(SurfaceStats, InwardCubeHasNegativeVolume) {
  SurfaceMesh m = unit_cube();
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  const SurfaceStats s = compute_surface_stats(m);
  EXPECT_NEAR(s.volume, -1.0, 1e-12);
  EXPECT_TRUE(s.closed);
}

TEST(SurfaceStats, DetectsHolesFlipsAndPinchedVertices) {
  SurfaceMesh open = unit_cube();
  open.triangles.pop_back();
  SurfaceStats s = compute_surface_stats(open);
  EXPECT_FALSE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.euler_characteristic, 1);

  SurfaceMesh flipped = unit_cube();
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  s = compute_surface_stats(flipped);
  EXPECT_FALSE(s.manifold);
  EXPECT_FALSE(s.closed);

  // Two cubes touching at one corner: every edge is fine, the shared vertex is not.
  SurfaceMesh pinched = unit_cube();
  const SurfaceMesh other = unit_cube(Vec3(1, 1, 1));
  for (int c = 0; c < 8; ++c)
    if (c != 0) pinched.points.push_back(other.points[c]);
  for (Triangle t : other.triangles) {
    for (int& v : t) v = v == 0 ? 7 : v + 7;
    pinched.triangles.push_back(t);
  }
  s = compute_surface_stats(pinched);
  EXPECT_FALSE(s.manifold);
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.components, 1);
}

}  // namespace
}  // namespace molmesh
