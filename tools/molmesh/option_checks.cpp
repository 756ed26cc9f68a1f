#include "option_checks.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace molmesh::cli {
namespace {

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Empty string when `text` is a finite number inside the interval, else the complaint.
CLI::Validator interval(double lo, double hi, bool open_below) {
  const std::string description =
      (open_below ? "(" : "[") + format(lo) + ", " + format(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
        if (!std::isfinite(v)) return "'" + text + "' is not a finite number";
        if (v < lo || v > hi || (open_below && v == lo))
          return "'" + text + "' is outside the accepted range " + description;
        return {};
      },
      "FINITE in " + description);
}

}  // namespace

CLI::Validator finite_in(double lo, double hi) { return interval(lo, hi, false); }
CLI::Validator finite_above(double lo, double hi) { return interval(lo, hi, true); }

}  // namespace molmesh::cli
