#include "molmesh/processing/dislocation.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "molmesh/processing/triangle_bvh.hpp"

namespace molmesh {

std::vector<double> vertex_dislocations(const SurfaceMesh& mesh, const SurfaceMesh& reference) {
  std::vector<char> used(mesh.points.size(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) used[v] = 1;
  }
  std::vector<double> distance(mesh.points.size(), 0.0);
  if (reference.triangles.empty()) return distance;
  const TriangleBvh bvh(reference);
  tbb::parallel_for(std::size_t{0}, mesh.points.size(), [&](std::size_t v) {
    if (used[v]) distance[v] = bvh.nearest(mesh.points[v]).distance;
  });
  return distance;
}

Dislocation measure_dislocation(const SurfaceMesh& mesh, const SurfaceMesh& reference) {
  const std::vector<double> distance = vertex_dislocations(mesh, reference);
  std::vector<char> used(mesh.points.size(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) used[v] = 1;
  }
  Dislocation result;
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t v = 0; v < distance.size(); ++v) {
    if (!used[v]) continue;
    sum += distance[v];
    result.max = std::max(result.max, distance[v]);
    ++count;
  }
  result.mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
  return result;
}

}  // namespace molmesh
