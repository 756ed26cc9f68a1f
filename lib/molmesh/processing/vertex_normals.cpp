#include "molmesh/processing/vertex_normals.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <cmath>

#include "molmesh/processing/vertex_rings.hpp"

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
  const VertexAdjacency faces = vertex_faces(mesh);
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  // Per vertex, summed over its faces in increasing index: parallel and yet the same bits
  // whatever the thread count.
  tbb::parallel_for(std::size_t{0}, mesh.points.size(), [&](std::size_t v) {
    Vec3 n = Vec3::Zero();
    const Vec3& p = mesh.points[v];
    for (std::int32_t f : faces.of(v)) {
      const Triangle& t = mesh.triangles[f];
      const int k = t[0] == static_cast<int>(v) ? 0 : (t[1] == static_cast<int>(v) ? 1 : 2);
      const Vec3 a = mesh.points[t[(k + 1) % 3]] - p;
      const Vec3 b = mesh.points[t[(k + 2) % 3]] - p;
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      n += angle * fn[f];
    }
    const double len = n.norm();
    normals[v] = len > 0 ? Vec3(n / len) : Vec3::Zero();
  });
  return normals;
}

}  // namespace molmesh
