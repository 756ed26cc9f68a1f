// Fuzz target: PDBx/mmCIF reader (gemmi).
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/atoms_structure.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::expect_clean([&] {
    molmesh::fuzz::check(
        molmesh::parse_structure(molmesh::fuzz::bytes(data, size), "fuzz.cif", true).atoms);
  });
  return 0;
}
