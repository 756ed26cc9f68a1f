// HierarchyOptions::validate(): the T0 list, the size growth per level and the processing and
// volume options of every level are checked by the library, whichever front end set them,
// naming the struct member (core/error.hpp); the CLI's parse-time check of --size-growth
// uses the same bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/hierarchy/build_hierarchy.hpp"

namespace molmesh {
namespace {

std::string message_of(const HierarchyOptions& options) {
  try {
    options.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(HierarchyOptions, SizeGrowthOutsideItsRangeNamesTheOption) {
  HierarchyOptions options;
  EXPECT_EQ(message_of(options), "");
  for (double growth : {kMinSizeGrowth, 2.0, kMaxSizeGrowth}) {
    options.size_growth = growth;
    EXPECT_EQ(message_of(options), "") << growth;
  }
  for (double growth :
       {0.999, std::nextafter(kMaxSizeGrowth, 20.0), 20.0, std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity()}) {
    options.size_growth = growth;
    const std::string message = message_of(options);
    EXPECT_NE(message.find("`size_growth`"), std::string::npos) << growth << ": " << message;
    EXPECT_NE(message.find("[1, 10]"), std::string::npos) << message;
  }
}

TEST(HierarchyOptions, T0MustBeGivenNonNegativeAndNonDecreasing) {
  HierarchyOptions options;
  options.t0 = {};
  EXPECT_NE(message_of(options).find("`t0`"), std::string::npos);
  options.t0 = {0.1, -0.2};
  EXPECT_NE(message_of(options).find("`t0`"), std::string::npos);
  options.t0 = {0.3, 0.2};
  EXPECT_NE(message_of(options).find("must not decrease"), std::string::npos);
  options.t0 = {0.2, 0.2, 0.5};
  EXPECT_EQ(message_of(options), "");
}

// A processing or volume option out of range is refused by validate() itself, so
// build_hierarchy() stops before level 0's surface is processed, not when a level reaches it.
TEST(HierarchyOptions, ProcessingAndVolumeOptionsAreCheckedUpFront) {
  HierarchyOptions options;
  options.processing.rings = 0;
  EXPECT_NE(message_of(options).find("`rings`"), std::string::npos) << message_of(options);
  options.processing.rings = 2;
  options.processing.t0 = {-1.0};  // replaced by each level's own T0: not an error
  EXPECT_EQ(message_of(options), "");
  options.tetmesh.min_dihedral_deg = kMaxMinDihedralDeg + 1.0;
  EXPECT_NE(message_of(options).find("`min_dihedral_deg`"), std::string::npos)
      << message_of(options);
}

}  // namespace
}  // namespace molmesh
