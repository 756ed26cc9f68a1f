#pragma once
// The library names options by their members in its options structs (core/error.hpp);
// the command line says the flag the user typed. One table for every command.
#include <string>
#include <string_view>

namespace molmesh::cli {

// `message` with every backquoted library option name the CLI has a flag for replaced by
// that flag (`size_factor` -> --size-factor, `max_levels` -> --levels).
std::string with_cli_flags(std::string_view message);

// The flag of an option the library names by its keyword (core/option_spec.hpp):
// "max_radius_edge" -> "--max-radius-edge".
std::string cli_flag(std::string_view name);

}  // namespace molmesh::cli
