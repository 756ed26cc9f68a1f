#pragma once
// Range checks for numeric command-line values, shared by every command's options. CLI11's
// PositiveNumber and Range let NaN through (every comparison with NaN is false) and accept
// inf and absurd magnitudes that later abort inside TetGen or exhaust memory; these refuse
// them at parse time, so the user gets exit code 2 and a message naming the option.
#include <CLI/CLI.hpp>

namespace molmesh::cli {

// A finite number with lo <= value <= hi.
CLI::Validator finite_in(double lo, double hi);
// A finite number with lo < value <= hi.
CLI::Validator finite_above(double lo, double hi);

}  // namespace molmesh::cli
