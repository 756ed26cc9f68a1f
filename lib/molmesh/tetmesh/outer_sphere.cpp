#include "molmesh/tetmesh/outer_sphere.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "molmesh/core/error.hpp"

namespace molmesh {

SurfaceMesh icosphere(const Vec3& center, double radius, int subdivisions) {
  if (!(radius > 0.0)) throw Error("outer sphere radius must be positive");
  if (subdivisions < 0 || subdivisions > 7)
    throw Error("outer sphere subdivision level must be in [0, 7], got " +
                std::to_string(subdivisions));
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : p) v.normalize();
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::unordered_map<std::uint64_t, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto lo = static_cast<std::uint64_t>(std::min(a, b));
      const auto hi = static_cast<std::uint64_t>(std::max(a, b));
      const auto [it, inserted] = midpoint.try_emplace(lo << 32 | hi, static_cast<int>(p.size()));
      if (inserted) p.push_back((p[a] + p[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> next;
    next.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  SurfaceMesh mesh;
  mesh.points.reserve(p.size());
  for (const auto& v : p) mesh.points.push_back(center + radius * v);
  mesh.triangles = std::move(f);
  return mesh;
}

}  // namespace molmesh
