#include "molmesh/core/option_spec.hpp"

#include <cmath>
#include <cstdio>

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

}  // namespace molmesh
