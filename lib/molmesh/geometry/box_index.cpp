#include "molmesh/geometry/box_index.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace molmesh {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Entry = std::pair<Box, int>;

struct BoxIndex::Tree {
  bgi::rtree<Entry, bgi::rstar<16>> rtree;
};

namespace {

Point point(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }

}  // namespace

BoxIndex::BoxIndex() : tree_(std::make_unique<Tree>()) {}

BoxIndex::BoxIndex(const std::vector<Box3>& boxes) : tree_(std::make_unique<Tree>()) {
  std::vector<Entry> entries;
  entries.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    entries.emplace_back(Box(point(boxes[i].min()), point(boxes[i].max())), static_cast<int>(i));
  }
  // The range constructor bulk-loads (packing): faster to build and to query than inserts.
  tree_->rtree = bgi::rtree<Entry, bgi::rstar<16>>(entries.begin(), entries.end());
}

BoxIndex::~BoxIndex() = default;
BoxIndex::BoxIndex(BoxIndex&&) noexcept = default;
BoxIndex& BoxIndex::operator=(BoxIndex&&) noexcept = default;

bool BoxIndex::empty() const { return tree_->rtree.empty(); }

void BoxIndex::containing(const Vec3& p, const std::function<void(int)>& visit) const {
  for (auto it = tree_->rtree.qbegin(bgi::intersects(point(p))); it != tree_->rtree.qend(); ++it)
    visit(it->second);
}

void BoxIndex::overlapping(const Box3& box, const std::function<void(int)>& visit) const {
  const Box probe(point(box.min()), point(box.max()));
  for (auto it = tree_->rtree.qbegin(bgi::intersects(probe)); it != tree_->rtree.qend(); ++it)
    visit(it->second);
}

int BoxIndex::nearest(const Vec3& p, const std::function<double(int)>& distance_sq,
                      double* best_distance_sq) const {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  const auto consider = [&](int item) {
    const double d = distance_sq(item);
    if (d < best_d || (d == best_d && item < best)) {
      best_d = d;
      best = item;
    }
  };
  const Point q = point(p);
  const auto& rtree = tree_->rtree;
  // A first bound from the few boxes nearest to p, then every box within that distance
  // (a little slack, so rounding in box distances never drops an exact tie). The exact
  // minimum lies among them, since an item is never nearer than its box.
  constexpr unsigned kFirst = 8;
  std::vector<int> seen;
  for (auto it = rtree.qbegin(bgi::nearest(q, kFirst)); it != rtree.qend(); ++it) {
    consider(it->second);
    seen.push_back(it->second);
  }
  if (best >= 0) {
    const double r = std::sqrt(best_d) * (1.0 + 1e-9) + 1e-300;
    const Box probe(Point(p.x() - r, p.y() - r, p.z() - r), Point(p.x() + r, p.y() + r, p.z() + r));
    for (auto it = rtree.qbegin(bgi::intersects(probe)); it != rtree.qend(); ++it) {
      if (std::find(seen.begin(), seen.end(), it->second) != seen.end()) continue;
      if (bg::comparable_distance(q, it->first) > best_d * (1.0 + 1e-9)) continue;
      consider(it->second);
    }
  } else {
    // The nearest boxes hold only excluded items: fall back to all of them.
    for (const Entry& e : rtree) consider(e.second);
  }
  if (best < 0) best_d = std::numeric_limits<double>::infinity();
  if (best_distance_sq) *best_distance_sq = best_d;
  return best;
}

}  // namespace molmesh
