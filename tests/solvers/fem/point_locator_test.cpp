// The point locator: containing cells with barycentric weights that interpolate linear
// functions exactly, on uniform and strongly graded meshes.
#include "solvers/fem/point_locator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

TEST(PointLocator, FindsContainingCellsAndInterpolatesLinearsExactly) {
  const auto shell = test::make_shell_mesh({.inner_radius = 2.0,
                                            .outer_radius = 6.0,
                                            .subdivisions = 2,
                                            .radial_layers = 3,
                                            .ball_layers = 2});
  const PointLocator locator(shell.mesh);
  const Vec3 probes[] = {Vec3(0, 0, 0), Vec3(0.3, -1.1, 0.7), Vec3(3.0, 2.0, -1.0),
                         Vec3(-4.5, 0.1, 1.2)};
  for (const Vec3& p : probes) {
    const auto at = locator.locate(p);
    ASSERT_TRUE(at.has_value());
    Vec3 back = Vec3::Zero();
    for (std::size_t a = 0; a < 4; ++a) {
      EXPECT_GE(at->barycentric[a], -1e-9);
      back += at->barycentric[a] *
              shell.mesh.points[static_cast<std::size_t>(
                  shell.mesh.tetrahedra[static_cast<std::size_t>(at->tetrahedron)][a])];
    }
    EXPECT_LT((back - p).norm(), 1e-9);
  }
  EXPECT_FALSE(locator.locate(Vec3(7.0, 0, 0)).has_value());
}

// Charges sit on mesh vertices (atom centres), shared by many cells: every vertex of a
// strongly graded mesh (geometric layers, cells 40x larger outside than inside) is found,
// with weight 1 on itself.
TEST(PointLocator, FindsEveryVertexOfAGradedMesh) {
  const auto shell = test::make_shell_mesh({.inner_radius = 1.0,
                                            .outer_radius = 40.0,
                                            .subdivisions = 2,
                                            .radial_layers = 12,
                                            .ball_layers = 2});
  const PointLocator locator(shell.mesh);
  for (std::size_t v = 0; v < shell.mesh.points.size(); ++v) {
    const auto at = locator.locate(shell.mesh.points[v]);
    ASSERT_TRUE(at.has_value()) << "vertex " << v;
    const Tetrahedron& tet = shell.mesh.tetrahedra[static_cast<std::size_t>(at->tetrahedron)];
    double own = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
      if (static_cast<std::size_t>(tet[a]) == v) own = at->barycentric[a];
    }
    EXPECT_NEAR(own, 1.0, 1e-9) << "vertex " << v;
  }
}

}  // namespace
}  // namespace molmesh::solvers
