// Fuzz target: MRC/CCP4 volume reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/volume_mrc.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_mrc(molmesh::fuzz::bytes(data, size), "fuzz.mrc"));
  });
  return 0;
}
