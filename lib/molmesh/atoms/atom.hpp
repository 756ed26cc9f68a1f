#pragma once
// The pipeline's input: atom centres and radii (Å), with the identity fields that users
// select atoms by (active sites, waters).
#include <optional>
#include <string>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct Atom {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;  // Å; zero is legal (pdb2pqr hydrogens) and adds nothing to the volume
  double charge = 0.0;  // elementary charges
  // Per-atom blobbyness B_i of Eq. 1 (negative); unset means "use the global value".
  std::optional<double> blobbyness;

  std::string atom_name;
  std::string residue_name;
  int residue_number = 0;
  std::string chain;
  bool hetatm = false;
  std::string element;  // may be empty (PQR carries none)
};

using Atoms = std::vector<Atom>;

}  // namespace molmesh
