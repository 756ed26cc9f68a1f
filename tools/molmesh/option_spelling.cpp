#include "option_spelling.hpp"

#include "molmesh/core/error.hpp"
#include "molmesh/pipeline/all_option_specs.hpp"

namespace molmesh::cli {

std::string cli_flag(std::string_view name) {
  std::string flag = "--" + std::string(name);
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

std::string with_cli_flags(std::string_view message) {
  // Library option (its struct member) -> flag; names without a flag stay backquoted.
  static const OptionSpellings kFlags = [] {
    OptionSpellings flags{
        {"level", "--level"}, {"max_levels", "--levels"}, {"max_memory_bytes", "--max-memory"},
        {"rings", "--rings"}, {"spacing", "--spacing"},   {"t0", "--t0"},
    };
    // The library's option tables; the first flag of a member wins (`t0` is --t0, not
    // surface's --coarsen), and negated flags (--no-flips) are not a member's spelling.
    for (const OptionSpec* spec : all_option_specs())
      if (spec->cli_names.empty()) flags.emplace(std::string(spec->member), cli_flag(spec->name));
    return flags;
  }();
  return spell_option_names(message, kFlags);
}

}  // namespace molmesh::cli
