// The paper's floors on real molecules, with the paper's parameters (B = -0.5, 0.5 Å grid,
// isovalue 1, T0 = 0.2, α = β = 1, 2 rings). Numbers measured are in docs/processing.md.
#include <gtest/gtest.h>

#include <cstdio>

#include "molmesh/processing/dislocation.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/processing/self_intersection.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/molecule_surfaces.hpp"

namespace molmesh {
namespace {

class Floors : public ::testing::TestWithParam<const char*> {};

TEST_P(Floors, PaperFloorsHold) {
  const SurfaceMesh raw = improve_test::raw_surface(GetParam());
  const SurfaceStats before = compute_surface_stats(raw);
  const ProcessingResult result = process_surface(raw, {});
  const SurfaceStats after = compute_surface_stats(result.mesh);
  const Dislocation d = measure_dislocation(result.mesh, raw);
  std::printf(
      "%s: %zu -> %zu vertices, min %.2f, max %.2f, %.1f%% in [40,80], "
      "dislocation max %.3f mean %.4f\n",
      GetParam(), before.vertices, after.vertices, after.min_angle_deg, after.max_angle_deg,
      100 * after.fraction_angles_40_80, d.max, d.mean);

  // Topology: closed manifold, same components and Euler characteristic, no self-cuts.
  EXPECT_TRUE(after.closed);
  EXPECT_TRUE(after.manifold);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_EQ(count_self_intersections(result.mesh), 0u);

  // Angles.
  EXPECT_GE(after.min_angle_deg, 22.0);
  EXPECT_LE(after.max_angle_deg, 130.0);
  EXPECT_GE(after.fraction_angles_40_80, 0.88);

  // Shape.
  EXPECT_LE(d.mean, 0.05);
  EXPECT_LE(d.max, 0.5);
  EXPECT_NEAR(after.volume, before.volume, 0.02 * before.volume);

  // Size at T0 = 0.2.
  EXPECT_GE(static_cast<double>(before.vertices), 4.0 * static_cast<double>(after.vertices));
}

INSTANTIATE_TEST_SUITE_P(Molecules, Floors,
                         ::testing::Values("1a1p.pqr", "fas2.pqr", "mache.pqr", "1a1p.pdb"));

}  // namespace
}  // namespace molmesh
