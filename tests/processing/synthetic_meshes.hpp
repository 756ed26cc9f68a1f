#pragma once
// Small closed meshes built in code for the processing tests: a finely gridded box (flat
// faces meeting at sharp 90° ridges); the icosphere is the library's (tetmesh/outer_sphere).
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"  // icosphere

namespace molmesh::test {

// Axis-aligned box [0,size]^3 with every face an n×n grid of squares split into two
// triangles, alternating the diagonal so valences stay near 6. Outward orientation.
inline SurfaceMesh gridded_box(int n, double size) {
  SurfaceMesh m;
  std::map<std::tuple<long, long, long>, int> ids;
  auto vertex = [&](const Vec3& p) {
    const auto key = std::make_tuple(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6),
                                     std::lround(p.z() * 1e6));
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    m.points.push_back(p);
    const int id = static_cast<int>(m.points.size()) - 1;
    ids.emplace(key, id);
    return id;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = side ? 1.0 : -1.0;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            Vec3 p = Vec3::Zero();
            p[axis] = side * size;
            p[u] = size * a / n;
            p[w] = size * b / n;
            return vertex(p);
          };
          const int p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
          std::array<Triangle, 2> tris =
              ((i + j) % 2 == 0)
                  ? std::array<Triangle, 2>{Triangle{p00, p10, p11}, Triangle{p00, p11, p01}}
                  : std::array<Triangle, 2>{Triangle{p00, p10, p01}, Triangle{p10, p11, p01}};
          for (Triangle tri : tris) {
            const Vec3 nrm =
                (m.points[tri[1]] - m.points[tri[0]]).cross(m.points[tri[2]] - m.points[tri[0]]);
            if (nrm.dot(normal) < 0) std::swap(tri[1], tri[2]);
            m.triangles.push_back(tri);
          }
        }
      }
    }
  }
  return m;
}

inline int euler_characteristic(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const Triangle& t : m.triangles) {
    for (int i = 0; i < 3; ++i) edges[std::minmax(t[i], t[(i + 1) % 3])]++;
  }
  return static_cast<int>(m.points.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(m.triangles.size());
}

}  // namespace molmesh::test
