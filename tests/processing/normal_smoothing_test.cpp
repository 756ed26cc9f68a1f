#include "molmesh/processing/normal_smoothing.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <random>

#include "processing/improve_meshes.hpp"

namespace molmesh {
namespace {

double radial_rms(const SurfaceMesh& mesh, double r) {
  double sum = 0;
  for (const Vec3& p : mesh.points) sum += (p.norm() - r) * (p.norm() - r);
  return std::sqrt(sum / static_cast<double>(mesh.points.size()));
}

SurfaceMesh noisy_sphere(unsigned seed) {
  SurfaceMesh mesh = icosphere(Vec3::Zero(), 10.0, 3);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 0.08);  // 8% of the ~0.9 Å edge length
  for (Vec3& p : mesh.points) p *= 1.0 + g(rng) / 10.0;
  return mesh;
}

TEST(NormalSmoothing, ReducesNoiseAndKeepsSphereVolume) {
  SurfaceMesh mesh = noisy_sphere(1);
  const double volume = improve_test::enclosed_volume(mesh);
  const double noise = radial_rms(mesh, 10.0);
  NormalSmoothingOptions options;
  options.vertex_iterations = 5;
  smooth_normals(mesh, options);
  EXPECT_NEAR(improve_test::enclosed_volume(mesh), volume, 0.01 * volume);
  EXPECT_LT(radial_rms(mesh, 10.0), 0.6 * noise);
}

TEST(NormalSmoothing, DefaultKeepsVolumeWithinOnePercent) {
  SurfaceMesh mesh = noisy_sphere(2);
  const double volume = improve_test::enclosed_volume(mesh);
  smooth_normals(mesh);
  EXPECT_NEAR(improve_test::enclosed_volume(mesh), volume, 0.01 * volume);
}

TEST(NormalSmoothing, KeepsCubeEdgesSharp) {
  // A cube from a subdivided icosphere would not do: build a box of 8 corners, 12 faces,
  // subdivided into a fine grid per face by splitting each face 4:1 three times.
  SurfaceMesh cube;
  for (int i = 0; i < 8; ++i) cube.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (int level = 0; level < 3; ++level) {
    std::map<std::pair<int, int>, int> mid;
    std::vector<Triangle> next;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      cube.points.push_back(0.5 * (cube.points[a] + cube.points[b]));
      return mid[key] = static_cast<int>(cube.points.size()) - 1;
    };
    for (const Triangle& t : cube.triangles) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    cube.triangles = next;
  }
  ASSERT_GT(improve_test::enclosed_volume(cube), 0.99);
  const SurfaceMesh before = cube;
  NormalSmoothingOptions options;
  options.vertex_iterations = 5;
  smooth_normals(cube, options);
  double worst = 0;
  for (std::size_t v = 0; v < cube.points.size(); ++v) {
    worst = std::max(worst, (cube.points[v] - before.points[v]).norm());
  }
  EXPECT_LT(worst, 0.01);  // flat faces, 90° edges: nothing for the filter to smooth away
}

TEST(NormalSmoothing, SameBitsWithOneOrTwoThreads) {
  SurfaceMesh one = noisy_sphere(3);
  SurfaceMesh two = one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    smooth_normals(one);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    smooth_normals(two);
  }
  for (std::size_t v = 0; v < one.points.size(); ++v) EXPECT_EQ(one.points[v], two.points[v]);
}

}  // namespace
}  // namespace molmesh
