#include "molmesh/core/option_spec.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message check_range throws for `value`, or "" when it accepts it.
std::string complaint(const OptionSpec& spec, double value) {
  try {
    check_range(spec, value);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CheckRange, NamesTheMemberTheRangeAndTheValueGot) {
  const OptionSpec spec{"blur", "blur_method", "help", OptionRange{0.0, 100.0, false}};
  EXPECT_EQ(complaint(spec, 101.0), "`blur_method` must be a finite number in [0, 100] (got 101)");
  EXPECT_EQ(complaint(spec, kNaN), "`blur_method` must be a finite number in [0, 100] (got nan)");
}

TEST(CheckRange, BoundsAreClosedUnlessTheLowestIsExcluded) {
  const OptionSpec closed{"a", "a", "", OptionRange{1.0, 10.0, false}};
  EXPECT_EQ(complaint(closed, 1.0), "");
  EXPECT_EQ(complaint(closed, 10.0), "");
  EXPECT_NE(complaint(closed, 0.5), "");
  EXPECT_NE(complaint(closed, 10.5), "");
  const OptionSpec open{"b", "b", "", OptionRange{0.0, kInf, true}};
  EXPECT_NE(complaint(open, 0.0), "");
  EXPECT_EQ(complaint(open, 1e300), "");
  EXPECT_NE(complaint(open, -1.0), "");
}

TEST(CheckRange, NonFiniteValuesAreRefusedEvenWithoutAnUpperBound) {
  const OptionSpec spec{"a", "a", "", OptionRange{0.0, kInf, false}};
  EXPECT_NE(complaint(spec, kInf), "");
  EXPECT_NE(complaint(spec, -kInf), "");
  EXPECT_NE(complaint(spec, kNaN), "");
  EXPECT_NE(complaint(spec, -kNaN), "");
}

TEST(CheckRange, AnOptionWithoutARangeAcceptsEveryValue) {
  const OptionSpec spec{"raw", "raw", "", std::nullopt};
  EXPECT_EQ(complaint(spec, kNaN), "");
}

}  // namespace
}  // namespace molmesh
