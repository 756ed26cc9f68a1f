#include "molmesh/core/option_spec.hpp"

#include <cmath>
#include <cstdio>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

}  // namespace

std::string range_text(const OptionRange& range) {
  const bool unbounded = std::isinf(range.highest);
  return (range.lowest_excluded ? "(" : "[") + number(range.lowest) + ", " +
         (unbounded ? std::string("inf)") : number(range.highest) + "]");
}

void check_range(std::string_view member, const OptionRange& range, double value) {
  const bool inside = value <= range.highest &&
                      (range.lowest_excluded ? value > range.lowest : value >= range.lowest);
  // NaN fails every comparison; inf fails inside unbounded ranges only here.
  if (inside && std::isfinite(value)) return;
  throw OptionError("`" + std::string(member) + "` must be a finite number in " +
                    range_text(range) + " (got " + number(value) + ")");
}

void check_range(const OptionSpec& spec, double value) {
  if (spec.range) check_range(spec.member, *spec.range, value);
}

}  // namespace molmesh
