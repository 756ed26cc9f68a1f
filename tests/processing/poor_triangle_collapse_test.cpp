#include "molmesh/processing/poor_triangle_collapse.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "molmesh/surface/surface_stats.hpp"
#include "processing/synthetic_meshes.hpp"

namespace molmesh {
namespace {

int vertex_at(const SurfaceMesh& mesh, const Vec3& p) {
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if ((mesh.points[i] - p).norm() < 1e-9) return static_cast<int>(i);
  return -1;
}

// A 3 Å box of 0.5 Å right triangles: every angle 45° or 90°, inside the floors, and twelve
// 90° creases that no flip may cross.
SurfaceMesh box() { return test::gridded_box(6, 3.0); }

TEST(PoorTriangleCollapse, LeavesAMeshInsideTheFloorsUnchanged) {
  const SurfaceMesh input = box();
  HalfedgeMesh mesh(input);
  EXPECT_FALSE(has_poor_triangle(input));
  EXPECT_EQ(collapse_poor_triangles(mesh), 0u);
  const SurfaceMesh output = mesh.to_surface_mesh().mesh;
  EXPECT_EQ(output.points, input.points);
  EXPECT_EQ(output.triangles, input.triangles);
}

// The crease vertex next to a corner slides along the crease to 0.05 Å from the corner: its
// triangles become slivers of a few degrees that sit on two faces of a 90° crease, where a
// flip would cut the box. The collapse removes them and the box stays the box: the corner
// survives and the volume is exactly 27 Å^3 (a collapse the other way, the corner into the
// crease vertex, would have cut the corner off).
TEST(PoorTriangleCollapse, CollapsesSliversOnACreaseAndKeepsTheCornerAndVolume) {
  SurfaceMesh input = box();
  const int corner = vertex_at(input, Vec3(0, 0, 0));
  const int near = vertex_at(input, Vec3(0.5, 0, 0));
  ASSERT_GE(corner, 0);
  ASSERT_GE(near, 0);
  input.points[near] = Vec3(0.05, 0, 0);
  const SurfaceStats before = compute_surface_stats(input);
  ASSERT_LT(before.min_angle_deg, 10.0);
  ASSERT_TRUE(has_poor_triangle(input));

  HalfedgeMesh mesh(input);
  EXPECT_GE(collapse_poor_triangles(mesh), 1u);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_TRUE(mesh.vertex_alive(corner));
  EXPECT_FALSE(mesh.vertex_alive(near));
  const SurfaceStats after = compute_surface_stats(mesh.to_surface_mesh().mesh);
  EXPECT_TRUE(after.closed);
  EXPECT_TRUE(after.manifold);
  EXPECT_EQ(after.euler_characteristic, 2);
  EXPECT_NEAR(after.volume, 27.0, 1e-12);
  EXPECT_GT(after.min_angle_deg, before.min_angle_deg + 10.0);
}

// A poor triangle whose every collapse would move the surface (a vertex pulled 0.2 Å out of
// a flat face, next to a neighbour) is left alone, and so is one inside a keep sphere.
TEST(PoorTriangleCollapse, RefusesCollapsesThatMoveTheSurfaceOrTouchAKeepSphere) {
  SurfaceMesh input = box();
  const int v = vertex_at(input, Vec3(1.5, 1.5, 0));
  ASSERT_GE(v, 0);
  input.points[v] = Vec3(1.1, 1.5, -0.2);
  ASSERT_TRUE(has_poor_triangle(input));
  {
    HalfedgeMesh mesh(input);
    collapse_poor_triangles(mesh);
    EXPECT_TRUE(mesh.vertex_alive(v));
    EXPECT_NEAR(compute_surface_stats(mesh.to_surface_mesh().mesh).volume,
                compute_surface_stats(input).volume, 1e-12);
  }
  SurfaceMesh crease = box();
  const int near = vertex_at(crease, Vec3(0.5, 0, 0));
  crease.points[near] = Vec3(0.05, 0, 0);
  ASSERT_TRUE(has_poor_triangle(crease));
  const Sphere keep{Vec3(0.05, 0, 0), 0.01};
  PoorTriangleCollapseOptions options;
  options.keep_spheres = std::span<const Sphere>(&keep, 1);
  HalfedgeMesh mesh(crease);
  collapse_poor_triangles(mesh, options);
  EXPECT_TRUE(mesh.vertex_alive(near));
}

}  // namespace
}  // namespace molmesh
