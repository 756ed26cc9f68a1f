#include "molmesh/hierarchy/aabb_tree.hpp"

#include <algorithm>
#include <numeric>

namespace molmesh {
namespace {
constexpr int kLeafSize = 4;
// Depth is bounded so the fixed query stacks (128 entries) never overflow: a median split
// halves the item count, so 60 levels cover any realistic mesh.
constexpr int kMaxDepth = 60;
}  // namespace

AabbTree::AabbTree(const std::vector<Box3>& boxes) {
  if (boxes.empty()) return;
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0);
  std::vector<Vec3> centres(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) centres[i] = boxes[i].center();
  nodes_.reserve(2 * boxes.size() / kLeafSize + 2);
  build(boxes, centres, 0, static_cast<int>(boxes.size()), 0);
}

int AabbTree::build(const std::vector<Box3>& boxes, std::vector<Vec3>& centres, int begin, int end,
                    int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Box3 box;
  Box3 centre_box;
  for (int i = begin; i < end; ++i) {
    const int item = items_[static_cast<std::size_t>(i)];
    box.extend(boxes[static_cast<std::size_t>(item)]);
    centre_box.extend(centres[static_cast<std::size_t>(item)]);
  }
  nodes_[static_cast<std::size_t>(index)].box = box;
  if (end - begin <= kLeafSize || depth >= kMaxDepth) {
    nodes_[static_cast<std::size_t>(index)].begin = begin;
    nodes_[static_cast<std::size_t>(index)].end = end;
    return index;
  }
  int axis = 0;
  centre_box.sizes().maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  // Ties broken by item index, so the tree (and every query result) is deterministic.
  std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end,
                   [&](int a, int b) {
                     const double ca = centres[static_cast<std::size_t>(a)][axis];
                     const double cb = centres[static_cast<std::size_t>(b)][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = build(boxes, centres, begin, middle, depth + 1);
  const int right = build(boxes, centres, middle, end, depth + 1);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

}  // namespace molmesh
