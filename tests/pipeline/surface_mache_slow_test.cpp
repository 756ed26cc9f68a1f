// mAChE (8279 atoms), the paper's molecule: the full raw surface checks, and the same mesh
// with one and two threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/self_intersection.hpp"
#include "molmesh/surface/point_in_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"

namespace molmesh {
namespace {

TEST(SurfaceMache, ClosedManifoldOutwardAllAtomsInsideDeterministic) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr");
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // GAMer 1's surface, for its node count
  options.raw = true;
  SurfacePipelineResult one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = surface_from_atoms(atoms, options);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = surface_from_atoms(atoms, options);
  }
  EXPECT_TRUE(one.raw.points == two.raw.points);
  EXPECT_TRUE(one.raw.triangles == two.raw.triangles);

  const SurfaceStats& s = *two.stages[1].stats;
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_GT(s.volume, 0.0);
  EXPECT_GT(s.min_angle_deg, 0.0);
  // GAMer 1 gets 102324 raw nodes with the same parameters.
  EXPECT_NEAR(static_cast<double>(s.vertices), 102324.0, 0.02 * 102324.0);
  EXPECT_LE(s.euler_characteristic, 2L * s.components);
  EXPECT_EQ(s.euler_characteristic % 2, 0);

  const PointInMesh tester(two.raw);
  int outside = 0;
  for (const Atom& a : atoms)
    if (a.radius > 0.0 && tester.winding_number(a.center) != 1) ++outside;
  EXPECT_EQ(outside, 0);
}

// Issue 13's floors on the paper's molecule and surface (the Gaussian, B = -0.5, isovalue 1):
// angles (min ≥ 30°, max ≤ 112°, ≥ 93 % in [40°, 80°]), no more than 18k vertices, the raw volume
// within 0.5 %, vertices on Eq. 1's level set.
TEST(SurfaceMache, PaperGaussianSurfaceReachesTheQualityFloors) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr");
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;
  const SurfacePipelineResult r = surface_from_atoms(atoms, options);
  const SurfaceStats s = compute_surface_stats(r.surface);
  EXPECT_GE(s.min_angle_deg, 30.0);
  EXPECT_LE(s.max_angle_deg, 112.0);
  EXPECT_GE(s.fraction_angles_40_80, 0.93);
  EXPECT_LE(s.vertices, 18000u);
  EXPECT_TRUE(s.closed && s.manifold);
  const SurfaceStats& raw = *r.stages[1].stats;
  EXPECT_EQ(s.euler_characteristic, raw.euler_characteristic);
  EXPECT_NEAR(s.volume, raw.volume, 0.005 * raw.volume);
  ASSERT_TRUE(r.level_set_distance.has_value());
  EXPECT_LT(r.level_set_distance->vertex_max, 0.05);
}

// Issue 12's floors for every surface kind (those of the Gaussian pipeline: min >= 27°,
// max <= 115°, >= 91 % in [40°, 80°]) on the SES (1.4 Å probe) of mAChE, where one 122°
// triangle on a 93° crease was left until the last poor triangles were collapsed
// (processing/poor_triangle_collapse.hpp); closed, manifold, no self-intersection, the raw
// topology and volume. The SES is the default surface.
TEST(SurfaceMache, SesSurfaceReachesTheQualityFloors) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr");
  const SurfacePipelineResult r = surface_from_atoms(atoms, {});
  ASSERT_EQ(SurfacePipelineOptions{}.surface, SurfaceKind::kSes);
  const SurfaceStats s = compute_surface_stats(r.surface);
  EXPECT_GE(s.min_angle_deg, 27.0);
  EXPECT_LE(s.max_angle_deg, 115.0);
  EXPECT_GE(s.fraction_angles_40_80, 0.91);
  EXPECT_TRUE(s.closed && s.manifold);
  EXPECT_EQ(count_self_intersections(r.surface), 0u);
  const SurfaceStats& raw = *r.stages[1].stats;
  EXPECT_EQ(s.euler_characteristic, raw.euler_characteristic);
  EXPECT_NEAR(s.volume, raw.volume, 0.005 * raw.volume);
}

}  // namespace
}  // namespace molmesh
