#include "molmesh/pipeline/surface_pipeline.hpp"

#include <gtest/gtest.h>

#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/point_in_mesh.hpp"

namespace molmesh {
namespace {

// The real molecules: closed, manifold, outward, every atom centre inside, and the Euler
// characteristic of a union of closed orientable surfaces (2 per component minus 2 per
// handle).
void check_molecule(const std::string& name, std::size_t min_vertices) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
  SurfacePipelineOptions options;
  options.raw = true;
  const SurfacePipelineResult result = surface_from_atoms(atoms, options);
  ASSERT_FALSE(result.stages.empty());
  EXPECT_EQ(result.stages[0].name, "blur");
  EXPECT_EQ(result.stages[1].name, "marching cubes");
  ASSERT_TRUE(result.stages[1].stats.has_value());
  const SurfaceStats& s = *result.stages[1].stats;
  EXPECT_TRUE(s.closed) << name;
  EXPECT_TRUE(s.manifold) << name;
  EXPECT_GT(s.volume, 0.0) << name;
  EXPECT_GE(s.vertices, min_vertices) << name;
  EXPECT_GT(s.min_angle_deg, 0.0) << name;
  EXPECT_GE(s.components, 1);
  EXPECT_LE(s.euler_characteristic, 2L * s.components);
  EXPECT_EQ(s.euler_characteristic % 2, 0);
  EXPECT_EQ(result.surface.triangles, result.raw.triangles);

  const PointInMesh tester(result.raw);
  int outside = 0;
  for (const Atom& a : atoms)
    if (a.radius > 0.0 && tester.winding_number(a.center) != 1) ++outside;
  EXPECT_EQ(outside, 0) << name;
}

TEST(SurfacePipeline, Molecule1a1p) { check_molecule("1a1p.pqr", 8000); }
TEST(SurfacePipeline, MoleculeFas2) { check_molecule("fas2.pqr", 20000); }
TEST(SurfacePipeline, MoleculeFromPdbWithRadiusTable) { check_molecule("1a1p.pdb", 8000); }

TEST(SurfacePipeline, VolumeInputSkipsBlur) {
  Atom a;
  a.radius = 1.5;
  const Grid grid = blur_atoms({a}, {});
  SurfacePipelineOptions raw_only;
  raw_only.raw = true;
  const SurfacePipelineResult r = surface_from_grid(grid, raw_only);
  ASSERT_EQ(r.stages.size(), 1u);
  EXPECT_EQ(r.stages[0].name, "marching cubes");
  EXPECT_EQ(r.stages[0].stats->euler_characteristic, 2);
}

TEST(SurfacePipeline, EmptyIsosurfaceIsAnError) {
  Atom a;
  a.radius = 1.5;
  SurfacePipelineOptions options;
  options.isovalue = 50.0;  // far above the peak exp(0.5) of a lone atom
  EXPECT_THROW(surface_from_atoms({a}, options), Error);
}

}  // namespace
}  // namespace molmesh
