// Fuzz target: OBJ surface mesh reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/mesh_obj.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_obj(molmesh::fuzz::bytes(data, size), "fuzz.obj"));
  });
  return 0;
}
