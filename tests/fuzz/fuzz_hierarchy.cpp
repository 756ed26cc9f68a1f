// Fuzz target: multigrid hierarchy HDF5 reader (what `info` and `solve` read first).
// Validation of the file's contents belongs to io/hierarchy_hdf5.cpp (issue 18, runtime
// half); this target only runs it on mutated files.
//
// read_hierarchy first reads the whole file in a forked child (io/hierarchy_probe.cpp) and
// refuses the file if that child dies: the containment of libhdf5's own defects. Under a
// sanitizer, a defect the sanitizer reports in that child (not a signal: an ASan report)
// would run the death callback the child inherited, libFuzzer's, which saves the input as
// a crash of this process. The child's callback is replaced, in the child only, by a plain
// exit, so the child dies, the probe refuses the file, and only faults of the real read,
// in this process, become findings (docs/testing.md, "Fuzz campaigns", session 15).
#include <pthread.h>
#include <unistd.h>

#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define MOLMESH_FUZZ_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MOLMESH_FUZZ_SANITIZED 1
#endif
#endif

#ifdef MOLMESH_FUZZ_SANITIZED
#include <sanitizer/common_interface_defs.h>

namespace {

// Any non-zero exit is a refusal to the probe; 86 marks "a sanitizer report in the child".
void exit_child_on_sanitizer_report() { ::_exit(86); }

[[maybe_unused]] const int child_death_callback_registered = [] {
  ::pthread_atfork(nullptr, nullptr,
                   [] { __sanitizer_set_death_callback(exit_child_on_sanitizer_report); });
  return 0;
}();

}  // namespace
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::ScratchFile file(molmesh::fuzz::bytes(data, size), "fuzz.h5");
  molmesh::fuzz::expect_clean([&] {
    const molmesh::Hierarchy h = molmesh::read_hierarchy(file.path());
    for (const auto& level : h.levels) molmesh::fuzz::check(level.volume);
    if (!h.levels.empty()) molmesh::point_field_names(file.path(), 0);
  });
  return 0;
}
