#pragma once
// Atoms for tests that build their input by hand rather than reading a molecule.
#include "molmesh/atoms/atom.hpp"

namespace molmesh::testing {

// An atom at (x, y, z) of radius r (Å), with no charge and the global blobbyness.
inline Atom make_atom(double x, double y, double z, double r) {
  Atom a;
  a.center = Vec3(x, y, z);
  a.radius = r;
  return a;
}

}  // namespace molmesh::testing
