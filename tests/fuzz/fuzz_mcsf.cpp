// Fuzz target: MCSF (FETK) tetrahedral mesh reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/mcsf.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::ScratchFile file(molmesh::fuzz::bytes(data, size), "fuzz.m");
  molmesh::fuzz::expect_clean([&] { molmesh::fuzz::check(molmesh::read_mcsf(file.path())); });
  return 0;
}
