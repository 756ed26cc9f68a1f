// Fuzz target: OpenDX volume reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/volume_dx.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_dx(molmesh::fuzz::bytes(data, size), "fuzz.dx"));
  });
  return 0;
}
