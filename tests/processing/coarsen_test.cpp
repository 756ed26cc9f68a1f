#include "molmesh/processing/coarsen.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/coarsen_checks.hpp"
#include "processing/synthetic_meshes.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh {
namespace {

bool on_box_edge(const Vec3& p, double size) {
  int extreme = 0;
  for (int i = 0; i < 3; ++i) {
    extreme += (std::abs(p[i]) < 1e-9 || std::abs(p[i] - size) < 1e-9) ? 1 : 0;
  }
  return extreme >= 2;
}

// `mesh` is `components` closed manifold spheres (Euler characteristic 2 each).
SurfaceStats expect_closed_spheres(const SurfaceMesh& mesh, int components) {
  const SurfaceStats stats = compute_surface_stats(mesh);
  EXPECT_TRUE(stats.closed && stats.manifold);
  EXPECT_EQ(stats.components, components);
  EXPECT_EQ(stats.euler_characteristic, 2 * components);
  return stats;
}

TEST(Coarsen, ThinsFlatFacesAndKeepsSharpRidges) {
  const double size = 4.0;
  const SurfaceMesh box = test::gridded_box(8, size);
  // 0.5 Å squares, the paper's grid spacing: ridge vertices have L * lambda2/lambda1 >=
  // 0.5 * 0.6 > T0, flat ones ~0.
  const CoarsenResult result = coarsen(box, CoarsenOptions{});
  const SurfaceStats before = compute_surface_stats(box);
  const SurfaceStats after = compute_surface_stats(result.mesh);
  ASSERT_TRUE(after.closed && after.manifold);
  EXPECT_EQ(after.euler_characteristic, 2);
  EXPECT_EQ(after.components, 1);
  ASSERT_EQ(result.provenance.size(), result.mesh.points.size());
  EXPECT_EQ(result.removed, box.points.size() - result.mesh.points.size());

  std::size_t edge_in = 0, edge_out = 0, flat_in = 0, flat_out = 0;
  for (const Vec3& p : box.points) (on_box_edge(p, size) ? edge_in : flat_in)++;
  for (std::size_t i = 0; i < result.mesh.points.size(); ++i) {
    const Vec3& p = result.mesh.points[i];
    EXPECT_EQ(p, box.points[result.provenance[i]]);  // vertices never move
    (on_box_edge(p, size) ? edge_out : flat_out)++;
  }
  // Every vertex on the 12 ridges survives; the flat faces lose most of theirs.
  EXPECT_EQ(edge_out, edge_in);
  EXPECT_LT(flat_out, flat_in / 2);
  // The shape is exactly the same box: no ridge was cut.
  EXPECT_NEAR(after.volume, before.volume, 1e-9 * before.volume);
  EXPECT_NEAR(after.area, before.area, 1e-9 * before.area);
  EXPECT_GT(after.min_angle_deg, 15.0);
}

TEST(Coarsen, KeepSpheresProtectTheirVertices) {
  const SurfaceMesh box = test::gridded_box(16, 8.0);
  CoarsenOptions options;
  const Sphere keep{Vec3(4.0, 4.0, 8.0), 2.2};  // a disc on the top face
  options.keep_spheres = {keep};
  const CoarsenResult result = coarsen(box, options);
  EXPECT_GT(test::expect_keep_sphere_untouched(box, result, keep), 50u);
  // Away from the sphere the top face still coarsens.
  EXPECT_LT(result.mesh.points.size(), box.points.size() / 2);
}

TEST(Coarsen, SmallThresholdDeletesNothingAndLargeOneIsSafeOnASphere) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 10.0, 4);
  CoarsenOptions none;
  none.t0 = 1e-6;
  EXPECT_EQ(coarsen(sphere, none).removed, 0u);

  CoarsenOptions lots;
  lots.t0 = 5.0;
  lots.max_passes = 20;
  const CoarsenResult result = coarsen(sphere, lots);
  const SurfaceStats stats = expect_closed_spheres(result.mesh, 1);
  EXPECT_GT(result.removed, sphere.points.size() / 2);
  EXPECT_GT(stats.volume, 0.0);
}

TEST(Coarsen, NeverShrinksAComponentBelowATetrahedron) {
  SurfaceMesh two = icosphere(Vec3::Zero(), 1.0, 1);
  testing::append_surface(two, icosphere(Vec3(5, 0, 0), 1.0, 0));
  CoarsenOptions options;
  options.t0 = 1e6;  // delete whatever topology and geometry allow
  options.max_passes = 50;
  const CoarsenResult result = coarsen(two, options);
  expect_closed_spheres(result.mesh, 2);
  EXPECT_GE(result.mesh.points.size(), 8u);
}

TEST(Coarsen, RejectsBadOptionsAndInput) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 1);
  CoarsenOptions bad;
  bad.rings = 0;
  EXPECT_THROW(coarsen(sphere, bad), Error);
  SurfaceMesh open = sphere;
  open.triangles.pop_back();
  EXPECT_THROW(coarsen(open, CoarsenOptions{}), Error);
}

SurfaceMesh raw_surface(const char* file) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + file);
  SurfacePipelineOptions options;
  options.raw = true;
  return surface_from_atoms(atoms, options).raw;
}

TEST(Coarsen, RealMoleculeHalvesAndKeepsTopology) {
  const SurfaceMesh raw = raw_surface("1a1p.pqr");
  const SurfaceStats before = compute_surface_stats(raw);
  const CoarsenResult result = coarsen(raw, CoarsenOptions{});
  const SurfaceStats after = compute_surface_stats(result.mesh);
  std::printf("1a1p: %zu -> %zu vertices, min %.2f max %.2f in[40,80] %.3f passes %d\n",
              before.vertices, after.vertices, after.min_angle_deg, after.max_angle_deg,
              after.fraction_angles_40_80, result.passes);
  EXPECT_TRUE(after.closed && after.manifold);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_LE(after.vertices * 2, before.vertices);
  EXPECT_NEAR(after.volume, before.volume, 0.02 * before.volume);
}

TEST(Coarsen, IsDeterministicAndThreadCountIndependent) {
  const SurfaceMesh raw = raw_surface("1a1p.pqr");
  const CoarsenResult a = coarsen(raw, CoarsenOptions{});
  CoarsenResult b;
  {
    // One thread must give exactly what the full pool gives.
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    b = coarsen(raw, CoarsenOptions{});
  }
  EXPECT_EQ(a.provenance, b.provenance);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

}  // namespace
}  // namespace molmesh
