// Fuzz target: OFF surface mesh reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/mesh_off.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_off(molmesh::fuzz::bytes(data, size), "fuzz.off"));
  });
  return 0;
}
