#include "molmesh/geometry/box_index.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <limits>
#include <utility>

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
  const Point q = point(p);
  const auto& rtree = tree_->rtree;
  // Boxes arrive by increasing distance; stop once a box is farther than the best item
  // (with a little slack, so rounding in the box distance never drops an exact tie).
  for (auto it = rtree.qbegin(bgi::nearest(q, static_cast<unsigned>(rtree.size())));
       it != rtree.qend(); ++it) {
    if (bg::comparable_distance(q, it->first) > best_d * (1.0 + 1e-9)) break;
    const int item = it->second;
    const double d = distance_sq(item);
    if (d < best_d || (d == best_d && item < best)) {
      best_d = d;
      best = item;
    }
  }
  if (best < 0) best_d = std::numeric_limits<double>::infinity();
  if (best_distance_sq) *best_distance_sq = best_d;
  return best;
}

}  // namespace molmesh
