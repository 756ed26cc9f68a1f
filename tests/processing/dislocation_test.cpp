#include "molmesh/processing/dislocation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "molmesh/processing/self_intersection.hpp"
#include "molmesh/processing/triangle_bvh.hpp"
#include "processing/improve_meshes.hpp"

namespace molmesh {
namespace {

TEST(TriangleBvh, NearestMatchesBruteForce) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 5.0, 3);
  const TriangleBvh bvh(sphere);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-8, 8);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    double best = std::numeric_limits<double>::infinity();
    for (const Triangle& t : sphere.triangles) {
      const Vec3 q = closest_point_on_triangle(p, sphere.points[t[0]], sphere.points[t[1]],
                                               sphere.points[t[2]]);
      best = std::min(best, (q - p).norm());
    }
    EXPECT_DOUBLE_EQ(bvh.nearest(p).distance, best);
  }
}

TEST(Dislocation, ScaledSphereIsOffsetByTheScale) {
  const SurfaceMesh reference = icosphere(Vec3::Zero(), 10.0, 4);
  SurfaceMesh moved = reference;
  for (Vec3& p : moved.points) p *= 1.01;  // 0.1 Å outwards: vertices are 0.1 Å off planes
  const Dislocation d = measure_dislocation(moved, reference);
  EXPECT_NEAR(d.max, 0.1, 1e-9);
  EXPECT_NEAR(d.mean, 0.1, 1e-9);
  const Dislocation self = measure_dislocation(reference, reference);
  EXPECT_EQ(self.max, 0.0);
  // Vertices of a coarser sphere lie on the sphere, hence outside the fine polyhedron's
  // chords: distance positive but below the fine mesh's sagitta.
  SurfaceMesh coarse_sphere = icosphere(Vec3::Zero(), 10.0, 2);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).matrix();
  for (Vec3& p : coarse_sphere.points) p = rotation * p;
  const Dislocation coarse = measure_dislocation(coarse_sphere, reference);
  EXPECT_GT(coarse.max, 0.0);
  EXPECT_LT(coarse.max, 0.05);
}

TEST(SelfIntersection, CleanSphereHasNone) {
  EXPECT_EQ(count_self_intersections(icosphere(Vec3::Zero(), 1.0, 3)), 0u);
}

TEST(SelfIntersection, FindsTwoInterpenetratingSpheres) {
  SurfaceMesh a = icosphere(Vec3::Zero(), 1.0, 2);
  const SurfaceMesh b = icosphere(Vec3(1.2, 0.1, 0.05), 1.0, 2);
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles) {
    for (int& v : t) v += offset;
    a.triangles.push_back(t);
  }
  EXPECT_GT(count_self_intersections(a), 10u);
}

TEST(SelfIntersection, FindsAVertexPushedThroughTheOppositeSide) {
  SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 2);
  sphere.points[0] = -1.3 * sphere.points[0];  // a spike through the far side
  EXPECT_GT(count_self_intersections(sphere), 0u);
}

}  // namespace
}  // namespace molmesh
