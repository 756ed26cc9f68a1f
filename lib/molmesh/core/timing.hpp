#pragma once
// Wall-clock timing for the `timings` sections of --stats and the hierarchy report.
#include <chrono>

namespace molmesh {

// Seconds of steady-clock time since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace molmesh
