#include "option_checks.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "molmesh/core/resource_limits.hpp"

namespace molmesh::cli {
namespace {

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Empty string when `text` is a finite number inside the interval, else the complaint.
CLI::Validator interval(double lo, double hi, bool open_below) {
  const std::string description = (open_below ? "(" : "[") + format(lo) + ", " + format(hi) + "]";
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

CLI::Validator output_extension(std::vector<std::string> extensions) {
  std::string list;
  for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
  return CLI::Validator(
      [extensions, list](std::string& text) -> std::string {
        std::string ext = std::filesystem::path(text).extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (const auto& e : extensions)
          if (ext == e) return {};
        return "cannot tell the format of '" + text + "' from its extension; use " + list;
      },
      "PATH (" + list + ")");
}

void add_max_memory_option(CLI::App& cmd, double& bytes) {
  cmd.add_option_function<double>(
         "--max-memory", [&bytes](double gigabytes) { bytes = gigabytes * 1e9; },
         "Memory limit in GB for the blurred grid and the tetrahedral mesh: larger requests "
         "stop at once with the size they would need (default: half the physical memory, " +
             format(default_memory_limit() / 1e9) + " GB here)")
      ->check(finite_above(0, 1e6))
      ->type_name("GB");
}

CLI::Validator finite_in(double lo, double hi) { return interval(lo, hi, false); }
CLI::Validator finite_above(double lo, double hi) { return interval(lo, hi, true); }

}  // namespace molmesh::cli
