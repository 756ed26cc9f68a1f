#include "molmesh/tetmesh/outer_sphere.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>

#include "molmesh/core/error.hpp"
#include "molmesh/tetmesh/molecule_size.hpp"

namespace molmesh {
namespace {

TEST(Icosphere, CountsClosedOutwardAndOnTheSphere) {
  const Vec3 c(1, -2, 3);
  for (int level = 0; level <= 4; ++level) {
    const SurfaceMesh s = icosphere(c, 7.0, level);
    const std::size_t f = 20u << (2 * level);
    EXPECT_EQ(s.triangles.size(), f);
    EXPECT_EQ(s.points.size(), f / 2 + 2);
    for (const auto& p : s.points) EXPECT_NEAR((p - c).norm(), 7.0, 1e-12);
    std::map<std::pair<int, int>, int> directed;
    double min_angle = 180.0;
    for (const auto& t : s.triangles) {
      for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
      const Vec3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      EXPECT_GT(n.dot(s.points[t[0]] - c), 0.0);
      for (int k = 0; k < 3; ++k) {
        const Vec3 u = s.points[t[(k + 1) % 3]] - s.points[t[k]];
        const Vec3 v = s.points[t[(k + 2) % 3]] - s.points[t[k]];
        min_angle = std::min(
            min_angle, std::acos(u.normalized().dot(v.normalized())) * 180 / std::numbers::pi);
      }
    }
    // Each directed edge once and its reverse once: closed and consistently oriented.
    for (const auto& [e, n] : directed) {
      EXPECT_EQ(n, 1);
      EXPECT_EQ(directed.count({e.second, e.first}), 1u);
    }
    EXPECT_GT(min_angle, 50.0);  // near-equilateral, needs no Steiner points in TetGen
  }
  EXPECT_THROW(icosphere(c, 0.0, 1), Error);
  EXPECT_THROW(icosphere(c, 1.0, 8), Error);
}

TEST(MoleculeExtent, MeanAndMaxDistance) {
  Atoms atoms(3);
  atoms[0].center = Vec3(0, 0, 0);
  atoms[1].center = Vec3(2, 0, 0);
  atoms[2].center = Vec3(4, 0, 0);
  const MoleculeExtent e = molecule_extent(atoms);
  EXPECT_TRUE(e.centroid.isApprox(Vec3(2, 0, 0)));
  EXPECT_DOUBLE_EQ(e.size, 2.0);
  EXPECT_DOUBLE_EQ(molecule_extent(std::vector<Vec3>{Vec3(1, 1, 1)}).size, 0.0);
  EXPECT_THROW(molecule_extent(Atoms{}), Error);
}

}  // namespace
}  // namespace molmesh
