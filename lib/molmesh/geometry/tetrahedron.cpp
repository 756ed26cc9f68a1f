#include "molmesh/geometry/tetrahedron.hpp"

#include <Eigen/LU>

namespace molmesh {

Eigen::Vector4d tet_barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                const Vec3& p) {
  Eigen::Matrix3d m;
  m.col(0) = b - a;
  m.col(1) = c - a;
  m.col(2) = d - a;
  const Eigen::Vector3d x = m.partialPivLu().solve(p - a);
  return {1.0 - x.sum(), x[0], x[1], x[2]};
}

}  // namespace molmesh
