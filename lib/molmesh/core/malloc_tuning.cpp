#include "molmesh/core/malloc_tuning.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc systems

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace molmesh {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // 32 MiB is the largest mmap threshold glibc accepts on 64-bit systems; blocks above it
  // (a grid of several hundred MB) still come from mmap and go back when freed.
  constexpr int kMmapThreshold = 32 << 20;
  // Heap tops up to 1 GiB stay mapped between stages.
  constexpr int kTrimThreshold = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
#endif
}

}  // namespace molmesh
