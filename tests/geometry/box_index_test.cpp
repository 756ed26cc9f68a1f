// The kernel's box index against brute force: containing / overlapping give exactly the
// boxes that qualify, nearest gives the exact minimum with ties to the lower index.
#include "molmesh/geometry/box_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace molmesh {
namespace {

std::vector<Box3> random_boxes(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-10, 10), s(0, 2);
  std::vector<Box3> boxes;
  for (int i = 0; i < n; ++i) {
    const Vec3 lo(u(rng), u(rng), u(rng));
    boxes.emplace_back(lo, lo + Vec3(s(rng), s(rng), s(rng)));
  }
  return boxes;
}

TEST(BoxIndex, ContainingAndOverlappingMatchBruteForce) {
  std::mt19937 rng(5);
  const auto boxes = random_boxes(500, rng);
  const BoxIndex index(boxes);
  std::uniform_real_distribution<double> u(-11, 11);
  for (int q = 0; q < 200; ++q) {
    const Vec3 p(u(rng), u(rng), u(rng));
    std::vector<int> got, want;
    index.containing(p, [&](int i) { got.push_back(i); });
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (boxes[static_cast<std::size_t>(i)].contains(p)) want.push_back(i);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);

    const Box3 probe(p, p + Vec3(1.5, 0.5, 1.0));
    got.clear();
    want.clear();
    index.overlapping(probe, [&](int i) { got.push_back(i); });
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (boxes[static_cast<std::size_t>(i)].intersects(probe)) want.push_back(i);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
  }
}

TEST(BoxIndex, NearestIsExactWithTiesToTheLowerIndex) {
  // Points as degenerate boxes, each present twice: every nearest query has a tie.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-10, 10);
  std::vector<Vec3> points;
  for (int i = 0; i < 300; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  std::vector<Box3> boxes;
  for (int copy = 0; copy < 2; ++copy)
    for (const Vec3& p : points) boxes.emplace_back(p, p);
  const BoxIndex index(boxes);
  for (int q = 0; q < 200; ++q) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const auto distance = [&](int i) {
      return (boxes[static_cast<std::size_t>(i)].min() - p).squaredNorm();
    };
    int want = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
      if (distance(i) < best) {
        best = distance(i);
        want = i;
      }
    }
    double got_d = 0.0;
    EXPECT_EQ(index.nearest(p, distance, &got_d), want);
    EXPECT_EQ(got_d, best);
  }
  // Items excluded by an infinite distance are skipped; none left gives -1.
  EXPECT_EQ(
      index.nearest(Vec3::Zero(), [](int) { return std::numeric_limits<double>::infinity(); }), -1);
  EXPECT_EQ(BoxIndex().nearest(Vec3::Zero(), [](int) { return 0.0; }), -1);
}

}  // namespace
}  // namespace molmesh
