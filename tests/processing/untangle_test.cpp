// untangle: crossings that moving vertices back to their input positions cannot undo (the
// connectivity itself folds) are unfolded by moving the crossing triangles' vertices to the
// mean of their neighbours; vertices away from the fold stay put.
#include "molmesh/processing/untangle.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "molmesh/processing/self_intersection.hpp"
#include "processing/improve_meshes.hpp"

namespace molmesh {
namespace {

// An icosphere with one triangle (a, b, c) split by a valence-3 vertex d that lies over the
// neighbouring triangle across b-c (the fold coarsening leaves on nearly flat vdW patches of
// fas2, issue 12).
SurfaceMesh sphere_with_folded_fan() {
  SurfaceMesh mesh = icosphere(Vec3::Zero(), 5.0, 2);
  const Triangle t = mesh.triangles.front();
  const int a = t[0], b = t[1], c = t[2];
  // The triangle on the other side of edge (b, c): it uses the edge as (c, b).
  int e = -1;
  for (const Triangle& u : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (u[k] == c && u[(k + 1) % 3] == b) e = u[(k + 2) % 3];
  EXPECT_GE(e, 0);
  const Vec3 over = (mesh.points[b] + mesh.points[c] + 2.0 * mesh.points[e]) / 4.0;
  const int d = static_cast<int>(mesh.points.size());
  mesh.points.push_back(over * 1.002);  // just above triangle (c, b, e)
  mesh.triangles.front() = {a, b, d};
  mesh.triangles.push_back({b, c, d});
  mesh.triangles.push_back({c, a, d});
  return mesh;
}

TEST(Untangle, UnfoldsAFanThatIsAlreadyAtItsInputPositions) {
  SurfaceMesh mesh = sphere_with_folded_fan();
  const SurfaceMesh input = mesh;
  std::vector<int> provenance(mesh.points.size());
  std::iota(provenance.begin(), provenance.end(), 0);
  const auto crossings = self_intersections(mesh);
  ASSERT_GT(crossings.size(), 0u);

  EXPECT_EQ(untangle(mesh, input, provenance), 0u);
  EXPECT_EQ(count_self_intersections(mesh), 0u);
  // Only vertices of crossing triangles (of some round) moved: the rest is untouched.
  const Vec3 fold = input.points.back();
  std::size_t moved = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (mesh.points[v] == input.points[v]) continue;
    ++moved;
    EXPECT_LT((input.points[v] - fold).norm(), 5.0) << v;
  }
  EXPECT_GT(moved, 0u);
  EXPECT_LT(moved, 12u);
}

TEST(Untangle, LeavesACleanSurfaceAlone) {
  SurfaceMesh mesh = icosphere(Vec3::Zero(), 5.0, 2);
  const SurfaceMesh input = mesh;
  std::vector<int> provenance(mesh.points.size());
  std::iota(provenance.begin(), provenance.end(), 0);
  EXPECT_EQ(untangle(mesh, input, provenance), 0u);
  EXPECT_EQ(mesh.points, input.points);
}

}  // namespace
}  // namespace molmesh
