#include "molmesh/processing/project_vertices.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

namespace molmesh {

std::size_t project_vertices(SurfaceMesh& mesh, const std::function<Vec3(const Vec3&)>& project) {
  if (!project) return 0;
  const std::size_t n = mesh.points.size();
  std::vector<Vec3> target(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) target[v] = project(mesh.points[v]);
  });
  // Triangles around each vertex (compressed rows).
  std::vector<std::size_t> start(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) ++start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> around(start.back());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int v : mesh.triangles[t]) around[fill[static_cast<std::size_t>(v)]++] = t;
  }
  const auto normal = [&](const Triangle& t) {
    return Vec3(
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]));
  };
  std::size_t kept = 0;
  std::vector<Vec3> before;
  for (std::size_t v = 0; v < n; ++v) {
    if (target[v] == mesh.points[v] || !target[v].allFinite()) continue;
    before.clear();
    for (std::size_t a = start[v]; a < start[v + 1]; ++a)
      before.push_back(normal(mesh.triangles[around[a]]));
    const Vec3 old = mesh.points[v];
    mesh.points[v] = target[v];
    bool turned = false;
    for (std::size_t a = start[v]; a < start[v + 1] && !turned; ++a)
      turned = !(normal(mesh.triangles[around[a]]).dot(before[a - start[v]]) > 0.0);
    if (turned) {
      mesh.points[v] = old;
      ++kept;
    }
  }
  return kept;
}

}  // namespace molmesh
