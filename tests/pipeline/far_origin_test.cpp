// Results do not depend on where the molecule sits (issue 18, finding 8): two atoms 2 Å apart
// at the origin and at (1e7, 1e7, 1e7) give the same processed surface and tetrahedral mesh.
// Before the local frame the far copy came out with ~1e6 times the area.
#include <gtest/gtest.h>

#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {
namespace {

Atoms two_atoms(const Vec3& at) {
  Atoms atoms(2);
  atoms[0].center = at;
  atoms[1].center = at + Vec3(2.0, 0.0, 0.0);
  for (auto& a : atoms) a.radius = 1.7;
  return atoms;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(FarFromOrigin, ProcessedSurfaceAndTetMeshDoNotDependOnPosition) {
  // Both pairs are centred on a multiple of the grid spacing (the origin and 1e7 per axis), so
  // the far pair's local frame puts its atoms exactly where the near pair's are.
  const Vec3 far(1e7 - 1.0, 1e7, 1e7);
  const SurfacePipelineResult near_result = surface_from_atoms(two_atoms(Vec3(-1.0, 0.0, 0.0)), {});
  const SurfacePipelineResult far_result = surface_from_atoms(two_atoms(far), {});
  const SurfaceStats a = compute_surface_stats(near_result.surface);
  const SurfaceStats b = compute_surface_stats(far_result.surface);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_LT(relative(b.area, a.area), 1e-6) << a.area << " vs " << b.area;
  EXPECT_LT(relative(b.volume, a.volume), 1e-6) << a.volume << " vs " << b.volume;
  EXPECT_GT(a.area, 40.0);
  // The far surface sits where the atoms are.
  Vec3 centre = Vec3::Zero();
  for (const auto& p : far_result.surface.points) centre += p;
  centre /= static_cast<double>(far_result.surface.points.size());
  EXPECT_LT((centre - (far + Vec3(1, 0, 0))).norm(), 0.1);

  // Processing a far user mesh (the improve and hierarchy path) too.
  ProcessingOptions processing;
  SurfaceMesh shifted = near_result.raw;
  for (auto& p : shifted.points) p += far;
  const double area_near =
      compute_surface_stats(process_surface(near_result.raw, processing).mesh).area;
  const double area_far = compute_surface_stats(process_surface(shifted, processing).mesh).area;
  EXPECT_LT(relative(area_far, area_near), 1e-6) << area_near << " vs " << area_far;

  TetMeshOptions tet;
  tet.domain = Domain::interior;
  const TetStats ta =
      compute_tet_stats(tetrahedralize(near_result.surface, two_atoms(Vec3(-1.0, 0.0, 0.0)), tet));
  const TetStats tb = compute_tet_stats(tetrahedralize(far_result.surface, two_atoms(far), tet));
  EXPECT_EQ(ta.tetrahedra, tb.tetrahedra);
  EXPECT_NEAR(ta.min_dihedral_deg, tb.min_dihedral_deg, 1e-3);
}

}  // namespace
}  // namespace molmesh
