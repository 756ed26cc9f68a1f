#pragma once
// An option of a library options struct as the front ends present it, so its name, help
// text and range are written once: the CLI binds `--` + name (with '-' for '_'), the Python
// module the keyword `name`, both with this help text and this range.
#include <optional>
#include <string>
#include <string_view>

namespace molmesh {

// The values validate() accepts: [lowest, highest], or (lowest, highest] when
// lowest_excluded; highest may be +inf (no bound beyond finiteness).
struct OptionRange {
  double lowest = 0.0;
  double highest = 0.0;
  bool lowest_excluded = false;
};

struct OptionSpec {
  std::string_view name;    // Python keyword; the CLI flag is "--" + name with '_' -> '-'
  std::string_view member;  // the struct member, as library messages name it (core/error.hpp)
  // One or two sentences with units; other options are named by their struct member,
  // backquoted (`sphere_ratio`), for each front end to spell as it does (spell_option_names).
  std::string_view help;
  std::optional<OptionRange> range;  // nullopt: not a number (a choice, a file, text)
  // The CLI's flag names where they are not "--" + name ("!--no-flips": a flag that turns
  // the option off; "--keep-on-surface,!--no-keep-on-surface"); empty: "--" + name.
  std::string_view cli_names = {};
};

// "[0, 70]", "(0, 10000]", "(0, inf)": the bounds as printf's %g prints them.
std::string range_text(const OptionRange& range);

// Throws molmesh::Error naming the option by its backquoted member (core/error.hpp), with
// the range and the value got, when `value` is NaN, infinite or outside `range`. For the
// validate() functions of the options structs, so the front ends' checks and the library's
// say the same. A spec without a range accepts every value.
void check_range(std::string_view member, const OptionRange& range, double value);
void check_range(const OptionSpec& spec, double value);

}  // namespace molmesh
