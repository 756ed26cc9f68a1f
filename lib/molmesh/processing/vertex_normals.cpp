#include "molmesh/processing/vertex_normals.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <cmath>

namespace molmesh {

std::vector<Vec3> face_normals(const SurfaceMesh& mesh) {
  std::vector<Vec3> normals(mesh.triangles.size());
  tbb::parallel_for(std::size_t{0}, mesh.triangles.size(), [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n =
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]);
    const double len = n.norm();
    normals[f] = len > 0 ? Vec3(n / len) : Vec3::Zero();
  });
  return normals;
}

std::vector<Vec3> vertex_normals(const SurfaceMesh& mesh) {
  const std::vector<Vec3> fn = face_normals(mesh);
  // Accumulated sequentially over faces so the sum order (and thus the result bits) is
  // fixed whatever the thread count.
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.points[t[k]];
      const Vec3 a = mesh.points[t[(k + 1) % 3]] - p;
      const Vec3 b = mesh.points[t[(k + 2) % 3]] - p;
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      normals[t[k]] += angle * fn[f];
    }
  }
  for (Vec3& n : normals) {
    const double len = n.norm();
    n = len > 0 ? Vec3(n / len) : Vec3::Zero();
  }
  return normals;
}

}  // namespace molmesh
