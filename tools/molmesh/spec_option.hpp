#pragma once
// An option bound with the library's name, help text and range (core/option_spec.hpp), so
// the command line and Python say the same about it.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>

#include "molmesh/core/option_spec.hpp"
#include "option_checks.hpp"
#include "option_spelling.hpp"

namespace molmesh::cli {

// The spec's flag names: its cli_names, or "--" + name with '-' for '_'.
inline std::string cli_names(const OptionSpec& spec) {
  return spec.cli_names.empty() ? cli_flag(spec.name) : std::string(spec.cli_names);
}

// The spec's help text with flags for members, then `help_suffix` (what it does in this
// command).
inline std::string cli_help(const OptionSpec& spec, const std::string& help_suffix = "") {
  return with_cli_flags(spec.help) + help_suffix;
}

// --NAME with the library's help text and range; `flags`: more names after the first
// (",--alias").
template <class T>
CLI::Option* add_spec_option(CLI::App& cmd, const OptionSpec& spec, T& value,
                             const std::string& flags = "", const std::string& help_suffix = "") {
  CLI::Option* option = cmd.add_option(cli_names(spec) + flags, value, cli_help(spec, help_suffix));
  if (spec.range) {
    // Unbounded above: the command line's bound for values without a natural one.
    const double highest = std::min(spec.range->highest, kLargestValue);
    option->check(spec.range->lowest_excluded ? finite_above(spec.range->lowest, highest)
                                              : finite_in(spec.range->lowest, highest));
  }
  return option;
}

// A flag (its cli_names may negate it: "!--no-flips") with the library's help text.
inline CLI::Option* add_spec_flag(CLI::App& cmd, const OptionSpec& spec, bool& value) {
  return cmd.add_flag(cli_names(spec), value, cli_help(spec));
}

}  // namespace molmesh::cli
