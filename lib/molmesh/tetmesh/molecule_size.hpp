#pragma once
// The molecule's centre and size as GAMer defines them (§2.4): the mean of the atom
// centres, and the largest distance of a centre from it. Sizes the outer sphere.
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct MoleculeExtent {
  Vec3 centroid = Vec3::Zero();
  double size = 0.0;  // Å; 0 for a single atom
};

// Throws molmesh::Error for an empty list.
MoleculeExtent molecule_extent(const Atoms& atoms);
// Same definition over points (surface-file inputs, where there are no atoms).
MoleculeExtent molecule_extent(const std::vector<Vec3>& points);

}  // namespace molmesh
