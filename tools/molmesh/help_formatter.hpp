#pragma once
// The help text's option column as a user reads it: CLI11 (2.1) prints a negated flag with
// its value in braces (`--no-renumber{false}`) and a choice's checker after its value name
// (`TEXT:{interior,exterior,full}`); here a flag is its names only, and a choice is written
// `a|b|c` by one_of().
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

namespace molmesh::cli {

class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* option, bool is_positional) const override {
    std::string name = CLI::Formatter::make_option_name(option, is_positional);
    // Drop "{value}" after a flag name: the help text says what the flag does.
    std::string shown;
    int depth = 0;
    for (char c : name) {
      if (c == '{') ++depth;
      if (depth == 0) shown += c;
      if (c == '}' && depth > 0) --depth;
    }
    return shown;
  }
};

// Every command's help through HelpFormatter (set before the subcommands are added: they
// inherit the formatter).
inline void use_help_formatter(CLI::App& app) { app.formatter(std::make_shared<HelpFormatter>()); }

// Restricts `option` to `names`, shown in help as `a|b|c` (its default after '=').
inline CLI::Option* one_of(CLI::Option* option, const std::vector<std::string>& names) {
  std::string shown;
  for (const std::string& name : names) shown += (shown.empty() ? "" : "|") + name;
  return option->check(CLI::IsMember(names).description(""))->type_name(shown);
}

}  // namespace molmesh::cli
