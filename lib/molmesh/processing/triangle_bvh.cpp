#include "molmesh/processing/triangle_bvh.hpp"

#include <cmath>
#include <vector>

namespace molmesh {

TriangleBvh::TriangleBvh(const SurfaceMesh& mesh) : mesh_(mesh) {
  std::vector<Box3> boxes;
  boxes.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    Box3 box(mesh.points[t[0]]);
    box.extend(mesh.points[t[1]]);
    box.extend(mesh.points[t[2]]);
    boxes.push_back(box);
  }
  index_ = BoxIndex(boxes);
}

Vec3 TriangleBvh::closest(int triangle, const Vec3& p) const {
  const Triangle& t = mesh_.triangles[static_cast<std::size_t>(triangle)];
  return closest_point_on_triangle(p, mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]]);
}

TriangleBvh::Nearest TriangleBvh::nearest(const Vec3& p) const {
  Nearest best;
  double best_sq = 0.0;
  best.triangle = index_.nearest(
      p, [&](int t) { return (closest(t, p) - p).squaredNorm(); }, &best_sq);
  if (best.triangle < 0) return best;
  best.point = closest(best.triangle, p);
  best.distance = std::sqrt(best_sq);
  return best;
}

}  // namespace molmesh
