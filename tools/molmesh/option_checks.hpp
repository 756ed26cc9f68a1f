#pragma once
// Range checks for numeric command-line values, shared by every command's options. CLI11's
// PositiveNumber and Range let NaN through (every comparison with NaN is false) and accept
// inf and absurd magnitudes that later abort inside TetGen or exhaust memory; these refuse
// them at parse time, so the user gets exit code 2 and a message naming the option.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace molmesh::cli {

// Upper bound of values that have no natural one: far beyond any sensible input, but it
// keeps inf-like magnitudes (1e300) out of the arithmetic.
inline constexpr double kLargestValue = 1e15;

// An output path whose extension (case-insensitive) is one of `extensions` (".off", ...):
// an unknown format is a command-line error (exit 2) before any work is done.
CLI::Validator output_extension(std::vector<std::string> extensions);

// --max-memory GB, shared by every command that builds grids or meshes: the limit goes to
// `bytes` (default: core/resource_limits.hpp).
void add_max_memory_option(CLI::App& cmd, double& bytes);

// A finite number with lo <= value <= hi.
CLI::Validator finite_in(double lo, double hi);
// A finite number with lo < value <= hi.
CLI::Validator finite_above(double lo, double hi);

}  // namespace molmesh::cli
