#include "molmesh/pipeline/surface_pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/point_in_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_field.hpp"
#include "molmesh/volume/level_set_projection.hpp"

namespace molmesh {
namespace {

// The real molecules: closed, manifold, outward, every atom centre inside, and the Euler
// characteristic of a union of closed orientable surfaces (2 per component minus 2 per
// handle).
void check_molecule(const std::string& name, std::size_t min_vertices) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
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

// Issue 13's angle floors through the default pipeline (B = -0.5, 0.5 Å, T0 = 0.2, projected
// onto Eq. 1); mAChE's are in surface_mache_slow_test.cpp.
void check_angle_floors(const std::string& name) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
  const SurfacePipelineResult r = surface_from_atoms(atoms, {});
  const SurfaceStats s = compute_surface_stats(r.surface);
  EXPECT_GE(s.min_angle_deg, 30.0) << name;
  EXPECT_LE(s.max_angle_deg, 112.0) << name;
  EXPECT_GE(s.fraction_angles_40_80, 0.93) << name;
  EXPECT_TRUE(s.closed && s.manifold) << name;
  EXPECT_EQ(s.euler_characteristic, r.stages[1].stats->euler_characteristic) << name;
}

TEST(SurfacePipeline, AngleFloorsOn1a1p) { check_angle_floors("1a1p.pqr"); }
TEST(SurfacePipeline, AngleFloorsOnFas2) { check_angle_floors("fas2.pqr"); }

TEST(SurfacePipeline, VolumeInputSkipsBlur) {
  Atom a;
  a.radius = 1.5;
  const Grid grid = blur_atoms({a}, {});
  SurfacePipelineOptions raw_only;
  raw_only.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  raw_only.raw = true;
  const SurfacePipelineResult r = surface_from_grid(grid, raw_only);
  ASSERT_EQ(r.stages.size(), 1u);
  EXPECT_EQ(r.stages[0].name, "marching cubes");
  EXPECT_EQ(r.stages[0].stats->euler_characteristic, 2);
}

// A volume input keeps its vertices on the volume's (tricubic) level set only when asked.
TEST(SurfacePipeline, VolumeInputProjectsOntoItsLevelSetWhenAsked) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr");
  const Grid grid = blur_atoms(atoms, {});
  const auto worst_distance = [&grid](const SurfaceMesh& mesh) {
    double worst = 0;
    for (const Vec3& p : mesh.points) {
      Vec3 g;
      const double f = tricubic_value(grid, p, &g) - 1.0;
      worst = std::max(worst, std::abs(f) / g.norm());
    }
    return worst;
  };
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  const SurfacePipelineResult plain = surface_from_grid(grid, options);
  EXPECT_FALSE(plain.projection);
  EXPECT_GT(worst_distance(plain.surface), 0.05);
  options.keep_on_surface = true;
  const SurfacePipelineResult kept = surface_from_grid(grid, options);
  ASSERT_TRUE(kept.projection);
  EXPECT_LT(worst_distance(kept.surface), 1e-3);
}

TEST(SurfacePipeline, EmptyIsosurfaceIsAnError) {
  Atom a;
  a.radius = 1.5;
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  options.isovalue = 50.0;                   // far above the peak exp(0.5) of a lone atom
  EXPECT_THROW(surface_from_atoms({a}, options), Error);
}

// Issue 13: a lone atom's Gaussian surface is its sphere (F = 1 at |x - c| = r), and processing
// keeps every vertex on it.
TEST(SurfacePipeline, LoneAtomStaysOnItsSphere) {
  Atom atom;
  atom.center = Vec3(0.3, -0.2, 0.1);
  atom.radius = 2.0;
  const Atoms atoms{atom};
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  const SurfacePipelineResult result = surface_from_atoms(atoms, options);
  ASSERT_GT(result.surface.points.size(), 50u);
  double worst = 0;
  for (const Vec3& p : result.surface.points)
    worst = std::max(worst, std::abs((p - atom.center).norm() - atom.radius));
  EXPECT_LT(worst, 1e-3);
}

// Issue 13: an ellipsoid-like blob of two atoms. Coarsening thins out its flat flanks but must
// keep its curved tips: each tip of the processed surface lies where Eq. 1 puts it (a removed
// tip vertex would leave a flat cap up to a chord error inside), and no facet cuts through the
// volume by more than the 0.15 Å floor.
TEST(SurfacePipeline, TwoAtomBlobKeepsItsTips) {
  Atom left, right;
  left.center = Vec3(-1.6, 0.1, 0.0);
  right.center = Vec3(1.6, 0.1, 0.0);
  left.radius = right.radius = 1.6;
  const Atoms atoms{left, right};
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  const SurfacePipelineResult result = surface_from_atoms(atoms, options);
  ASSERT_TRUE(result.level_set_distance.has_value());
  EXPECT_LT(result.level_set_distance->vertex_max, 1e-3);
  EXPECT_LT(result.level_set_distance->centroid_max, 0.15);
  EXPECT_LT(result.surface.points.size(), result.raw.points.size() / 2);  // coarsened

  // The tips of the exact surface: F = 1 on the axis, by bisection (F falls along it).
  BlurOptions blur = options.blur;
  blur.isovalue = options.isovalue;
  const GaussianField field(atoms, blur);
  const auto tip = [&](double direction) {
    double inside = 1.6, outside = 8.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = (inside + outside) / 2;
      (field.value(Vec3(direction * mid, 0.1, 0.0)) > options.isovalue ? inside : outside) = mid;
    }
    return direction * inside;
  };
  double lo = 1e9, hi = -1e9;
  for (const Vec3& p : result.surface.points) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
  EXPECT_NEAR(hi, tip(+1.0), 0.02);
  EXPECT_NEAR(lo, tip(-1.0), 0.02);
}

}  // namespace
}  // namespace molmesh

