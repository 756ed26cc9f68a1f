// Fuzz target: MSMS .vert/.face reader. The input holds both files, split at the first
// line "@face" (seeds: tests/fuzz/corpus/msms).
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "molmesh/io/msms.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = molmesh::fuzz::bytes(data, size);
  const std::size_t split = input.find("\n@face\n");
  const std::string vert = input.substr(0, split);
  const std::string face = split == std::string::npos ? std::string() : input.substr(split + 7);
  molmesh::fuzz::ScratchFile v(vert, "fuzz.vert"), f(face, "fuzz.face");
  molmesh::fuzz::expect_clean([&] { molmesh::fuzz::check(molmesh::read_msms(v.path())); });
  return 0;
}
