// Fuzz target: PLY surface mesh reader (ascii and binary, both byte orders).
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/mesh_ply.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_ply(molmesh::fuzz::bytes(data, size), "fuzz.ply"));
  });
  return 0;
}
