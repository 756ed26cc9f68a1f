// Fuzz target: sphere list reader (x y z radius per line).
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/sphere_list.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  molmesh::fuzz::ScratchFile file(molmesh::fuzz::bytes(data, size), "fuzz.spheres");
  molmesh::fuzz::expect_clean([&] {
    for (const auto& s : molmesh::read_spheres(file.path()))
      molmesh::fuzz::require(s.center.allFinite() && std::isfinite(s.radius) && s.radius >= 0.0,
                             "sphere");
  });
  return 0;
}
