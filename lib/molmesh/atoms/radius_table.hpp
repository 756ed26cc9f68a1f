#pragma once
// Atomic radii for files that carry none (PDB, mmCIF). The built-in table is by element:
// Bondi (1964) van der Waals radii, completed for main-group elements Bondi lacks by
// Mantina et al. (2009); docs/formats.md lists the values and the reasons. Users override
// it with a table of per-residue/atom-name and per-element entries.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "molmesh/atoms/atom.hpp"

namespace molmesh {

struct RadiusTable {
  // Keys are upper case. "*" is a wildcard for the residue or the atom name.
  std::map<std::pair<std::string, std::string>, double> by_residue_atom;
  std::map<std::string, double> by_element;  // "*" = any element
  std::string source;                        // for messages: file name or "built-in"

  // The most specific match: residue+atom, *+atom, residue+*, element, * (any element).
  std::optional<double> lookup(const Atom& atom) const;
  bool empty() const { return by_residue_atom.empty() && by_element.empty(); }
};

// Bondi (1964) with Mantina et al. (2009) completions; element symbols in upper case.
const RadiusTable& builtin_radius_table();

// Upper-cased copy (element symbols, residue and atom names are compared this way).
std::string to_upper(std::string_view text);

}  // namespace molmesh
