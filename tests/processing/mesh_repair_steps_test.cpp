// The steps of mesh repair on their own (mesh_repair_steps.hpp). merge_map hashes grid cells
// of the vertex coordinates: far from the origin the cell indices reach 1e12 and more, where
// a signed hash overflowed (undefined behaviour, which UBSan halts on in the sanitizer leg;
// issue 18, finding 8), and beyond 1e18 they are clamped.
#include "molmesh/processing/mesh_repair_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"

namespace molmesh::repair_steps {
namespace {

TEST(MergeMap, WeldsDuplicatesFarFromTheOriginAndKeepsNeighboursApart) {
  for (const double far : {1e9, -1e9, 1e15, -1e15, 1e300}) {
    const Vec3 p(far, -far, far);
    // The next representable neighbours along x (spacing 0.125 at 1e15): distinct points
    // farther apart than the tolerance only where doubles resolve them.
    const Vec3 q = p + Vec3(std::abs(far) * 1e-12, 0.0, 0.0);
    const std::vector<Vec3> points{p, q, p, q, p};
    const std::vector<int> rep = merge_map(points, 1e-3);
    ASSERT_EQ(rep.size(), points.size()) << far;
    EXPECT_EQ(rep[0], 0) << far;
    EXPECT_EQ(rep[2], 0) << far;
    EXPECT_EQ(rep[4], 0) << far;
    const int expected_q = (q - p).norm() <= 1e-3 ? 0 : 1;
    EXPECT_EQ(rep[1], expected_q) << far;
    EXPECT_EQ(rep[3], expected_q) << far;
  }
}

TEST(MergeMap, ExactMergeWithoutToleranceAndNonFiniteCoordinatesRefused) {
  const std::vector<Vec3> points{Vec3(1e12, 2e12, -3e12), Vec3(1e12, 2e12, -3e12),
                                 Vec3(1e12, 2e12, -3e12 + 1.0)};
  EXPECT_EQ(merge_map(points, 0.0), (std::vector<int>{0, 0, 2}));
  const std::vector<Vec3> bad{Vec3(0, 0, 0), Vec3(0, std::nan(""), 0)};
  EXPECT_THROW(merge_map(bad, 1e-3), Error);
}

}  // namespace
}  // namespace molmesh::repair_steps
