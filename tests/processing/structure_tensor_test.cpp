#include "molmesh/processing/structure_tensor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "molmesh/processing/vertex_normals.hpp"
#include "molmesh/processing/vertex_rings.hpp"
#include "processing/improve_meshes.hpp"

namespace molmesh {
namespace {

TEST(StructureTensor, PlaneHasOneEigenvalue) {
  std::vector<Vec3> normals(7, Vec3(0, 0, 1));
  const StructureTensor t = structure_tensor_of_normals(normals);
  EXPECT_NEAR(t.eigenvalues[0], 1.0, 1e-12);
  EXPECT_NEAR(t.eigenvalues[1], 0.0, 1e-7);
  EXPECT_NEAR(t.eigenvalues[2], 0.0, 1e-7);
  EXPECT_NEAR(std::abs(t.eigenvectors.col(0).dot(Vec3(0, 0, 1))), 1.0, 1e-12);
}

TEST(StructureTensor, RidgeHasTwoLargeEigenvalues) {
  // Normals of the two faces of a 90° roof along the x axis.
  std::vector<Vec3> normals;
  for (int i = 0; i < 5; ++i) normals.push_back(Vec3(0, 1, 1).normalized());
  for (int i = 0; i < 5; ++i) normals.push_back(Vec3(0, -1, 1).normalized());
  const StructureTensor t = structure_tensor_of_normals(normals);
  EXPECT_NEAR(t.eigenvalues[0], 1.0, 1e-12);
  EXPECT_NEAR(t.eigenvalues[1], 1.0, 1e-12);
  EXPECT_NEAR(t.eigenvalues[2], 0.0, 1e-7);
  EXPECT_NEAR(std::abs(t.eigenvectors.col(2).x()), 1.0, 1e-9);  // along the ridge
}

TEST(StructureTensor, WholeSphereHasThreeEqualEigenvalues) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 3);
  const std::vector<Vec3> normals = vertex_normals(sphere);
  const StructureTensor t = structure_tensor_of_normals(normals);
  EXPECT_NEAR(t.eigenvalues[1], 1.0, 1e-6);
  EXPECT_NEAR(t.eigenvalues[2], 1.0, 1e-6);
}

TEST(StructureTensor, MatchesIterativeSolverOnRandomNormals) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> normals;
    const int count = 2 + trial % 20;
    for (int i = 0; i < count; ++i)
      normals.emplace_back(g(rng), g(rng), 0.2 * (trial % 3) * g(rng));
    const StructureTensor t = structure_tensor_of_normals(normals);
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    for (const Vec3& n : normals) a += n * n.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> reference(a);
    const double top = reference.eigenvalues()[2];
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(t.eigenvalues[k], std::max(0.0, reference.eigenvalues()[2 - k] / top), 1e-8);
      // A e = λ e for the unnormalised tensor.
      const Vec3 e = t.eigenvectors.col(k);
      EXPECT_NEAR(e.norm(), 1.0, 1e-9);
      EXPECT_LT((a * e - reference.eigenvalues()[2 - k] * e).norm(), 1e-7 * top);
    }
    EXPECT_GT(t.eigenvectors.determinant(), 0.999);
  }
}

TEST(StructureTensor, PerVertexOnSphereAndPlane) {
  const SurfaceMesh grid = improve_test::planar_grid(8);
  for (const StructureTensor& t : structure_tensors(grid, 2)) {
    EXPECT_NEAR(t.eigenvalues[1], 0.0, 1e-7);
    EXPECT_NEAR(std::abs(t.eigenvectors(2, 0)), 1.0, 1e-12);
  }
  // On a sphere, the 2-ring tensor is plane-like but with λ2 ≈ λ3 > 0 (isotropic spread).
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 3);
  const std::vector<Vec3> normals = vertex_normals(sphere);
  const auto tensors = structure_tensors(sphere, 2);
  for (std::size_t v = 0; v < sphere.points.size(); ++v) {
    EXPECT_GT(tensors[v].eigenvalues[1], 1e-4);
    EXPECT_NEAR(tensors[v].eigenvalues[1], tensors[v].eigenvalues[2],
                0.35 * tensors[v].eigenvalues[1]);
    EXPECT_GT(std::abs(tensors[v].eigenvectors.col(0).dot(normals[v])), 0.999);
  }
}

TEST(VertexRings, OrderedOneRingIsCounterClockwiseFan) {
  const SurfaceMesh fan = improve_test::planar_fan(6);
  const auto faces = vertex_faces(fan);
  const auto rings = ordered_one_rings(fan, faces);
  const auto ring = rings.of(0);
  ASSERT_EQ(ring.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const int a = ring[i], b = ring[(i + 1) % 6];
    EXPECT_EQ((b - 1), (a - 1 + 1) % 6);  // rim indices increase counter-clockwise
  }
  EXPECT_TRUE(rings.of(1).empty());  // boundary vertex: no closed fan
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 2);
  const auto sphere_rings = ordered_one_rings(sphere, vertex_faces(sphere));
  for (std::size_t v = 0; v < sphere.points.size(); ++v) {
    const auto r = sphere_rings.of(v);
    ASSERT_GE(r.size(), 5u);
    const Vec3 x = sphere.points[v];
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec3 n = (sphere.points[r[i]] - x).cross(sphere.points[r[(i + 1) % r.size()]] - x);
      EXPECT_GT(n.dot(x), 0.0);
    }
  }
  const auto two = k_rings(sphere, vertex_neighbours(sphere, vertex_faces(sphere)), 2);
  EXPECT_EQ(two.of(0).size(), 1u + 5u + 10u);  // icosahedron vertex: valence 5
}

}  // namespace
}  // namespace molmesh
