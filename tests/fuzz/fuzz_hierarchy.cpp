// Fuzz target: multigrid hierarchy HDF5 reader (what `info` and `solve` read first).
// Validation of the file's contents belongs to io/hierarchy_hdf5.cpp (issue 18, runtime
// half); this target only runs it on mutated files.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::ScratchFile file(molmesh::fuzz::bytes(data, size), "fuzz.h5");
  molmesh::fuzz::expect_clean([&] {
    const molmesh::Hierarchy h = molmesh::read_hierarchy(file.path());
    for (const auto& level : h.levels) molmesh::fuzz::check(level.volume);
    if (!h.levels.empty()) molmesh::point_field_names(file.path(), 0);
  });
  return 0;
}
