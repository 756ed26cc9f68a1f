#pragma once
// A bounding-volume hierarchy of axis-aligned boxes, for point location in tetrahedral
// meshes and nearest-primitive queries. A uniform grid would not do: exterior meshes span
// several orders of magnitude in element size (a molecule inside a far outer sphere).
// Queries are read-only and may run concurrently.
#include <Eigen/Geometry>
#include <limits>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

using Box3 = Eigen::AlignedBox3d;

class AabbTree {
 public:
  AabbTree() = default;
  // items are identified by their index in `boxes`.
  explicit AabbTree(const std::vector<Box3>& boxes);

  // Calls visit(item) for every item whose box contains p (boxes are used as given).
  template <class Visit>
  void for_each_containing(const Vec3& p, Visit&& visit) const {
    if (nodes_.empty()) return;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!node.box.contains(p)) continue;
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i) visit(items_[static_cast<std::size_t>(i)]);
      } else {
        stack[top++] = node.left;
        stack[top++] = node.right;
      }
    }
  }

  // Item minimising distance_sq(item) (a squared distance from p that is never below the
  // squared distance from p to the item's box); ties go to the lower item index, so the
  // result does not depend on traversal order. Returns -1 for an empty tree.
  template <class DistanceSq>
  int nearest(const Vec3& p, DistanceSq&& distance_sq, double* best_out = nullptr) const {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    if (!nodes_.empty()) {
      int stack[128];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
        if (node.box.squaredExteriorDistance(p) > best_d) continue;
        if (node.left < 0) {
          for (int i = node.begin; i < node.end; ++i) {
            const int item = items_[static_cast<std::size_t>(i)];
            const double d = distance_sq(item);
            if (d < best_d || (d == best_d && item < best)) {
              best_d = d;
              best = item;
            }
          }
        } else {
          // Visit the nearer child first (pushed last) so pruning works early.
          const auto& l = nodes_[static_cast<std::size_t>(node.left)].box;
          const auto& r = nodes_[static_cast<std::size_t>(node.right)].box;
          if (l.squaredExteriorDistance(p) <= r.squaredExteriorDistance(p)) {
            stack[top++] = node.right;
            stack[top++] = node.left;
          } else {
            stack[top++] = node.left;
            stack[top++] = node.right;
          }
        }
      }
    }
    if (best_out) *best_out = best_d;
    return best;
  }

  bool empty() const { return nodes_.empty(); }

 private:
  struct Node {
    Box3 box;
    int left = -1, right = -1;  // children; -1 in leaves
    int begin = 0, end = 0;     // leaf item range in items_
  };
  int build(const std::vector<Box3>& boxes, std::vector<Vec3>& centres, int begin, int end,
            int depth);
  std::vector<Node> nodes_;
  std::vector<int> items_;
};

}  // namespace molmesh
