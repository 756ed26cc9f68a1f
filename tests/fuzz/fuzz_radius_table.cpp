// Fuzz target: --radii table reader.
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/radius_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::ScratchFile file(molmesh::fuzz::bytes(data, size), "fuzz.radii");
  molmesh::fuzz::expect_clean([&] {
    const auto table = molmesh::read_radius_table(file.path());
    for (const auto& [key, r] : table.by_element)
      molmesh::fuzz::require(std::isfinite(r) && r >= 0.0, "radius");
    for (const auto& [key, r] : table.by_residue_atom)
      molmesh::fuzz::require(std::isfinite(r) && r >= 0.0, "radius");
  });
  return 0;
}
