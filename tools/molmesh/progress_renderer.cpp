#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "cli_context.hpp"

namespace molmesh::cli {
namespace {

// Redraws at most ~10 times a second so progress never slows the work it reports.
class ProgressRenderer {
 public:
  explicit ProgressRenderer(bool terminal) : terminal_(terminal) {}

  void update(std::string_view stage, double fraction) {
    const auto now = std::chrono::steady_clock::now();
    const bool new_stage = stage != stage_;
    const bool done = fraction >= 1.0;
    if (!new_stage && !done && now - last_draw_ < std::chrono::milliseconds(100)) return;
    if (!terminal_) {
      // In logs, one line per stage start and end is enough.
      if (new_stage) std::fprintf(stderr, "molmesh: %.*s...\n", int(stage.size()), stage.data());
      if (done && !(new_stage && fraction >= 1.0))
        std::fprintf(stderr, "molmesh: %.*s done\n", int(stage.size()), stage.data());
    } else {
      std::fprintf(stderr, "\r\033[Kmolmesh: %.*s %3d%%", int(stage.size()), stage.data(),
                   int(fraction * 100.0 + 0.5));
      if (done) std::fputc('\n', stderr);
    }
    std::fflush(stderr);
    stage_ = std::string(stage);
    last_draw_ = now;
  }

 private:
  bool terminal_;
  std::string stage_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace

Reporter CliContext::reporter() const {
  Reporter r;
  r.on_warning = [](std::string_view message) {
    std::fprintf(stderr, "molmesh: warning: %.*s\n", int(message.size()), message.data());
  };
  if (!quiet) {
    auto renderer = std::make_shared<ProgressRenderer>(isatty(STDERR_FILENO) != 0);
    r.on_progress = [renderer](std::string_view stage, double fraction) {
      renderer->update(stage, fraction);
    };
  }
  return r;
}

}  // namespace molmesh::cli
