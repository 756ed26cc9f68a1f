#include "molmesh/processing/edge_flips.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/synthetic_meshes.hpp"

namespace molmesh {
namespace {

// Tangential jitter makes a sphere mesh with poor angles (shape kept, connectivity bad).
SurfaceMesh jittered_sphere(int subdivisions, double amount, unsigned seed) {
  SurfaceMesh m = icosphere(Vec3::Zero(), 5.0, subdivisions);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& p : m.points) p = 5.0 * (p + Vec3(u(rng), u(rng), u(rng))).normalized();
  return m;
}

long valence_deviation(const HalfedgeMesh& mesh) {
  long sum = 0;
  for (int v = 0; v < mesh.vertex_capacity(); ++v) {
    if (mesh.vertex_alive(v)) sum += (mesh.valence(v) - 6) * (mesh.valence(v) - 6);
  }
  return sum;
}

TEST(EdgeFlips, RaiseTheWorstAngleAndKeepTopologyOnAJitteredSphere) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    SurfaceMesh mesh = jittered_sphere(3, 0.3, seed);
    const SurfaceStats before = compute_surface_stats(mesh);
    FlipOptions options;
    options.max_dihedral_deg = 25.0;
    const std::size_t flips = flip_edges_for_angles(mesh, options);
    const SurfaceStats after = compute_surface_stats(mesh);
    EXPECT_GT(flips, 10u);
    EXPECT_TRUE(after.closed && after.manifold);
    EXPECT_EQ(after.euler_characteristic, 2);
    EXPECT_EQ(after.vertices, before.vertices);
    EXPECT_EQ(after.triangles, before.triangles);
    EXPECT_GE(after.min_angle_deg, before.min_angle_deg);
    EXPECT_GT(after.fraction_angles_40_80, before.fraction_angles_40_80);
    EXPECT_NO_THROW(HalfedgeMesh(mesh).validate());
  }
}

TEST(EdgeFlips, NeverFlipAcrossTheRidgesOfABox) {
  // A box whose faces are split along one diagonal direction: plenty of flips would raise
  // angles, but an edge on a ridge must stay, so the box keeps its exact volume.
  SurfaceMesh box = test::gridded_box(6, 3.0);
  const SurfaceStats before = compute_surface_stats(box);
  flip_edges_for_angles(box);
  const SurfaceStats after = compute_surface_stats(box);
  EXPECT_NEAR(after.volume, before.volume, 1e-9);
  EXPECT_NEAR(after.area, before.area, 1e-9);
  EXPECT_TRUE(after.closed && after.manifold);
}

TEST(EdgeFlips, ValenceFlipsMoveTowardsSixWithoutBreakingAnything) {
  HalfedgeMesh mesh(jittered_sphere(3, 0.0, 1));
  // Scramble the connectivity with legal flips first (flat enough to pass the ridge gate).
  std::mt19937 rng(7);
  for (int i = 0; i < 400; ++i) {
    const int h = static_cast<int>(rng() % static_cast<unsigned>(3 * mesh.face_capacity()));
    if (flip_is_geometrically_safe(mesh, h, 30.0)) mesh.flip_edge(h);
  }
  ASSERT_NO_THROW(mesh.validate());
  const long before = valence_deviation(mesh);
  const std::size_t flips = flip_edges_for_valence(mesh, FlipOptions{}, 20.0);
  EXPECT_GT(flips, 0u);
  EXPECT_LT(valence_deviation(mesh), before);
  EXPECT_NO_THROW(mesh.validate());
}

TEST(EdgeFlips, FrozenVerticesKeepTheirStars) {
  HalfedgeMesh mesh(jittered_sphere(3, 0.3, 4));
  std::vector<std::uint8_t> frozen(static_cast<std::size_t>(mesh.vertex_capacity()), 0);
  for (int v = 0; v < mesh.vertex_capacity(); v += 2) frozen[v] = 1;
  std::vector<std::vector<int>> rings(frozen.size());
  for (int v = 0; v < mesh.vertex_capacity(); v += 2) mesh.one_ring(v, rings[v]);
  EXPECT_GT(flip_edges_for_angles(mesh, FlipOptions{}, frozen), 0u);
  std::vector<int> ring;
  for (int v = 0; v < mesh.vertex_capacity(); v += 2) {
    mesh.one_ring(v, ring);
    std::sort(ring.begin(), ring.end());
    std::sort(rings[v].begin(), rings[v].end());
    EXPECT_EQ(ring, rings[v]);
  }
}

TEST(EdgeFlips, RealMarchingCubesSurfaceStaysClosedManifoldAndEulerExact) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr");
  SurfacePipelineOptions options;
  options.raw = true;
  SurfaceMesh mesh = surface_from_atoms(atoms, options).raw;
  const SurfaceStats before = compute_surface_stats(mesh);
  const std::size_t flips = flip_edges_for_angles(mesh);
  const SurfaceStats after = compute_surface_stats(mesh);
  EXPECT_GT(flips, 100u);
  EXPECT_TRUE(after.closed && after.manifold);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_EQ(after.components, before.components);
  EXPECT_GE(after.min_angle_deg, before.min_angle_deg);
  EXPECT_NEAR(after.volume, before.volume, 0.01 * before.volume);
  EXPECT_NO_THROW(HalfedgeMesh(mesh).validate());
}

}  // namespace
}  // namespace molmesh
