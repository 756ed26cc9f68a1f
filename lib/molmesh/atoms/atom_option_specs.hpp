#pragma once
// The names and help texts of the AtomReadOptions (io/read_atoms.hpp) the front ends expose
// (the CLI's --radii, --hetatm/--no-hetatm and --waters of `surface`, `tetmesh` and
// `hierarchy`, the keywords of molmesh.read_atoms), written once here. Defaults are
// AtomReadOptions' own.
#include <array>

#include "molmesh/core/option_spec.hpp"

namespace molmesh {

struct AtomOptionSpecs {
  OptionSpec radii;
  OptionSpec hetatm;
  OptionSpec waters;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 3> all() const { return {&radii, &hetatm, &waters}; }
};

inline constexpr AtomOptionSpecs kAtomOptionSpecs{
    .radii = {"radii", "radii_file",
              "Radius table (docs/formats.md) overriding the built-in radii; for PQR input it "
              "replaces the file's radii wherever it has an entry",
              std::nullopt},
    .hetatm = {"hetatm", "include_hetatm",
               "Include HETATM records (ligands, ions), as by default; off: leave them out",
               std::nullopt, "--hetatm,!--no-hetatm"},
    .waters = {"waters", "include_waters",
               "Include water molecules (HOH, WAT, ...), which are dropped by default",
               std::nullopt},
};

}  // namespace molmesh
