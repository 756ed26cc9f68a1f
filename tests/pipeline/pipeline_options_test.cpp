// SurfacePipelineOptions::validate() and ImprovePipelineOptions::validate(): every ranged
// option of surface_option_specs.hpp and improve_option_specs.hpp (and the processing options
// they hold) is refused when NaN, infinite or out of range, naming its member, by the
// library's entry points too; a volume's isovalue may be any finite number.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/pipeline/improve_pipeline.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message validate() throws, or "" when it accepts the options; any other exception
// than OptionError fails the test.
std::string complaint(const std::function<void()>& validate) {
  try {
    validate();
  } catch (const OptionError& e) {  // the type the CLI maps to exit code 2
    return e.what();
  }
  return "";
}

std::string surface_with(const std::function<void(SurfacePipelineOptions&)>& change,
                         SurfaceInput input = SurfaceInput::kAtoms) {
  SurfacePipelineOptions options;
  change(options);
  return complaint([&] { options.validate(input); });
}

std::string improve_with(const std::function<void(ImprovePipelineOptions&)>& change) {
  ImprovePipelineOptions options;
  change(options);
  return complaint([&] { options.validate(); });
}

bool names(const std::string& message, const std::string& member) {
  return message.find("`" + member + "`") != std::string::npos;
}

TEST(SurfacePipelineOptions, DefaultsPass) {
  EXPECT_EQ(surface_with([](auto&) {}), "");
  EXPECT_EQ(surface_with([](auto&) {}, SurfaceInput::kVolume), "");
  for (SurfaceKind kind : kSurfaceKinds)
    EXPECT_EQ(surface_with([kind](auto& o) { o.surface = kind; }), "");
}

TEST(SurfacePipelineOptions, NonFiniteValuesAreRefusedNamingTheMember) {
  for (double bad : {kNaN, kInf, -kInf}) {
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.probe_radius = bad; }), "probe_radius"));
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.blur.spacing = bad; }), "spacing"));
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.blur.blobbyness = bad; }), "blobbyness"));
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.isovalue = bad; }), "isovalue"));
    EXPECT_TRUE(
        names(surface_with([&](auto& o) { o.isovalue = bad; }, SurfaceInput::kVolume), "isovalue"));
    EXPECT_TRUE(
        names(surface_with([&](auto& o) { o.min_cavity_volume = bad; }), "min_cavity_volume"));
    // The processing options it holds, the coarsening thresholds among them.
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.processing.t0 = {bad}; }), "t0"));
    EXPECT_TRUE(names(surface_with([&](auto& o) { o.processing.alpha = bad; }), "alpha"));
  }
}

TEST(SurfacePipelineOptions, OutOfRangeValuesAreRefusedWithTheRangeAndTheValue) {
  EXPECT_EQ(surface_with([](auto& o) { o.blur.spacing = 0.0; }),
            "`spacing` must be a finite number in (0, inf) (got 0)");
  EXPECT_EQ(surface_with([](auto& o) { o.blur.blobbyness = 0.5; }),
            "`blobbyness` must be a finite number in [-1e+06, -1e-12] (got 0.5)");
  EXPECT_TRUE(names(surface_with([](auto& o) { o.probe_radius = -1.0; }), "probe_radius"));
  EXPECT_TRUE(
      names(surface_with([](auto& o) { o.min_cavity_volume = -1.0; }), "min_cavity_volume"));
  EXPECT_TRUE(names(surface_with([](auto& o) { o.processing.rings = 0; }), "rings"));
}

TEST(SurfacePipelineOptions, TheIsovalueRangeIsForAtomsOnly) {
  EXPECT_TRUE(names(surface_with([](auto& o) { o.isovalue = -1.0; }), "isovalue"));
  EXPECT_TRUE(names(surface_with([](auto& o) { o.isovalue = 0.0; }), "isovalue"));
  // A potential map's level may be zero or negative.
  EXPECT_EQ(surface_with([](auto& o) { o.isovalue = -1.0; }, SurfaceInput::kVolume), "");
  EXPECT_EQ(surface_with([](auto& o) { o.isovalue = 0.0; }, SurfaceInput::kVolume), "");
}

TEST(SurfacePipelineOptions, TheEntryPointsValidateFirst) {
  SurfacePipelineOptions bad;
  bad.min_cavity_volume = kNaN;
  // No atoms, an empty grid: validation comes before anything looks at the input.
  EXPECT_TRUE(names(complaint([&] { surface_from_atoms({}, bad); }), "min_cavity_volume"));
  EXPECT_TRUE(names(complaint([&] { surface_from_grid(Grid{}, bad); }), "min_cavity_volume"));
}

TEST(SurfacePipelineOptions, AVolumeIsContouredAtANegativeIsovalue) {
  Atom a;
  a.radius = 1.5;
  Grid grid = blur_atoms({a}, {});
  for (double& v : grid.values) v -= 2.0;  // the blurred atom's level 1 is now -1
  SurfacePipelineOptions options;
  options.raw = true;
  options.isovalue = -1.0;
  const SurfacePipelineResult r = surface_from_grid(grid, options);
  EXPECT_FALSE(r.surface.triangles.empty());
  EXPECT_EQ(r.level, -1.0);
}

TEST(ImprovePipelineOptions, DefaultsPass) {
  EXPECT_EQ(improve_with([](auto&) {}), "");
}

TEST(ImprovePipelineOptions, BadValuesAreRefusedNamingTheMember) {
  for (double bad : {kNaN, kInf, -1.0}) {
    EXPECT_TRUE(
        names(improve_with([&](auto& o) { o.repair.merge_tolerance = bad; }), "merge_tolerance"));
    EXPECT_TRUE(names(improve_with([&](auto& o) { o.processing.t0 = {0.1, bad}; }), "t0"));
    EXPECT_TRUE(names(improve_with([&](auto& o) { o.processing.improve.feature_weight = bad; }),
                      "feature_weight"));
  }
  EXPECT_TRUE(names(improve_with([](auto& o) { o.processing.improve.sweeps = 101; }), "sweeps"));
}

TEST(ImprovePipelineOptions, ImproveSurfaceValidatesFirst) {
  ImprovePipelineOptions bad;
  bad.processing.cleanup_rounds = -1;
  // A mesh without triangles would be an InputError; the options are looked at first.
  EXPECT_TRUE(names(complaint([&] { improve_surface({}, "mesh", bad); }), "cleanup_rounds"));
}

}  // namespace
}  // namespace molmesh
