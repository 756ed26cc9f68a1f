#pragma once
// Reads atoms from any supported molecule file, chosen by extension: .pqr (radii and
// charges from the file), .pdb/.ent and .cif/.mmcif (radii from a table), each optionally
// gzipped (.gz). The result is validated: finite coordinates, non-negative radii, at
// least one atom. Formats and the radius table are described in docs/formats.md.
#include <filesystem>
#include <optional>
#include <string_view>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"

namespace molmesh {

struct AtomReadOptions {
  // A user radius table (docs/formats.md) that overrides the built-in one. For PQR files,
  // whose radii come with the file, it replaces the file's radii wherever it has an entry.
  std::optional<std::filesystem::path> radii_file;
  bool include_hetatm = true;
  bool include_waters = false;  // HOH, WAT, H2O, DOD, TIP3, SOL...
  bool include_hydrogens = true;
};

// Throws InputError (file:line: what) for unreadable, malformed or empty input. Warns once
// through `reporter` about zero radii ("N atoms have zero radius ...") and skipped records.
Atoms read_atoms(const std::filesystem::path& path, const AtomReadOptions& options = {},
                 const Reporter& reporter = {});

// True for residue names that denote water molecules.
bool is_water_residue(std::string_view residue_name);

}  // namespace molmesh
