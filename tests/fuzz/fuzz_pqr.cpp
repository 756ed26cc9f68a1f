// Fuzz target: PQR reader (docs/testing.md, "Fuzzing").
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/atoms_pqr.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(molmesh::parse_pqr(molmesh::fuzz::bytes(data, size), "fuzz.pqr"));
  });
  return 0;
}