namespace molmesh {
namespace {

// The distance to Eq. 1's level set is measured for the Gaussian surface of atoms, with both
// blur methods, and only when asked for; processing keeps the vertices on it by default, and
// without the projection they drift farther from it than the raw ones.
TEST(SurfacePipeline, LevelSetDistanceOfTheGaussianSurface) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr");
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // the paper's surface (the default is ses)
  options.raw = true;
  const SurfacePipelineResult raw = surface_from_atoms(atoms, options);
  ASSERT_TRUE(raw.level_set_distance.has_value());
  options.raw = false;
  const SurfacePipelineResult processed = surface_from_atoms(atoms, options);
  ASSERT_TRUE(processed.level_set_distance.has_value());
  for (const LevelSetDistance& d : {*raw.level_set_distance, *processed.level_set_distance}) {
    for (double v : {d.vertex_mean, d.vertex_max, d.centroid_mean, d.centroid_max}) {
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0);
    }
    EXPECT_LE(d.vertex_mean, d.vertex_max);
    EXPECT_LE(d.centroid_mean, d.centroid_max);
    EXPECT_LT(d.vertex_max, options.blur.spacing * 2);
  }
  EXPECT_LT(raw.level_set_distance->vertex_mean, 0.04 * options.blur.spacing);
  // By default processing keeps the vertices on F = 1 (issue 13's floors: mean 0.005 Å, max
  // 0.05 Å; centroids 0.03 / 0.15 Å); without the projection they drift off it.
  EXPECT_LT(processed.level_set_distance->vertex_mean, 0.005);
  EXPECT_LT(processed.level_set_distance->vertex_max, 0.05);
  EXPECT_LT(processed.level_set_distance->centroid_mean, 0.03);
  EXPECT_LT(processed.level_set_distance->centroid_max, 0.15);
  options.keep_on_surface = false;
  const SurfacePipelineResult drifted = surface_from_atoms(atoms, options);
  EXPECT_GT(drifted.level_set_distance->vertex_mean, raw.level_set_distance->vertex_mean);
  EXPECT_GT(drifted.level_set_distance->vertex_max, 0.05);
  options.keep_on_surface.reset();

  options.raw = true;
  options.blur_method = BlurMethod::kFast;
  const SurfacePipelineResult fast = surface_from_atoms(atoms, options);
  ASSERT_TRUE(fast.level_set_distance.has_value());
  EXPECT_LT(fast.level_set_distance->vertex_mean, 0.1 * options.blur.spacing);

  options.measure = false;
  EXPECT_FALSE(surface_from_atoms(atoms, options).level_set_distance.has_value());
  options.measure = true;
  options.surface = SurfaceKind::kVdw;
  options.blur_method = BlurMethod::kExact;  // the Gaussian-only options keep their defaults
  EXPECT_FALSE(surface_from_atoms(atoms, options).level_set_distance.has_value());
}

// The default surface is the SES; a Gaussian-only option changed with it is refused, not
// silently ignored (docs/surface.md "Which surface").
TEST(SurfacePipeline, GaussianOnlyOptionsAreRefusedForOtherSurfaces) {
  EXPECT_EQ(SurfacePipelineOptions{}.surface, SurfaceKind::kSes);
  const auto refused = [](const SurfacePipelineOptions& options) {
    try {
      options.validate(SurfaceInput::kAtoms);
    } catch (const OptionError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refused(SurfacePipelineOptions{}), "");
  SurfacePipelineOptions blobby;
  blobby.blur.blobbyness = -2.0;
  EXPECT_NE(refused(blobby).find("`blobbyness` applies only to the Gaussian surface"),
            std::string::npos);
  blobby.surface = SurfaceKind::kGaussian;
  EXPECT_EQ(refused(blobby), "");
  SurfacePipelineOptions level;
  level.surface = SurfaceKind::kVdw;
  level.isovalue = 2.0;
  EXPECT_NE(refused(level).find("`isovalue`"), std::string::npos);
  EXPECT_NO_THROW(level.validate(SurfaceInput::kVolume));  // a volume's level is its own
}

}  // namespace
}  // namespace molmesh
