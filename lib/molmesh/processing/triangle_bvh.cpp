#include "molmesh/processing/triangle_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace molmesh {

TriangleBvh::TriangleBvh(const SurfaceMesh& mesh) : mesh_(mesh) {
  const auto n = static_cast<std::int32_t>(mesh.triangles.size());
  order_.resize(static_cast<std::size_t>(n));
  std::vector<Vec3> centroids(static_cast<std::size_t>(n));
  for (std::int32_t i = 0; i < n; ++i) {
    order_[i] = i;
    const Triangle& t = mesh.triangles[i];
    centroids[i] = (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]]) / 3.0;
  }
  nodes_.reserve(static_cast<std::size_t>(2 * n / 4 + 2));
  if (n > 0) build(0, n, centroids);
}

std::int32_t TriangleBvh::build(std::int32_t begin, std::int32_t end,
                                std::vector<Vec3>& centroids) {
  const auto index = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  Box3 box;
  Box3 centre_box;
  for (std::int32_t i = begin; i < end; ++i) {
    const Triangle& t = mesh_.triangles[order_[i]];
    for (int v : t) box.extend(mesh_.points[v]);
    centre_box.extend(centroids[order_[i]]);
  }
  nodes_[index].box = box;
  constexpr std::int32_t kLeaf = 4;
  if (end - begin <= kLeaf) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  Eigen::Index axis = 0;
  centre_box.sizes().maxCoeff(&axis);
  const std::int32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::int32_t x, std::int32_t y) {
                     const double cx = centroids[x][axis], cy = centroids[y][axis];
                     return cx < cy || (cx == cy && x < y);
                   });
  build(begin, mid, centroids);  // the left child is always index + 1
  const std::int32_t right = build(mid, end, centroids);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

TriangleBvh::Nearest TriangleBvh::nearest(const Vec3& p) const {
  Nearest best;
  if (nodes_.empty()) return best;
  double best_sq = std::numeric_limits<double>::infinity();
  // Depth-first, nearer child first, pruning boxes farther than the best so far.
  struct Item {
    std::int32_t node;
    double sq;
  };
  std::vector<Item> stack;
  stack.reserve(64);
  stack.push_back({0, nodes_[0].box.squaredExteriorDistance(p)});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.sq >= best_sq) continue;
    const Node& node = nodes_[item.node];
    if (node.count > 0) {
      for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& t = mesh_.triangles[order_[i]];
        const Vec3 q = closest_point_on_triangle(p, mesh_.points[t[0]], mesh_.points[t[1]],
                                                 mesh_.points[t[2]]);
        const double sq = (q - p).squaredNorm();
        if (sq < best_sq || (sq == best_sq && order_[i] < best.triangle)) {
          best_sq = sq;
          best.triangle = order_[i];
          best.point = q;
        }
      }
      continue;
    }
    const std::int32_t left = item.node + 1;
    const std::int32_t right = node.first;
    const double dl = nodes_[left].box.squaredExteriorDistance(p);
    const double dr = nodes_[right].box.squaredExteriorDistance(p);
    if (dl < dr) {
      stack.push_back({right, dr});
      stack.push_back({left, dl});
    } else {
      stack.push_back({left, dl});
      stack.push_back({right, dr});
    }
  }
  best.distance = std::sqrt(best_sq);
  return best;
}

void TriangleBvh::overlapping(const Box3& box, const std::function<void(int)>& visit) const {
  if (nodes_.empty()) return;
  std::vector<std::int32_t> stack{0};
  while (!stack.empty()) {
    const std::int32_t index = stack.back();
    stack.pop_back();
    const Node& node = nodes_[index];
    if (!node.box.intersects(box)) continue;
    if (node.count > 0) {
      for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& t = mesh_.triangles[order_[i]];
        Box3 tb(mesh_.points[t[0]]);
        tb.extend(mesh_.points[t[1]]);
        tb.extend(mesh_.points[t[2]]);
        if (tb.intersects(box)) visit(order_[i]);
      }
      continue;
    }
    stack.push_back(node.first);
    stack.push_back(index + 1);
  }
}

}  // namespace molmesh
