#pragma once
// Small geometric vocabulary shared by every stage. Positions are in Ångström.
#include <Eigen/Core>
#include <array>

namespace molmesh {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;     // vertex indices, counter-clockwise seen from outside
using Tetrahedron = std::array<int, 4>;  // vertex indices, positive orientation

}  // namespace molmesh
