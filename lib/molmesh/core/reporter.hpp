#pragma once
// The library never prints. Long operations report progress and warnings through a
// Reporter; the CLI renders them on stderr (or not, with --quiet). A default-constructed
// Reporter ignores everything, so callers that do not care pass {}.
#include <functional>
#include <string>
#include <string_view>

namespace molmesh {

struct Reporter {
  // stage: short human name ("blur", "marching cubes"); fraction in [0, 1].
  std::function<void(std::string_view stage, double fraction)> on_progress;
  std::function<void(std::string_view message)> on_warning;

  void progress(std::string_view stage, double fraction) const {
    if (on_progress) on_progress(stage, fraction);
  }
  void warn(std::string_view message) const {
    if (on_warning) on_warning(message);
  }
};

}  // namespace molmesh
