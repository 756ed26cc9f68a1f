#include "option_spelling.hpp"

#include "molmesh/core/error.hpp"

namespace molmesh::cli {

std::string with_cli_flags(std::string_view message) {
  // Library option (its struct member) -> flag; names without a flag stay backquoted.
  static const OptionSpellings kFlags{
      {"level", "--level"},
      {"max_levels", "--levels"},
      {"max_memory_bytes", "--max-memory"},
      {"max_radius_edge_ratio", "--max-radius-edge"},
      {"max_volume", "--max-volume"},
      {"min_dihedral_deg", "--min-dihedral"},
      {"outer_radius", "--outer-radius"},
      {"outer_sphere_subdivisions", "--sphere-subdivisions"},
      {"radii_file", "--radii"},
      {"rings", "--rings"},
      {"size_factor", "--size-factor"},
      {"spacing", "--spacing"},
      {"sphere_ratio", "--sphere-ratio"},
      {"t0", "--t0"},
      {"tetgen_switches", "--tetgen-switches"},
  };
  return spell_option_names(message, kFlags);
}

}  // namespace molmesh::cli
