// Closest point of a triangle: every Voronoi region (vertex, edge, face) of a unit triangle.
#include "molmesh/geometry/closest_point.hpp"

#include <gtest/gtest.h>

namespace molmesh {
namespace {

TEST(ClosestPoint, BarycentricsOfRegions) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(
      closest_point_barycentric(Vec3(-1, -1, 3), a, b, c).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(
      closest_point_barycentric(Vec3(0.5, -2, 0), a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(closest_point_barycentric(Vec3(0.25, 0.25, -4), a, b, c)
                  .isApprox(Eigen::Vector3d(0.5, 0.25, 0.25)));
  EXPECT_TRUE(
      closest_point_barycentric(Vec3(1, 1, 0), a, b, c).isApprox(Eigen::Vector3d(0, 0.5, 0.5)));
}

TEST(ClosestPoint, RegionsOfATriangle) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.2, 0.2, 3), a, b, c).isApprox(Vec3(0.2, 0.2, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(-1, -1, 0), a, b, c).isApprox(a));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(2, -1, 1), a, b, c).isApprox(b));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.5, -2, 0), a, b, c).isApprox(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
}

}  // namespace
}  // namespace molmesh
