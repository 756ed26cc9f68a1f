#include "molmesh/core/resource_limits.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "molmesh/core/error.hpp"

namespace molmesh {

double default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 4.0 * 1024 * 1024 * 1024;
  return 0.5 * static_cast<double>(pages) * static_cast<double>(page_size);
}

std::string format_bytes(double bytes) {
  static const char* const kUnits[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 1000.0 && unit < 6) {
    bytes /= 1000.0;
    ++unit;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, bytes < 10 && unit > 0 ? "%.1f %s" : "%.0f %s", bytes,
                kUnits[unit]);
  return buf;
}

void check_memory(double bytes, double limit, const std::string& what, const std::string& hint) {
  // NaN or inf estimates (absurd inputs) are refused too.
  if (bytes <= limit) return;
  throw Error(
      what + " would need " + (std::isfinite(bytes) ? format_bytes(bytes) : "unbounded memory") +
      ", more than the memory limit of " + format_bytes(limit) + " (`max_memory_bytes`); " + hint);
}

}  // namespace molmesh
