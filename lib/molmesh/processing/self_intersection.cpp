#include "molmesh/processing/self_intersection.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/processing/triangle_bvh.hpp"

namespace molmesh {

std::vector<std::pair<int, int>> self_intersections(const SurfaceMesh& mesh) {
  const TriangleBvh bvh(mesh);
  const std::size_t n = mesh.triangles.size();
  std::vector<std::vector<int>> hits(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const Triangle& s = mesh.triangles[i];
    Box3 box(mesh.points[s[0]]);
    box.extend(mesh.points[s[1]]);
    box.extend(mesh.points[s[2]]);
    bvh.overlapping(box, [&](int j) {
      if (static_cast<std::size_t>(j) <= i) return;
      if (triangles_intersect(mesh.points, s, mesh.triangles[j], SegmentContact::kClosed))
        hits[i].push_back(j);
    });
    std::sort(hits[i].begin(), hits[i].end());
  });
  std::vector<std::pair<int, int>> result;
  for (std::size_t i = 0; i < n; ++i) {
    for (int j : hits[i]) result.emplace_back(static_cast<int>(i), j);
  }
  return result;
}

}  // namespace molmesh
