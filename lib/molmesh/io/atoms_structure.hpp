#pragma once
// PDB and PDBx/mmCIF coordinate files, parsed with gemmi. These carry no radii: the atoms
// come back with radius 0 and read_atoms assigns radii from a table. The first model is
// read; of alternative conformations only the first is kept.
#include <cstddef>
#include <string>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"

namespace molmesh {

struct StructureAtoms {
  Atoms atoms;
  std::vector<std::size_t> lines;  // source line per atom (PDB), or 0 when unknown (mmCIF)
};

// `contents` is the (already decompressed) file text; `name` names it in errors.
StructureAtoms parse_structure(const std::string& contents, const std::string& name, bool mmcif,
                               const Reporter& reporter = {});

}  // namespace molmesh
