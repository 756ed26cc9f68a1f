#pragma once
// Membership in a union of spheres: the one keep-sphere and active-site test. Not in
// core/geometry.hpp, which must stay C++17 (the gemmi reader includes it; lib/CMakeLists.txt).
#include <span>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Whether p lies in the union of the spheres (keep-spheres, active sites).
inline bool in_any(std::span<const Sphere> spheres, const Vec3& p) {
  for (const Sphere& s : spheres)
    if (s.contains(p)) return true;
  return false;
}

}  // namespace molmesh
