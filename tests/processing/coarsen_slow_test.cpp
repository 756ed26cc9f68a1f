// Coarsening on the larger real molecules: topology, reduction, keep-spheres, and the whole
// GAMer post-processing chain (improve -> coarsen -> smooth -> improve) around it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/coarsen.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/coarsen_checks.hpp"

namespace molmesh {
namespace {

SurfaceMesh raw_surface(const std::string& file) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + file);
  SurfacePipelineOptions options;
  options.raw = true;
  return surface_from_atoms(atoms, options).raw;
}

class CoarsenMolecule : public ::testing::TestWithParam<const char*> {};

TEST_P(CoarsenMolecule, KeepsTopologyAndRemovesMostVertices) {
  const SurfaceMesh raw = raw_surface(GetParam());
  const SurfaceStats before = compute_surface_stats(raw);
  const CoarsenResult result = coarsen(raw, CoarsenOptions{});
  const SurfaceStats after = compute_surface_stats(result.mesh);
  std::printf("%s coarsen raw: %zu -> %zu vertices\n", GetParam(), before.vertices, after.vertices);
  EXPECT_TRUE(after.closed && after.manifold);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_LE(after.vertices * 2, before.vertices);
  EXPECT_NEAR(after.volume, before.volume, 0.02 * before.volume);
  EXPECT_NO_THROW(HalfedgeMesh(result.mesh).validate());
  for (std::size_t i = 0; i < result.provenance.size(); ++i) {
    ASSERT_EQ(result.mesh.points[i], raw.points[result.provenance[i]]);
  }
}

INSTANTIATE_TEST_SUITE_P(Real, CoarsenMolecule, ::testing::Values("fas2.pqr", "mache.pqr"));

TEST(CoarsenSlow, FullPostProcessingOfMache) {
  const SurfaceMesh raw = raw_surface("mache.pqr");
  const SurfaceStats before = compute_surface_stats(raw);
  ProcessingOptions options;
  options.record_stages = false;
  const ProcessingResult result = process_surface(raw, options);
  const SurfaceStats after = compute_surface_stats(result.mesh);
  std::printf("mache pipeline: %zu -> %zu vertices, min %.2f max %.2f in[40,80] %.3f\n",
              before.vertices, after.vertices, after.min_angle_deg, after.max_angle_deg,
              after.fraction_angles_40_80);
  EXPECT_TRUE(after.closed && after.manifold);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_LE(after.vertices * 4, before.vertices);  // GAMer 1: 102324 -> 20638
}

TEST(CoarsenSlow, ActiveSiteSphereStaysDense) {
  const SurfaceMesh raw = raw_surface("mache.pqr");
  // A ball around a surface point: everything in it must survive coarsening untouched.
  const Vec3 centre = raw.points[raw.points.size() / 2];
  CoarsenOptions options;
  options.keep_spheres = {Sphere{centre, 6.0}};
  const CoarsenResult result = coarsen(raw, options);
  EXPECT_GT(test::expect_keep_sphere_untouched(raw, result, options.keep_spheres[0]), 100u);
  EXPECT_LE(result.mesh.points.size() * 2, raw.points.size());
}

}  // namespace
}  // namespace molmesh
