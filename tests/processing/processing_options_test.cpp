// ProcessingOptions::validate(): every ranged option of processing_option_specs.hpp and
// every T0 is refused when NaN, infinite or out of range, naming its member.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/processing/process_surface.hpp"

namespace molmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message validate() throws for `options`, or "" when it accepts them.
std::string complaint(const ProcessingOptions& options) {
  try {
    options.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string with(const std::function<void(ProcessingOptions&)>& change) {
  ProcessingOptions options;
  change(options);
  return complaint(options);
}

TEST(ProcessingOptions, DefaultsPass) {
  EXPECT_EQ(complaint(ProcessingOptions{}), "");
  ProcessingOptions none;
  none.t0.clear();
  EXPECT_EQ(complaint(none), "");
}

TEST(ProcessingOptions, NonFiniteValuesAreRefusedNamingTheMember) {
  for (double bad : {kNaN, kInf, -kInf}) {
    EXPECT_NE(with([&](auto& o) { o.alpha = bad; }).find("`alpha`"), std::string::npos) << bad;
    EXPECT_NE(with([&](auto& o) { o.beta = bad; }).find("`beta`"), std::string::npos) << bad;
    EXPECT_NE(with([&](auto& o) { o.improve.feature_weight = bad; }).find("`feature_weight`"),
              std::string::npos)
        << bad;
    EXPECT_NE(with([&](auto& o) { o.t0 = {0.1, bad}; }).find("`t0`"), std::string::npos) << bad;
  }
}

TEST(ProcessingOptions, OutOfRangeValuesAreRefusedWithTheRangeAndTheValue) {
  EXPECT_EQ(with([](auto& o) { o.rings = 0; }),
            "`rings` must be a finite number in [1, 10] (got 0)");
  EXPECT_NE(with([](auto& o) { o.rings = 11; }), "");
  EXPECT_EQ(with([](auto& o) {
              o.t0 = {0.2, -0.1};
            }),
            "`t0` must be a finite number in [0, inf) (got -0.1)");
  EXPECT_NE(with([](auto& o) { o.alpha = -1.0; }), "");
  EXPECT_NE(with([](auto& o) { o.improve.sweeps = 101; }).find("`sweeps`"), std::string::npos);
  EXPECT_NE(with([](auto& o) { o.smoothing.normal_iterations = -1; }).find("`normal_iterations`"),
            std::string::npos);
  EXPECT_NE(with([](auto& o) { o.cleanup_rounds = 1000; }).find("`cleanup_rounds`"),
            std::string::npos);
}

TEST(ProcessingOptions, TheRangesBoundsAreAccepted) {
  EXPECT_EQ(with([](auto& o) {
              o.rings = 10;
              o.improve.sweeps = 0;
              o.smoothing.normal_iterations = 100;
              o.cleanup_rounds = 0;
              o.t0 = {0.0, 1e300};
            }),
            "");
}

TEST(ProcessingOptions, ProcessSurfaceRefusesThemBeforeLookingAtTheMesh) {
  ProcessingOptions bad;
  bad.improve.sweeps = 1000;  // no later stage refuses it
  // An empty mesh, which processes to nothing: validation comes first, whatever the input.
  EXPECT_NO_THROW(process_surface(SurfaceMesh{}, ProcessingOptions{}));
  try {
    process_surface(SurfaceMesh{}, bad);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("`sweeps`"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace molmesh
