// Fuzz target: STL surface mesh reader (ascii and binary).
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/mesh_stl.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_stl(molmesh::fuzz::bytes(data, size), "fuzz.stl"));
  });
  return 0;
}
