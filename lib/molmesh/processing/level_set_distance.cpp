#include "molmesh/processing/level_set_distance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace molmesh {

double level_set_distance(const ScalarField& field, double level, const Vec3& x) {
  Vec3 g;
  const double f = field(x, &g) - level;
  if (f == 0.0) return 0.0;
  const double norm = g.norm();
  return norm > 0.0 ? std::abs(f) / norm : std::numeric_limits<double>::infinity();
}

namespace {

// Mean and max of `values` where `used`, summed in index order.
void mean_and_max(const std::vector<double>& values, const std::vector<char>& used, double& mean,
                  double& max) {
  double sum = 0.0;
  std::size_t count = 0;
  max = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!used[i]) continue;
    sum += values[i];
    max = std::max(max, values[i]);
    ++count;
  }
  mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace

LevelSetDistance measure_level_set_distance(const SurfaceMesh& mesh, const ScalarField& field,
                                            double level) {
  std::vector<char> referenced(mesh.points.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) referenced[static_cast<std::size_t>(v)] = 1;
  std::vector<double> vertex(mesh.points.size(), 0.0);
  std::vector<double> centroid(mesh.triangles.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.points.size(), 512),
                    [&](const auto& r) {
                      for (std::size_t v = r.begin(); v != r.end(); ++v)
                        if (referenced[v])
                          vertex[v] = level_set_distance(field, level, mesh.points[v]);
                    });
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 512), [&](const auto& r) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const Triangle& tri = mesh.triangles[t];
          const Vec3 c = (mesh.points[tri[0]] + mesh.points[tri[1]] + mesh.points[tri[2]]) / 3.0;
          centroid[t] = level_set_distance(field, level, c);
        }
      });
  LevelSetDistance d;
  mean_and_max(vertex, referenced, d.vertex_mean, d.vertex_max);
  mean_and_max(centroid, std::vector<char>(centroid.size(), 1), d.centroid_mean, d.centroid_max);
  return d;
}

}  // namespace molmesh
