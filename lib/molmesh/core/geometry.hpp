#pragma once
// Small geometric vocabulary shared by every stage. Positions are in Ångström.
#include <Eigen/Core>
// Vec3::cross and friends are declared in Core but defined in Geometry; without it every
// user of cross() fails to link.
#include <Eigen/Geometry>
#include <array>

namespace molmesh {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;     // vertex indices, counter-clockwise seen from outside
using Tetrahedron = std::array<int, 4>;  // vertex indices, positive orientation

// A ball in space: keep-spheres that forbid coarsening, active-site spheres for markers.
struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  bool contains(const Vec3& p) const { return (p - center).squaredNorm() <= radius * radius; }
};

}  // namespace molmesh
