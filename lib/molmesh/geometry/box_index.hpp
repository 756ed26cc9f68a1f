#pragma once
// The geometry kernel's one spatial index (docs/architecture.md): axis-aligned boxes of
// items (cells, faces, points) in a Boost.Geometry R-tree, bulk-loaded, with the queries the
// stages need. Built once, read-only afterwards, so queries may run concurrently. Query
// results never depend on the tree's internal order: visitors see a set, and nearest()
// breaks ties by the lower item index.
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

using Box3 = Eigen::AlignedBox3d;

class BoxIndex {
 public:
  BoxIndex();
  // Items are identified by their index in `boxes`.
  explicit BoxIndex(const std::vector<Box3>& boxes);
  ~BoxIndex();
  BoxIndex(BoxIndex&&) noexcept;
  BoxIndex& operator=(BoxIndex&&) noexcept;

  bool empty() const;

  // Calls visit(item) for every item whose (closed) box contains p.
  void containing(const Vec3& p, const std::function<void(int)>& visit) const;
  // Calls visit(item) for every item whose (closed) box meets `box`.
  void overlapping(const Box3& box, const std::function<void(int)>& visit) const;
  // The item minimising distance_sq(item), a squared distance from p that is never below
  // the squared distance from p to the item's box (infinity excludes an item); ties go to
  // the lower index. Returns -1 when no item has a finite distance.
  int nearest(const Vec3& p, const std::function<double(int)>& distance_sq,
              double* best_distance_sq = nullptr) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace molmesh
