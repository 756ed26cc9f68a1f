// The command line turns the readers' InputErrors into exit code 3 and one line naming
// file and line (docs/cli.md); these runs stop at reading, so they are fast.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "io/io_test_support.hpp"
#include "support/cli.hpp"

namespace molmesh {
namespace {

using testing::CliRun;
using testing::run_cli;

TEST(CliInputErrors, MalformedPqrExitsWithCode3AndTheLine) {
  const auto pqr = test::write_text(
      "bad.pqr", "REMARK\nATOM 1 N ALA 1 0 0 0 0 1.8\nATOM 2 C ALA 1 0 0 0 0 -1\n");
  const auto out = testing::test_dir() / "out.off";
  const CliRun run = run_cli("surface " + pqr.string() + " -o " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("molmesh: error: " + pqr.string() + ":3: negative radius -1"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliInputErrors, BadRadiusTableAndUnknownElement) {
  const auto pdb = test::write_text(
      "fe.pdb",
      "HETATM    1 FE   HEM A 200      10.000  10.000  10.000  1.00  0.00          FE  \n");
  const auto out = (testing::test_dir() / "out.off").string();
  CliRun run = run_cli("surface " + pdb.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(pdb.string() + ":1:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--radii"), std::string::npos) << run.err;
  const auto table = test::write_text("radii.txt", "FE\n");
  run = run_cli("surface " + pdb.string() + " --radii " + table.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(table.string() + ":1:"), std::string::npos) << run.err;
}

// Issue 18: inputs that were accepted (exit 0 with a misread atom), crashed (SIGSEGV) or
// allocated gigabytes are exit 3 with file:line.
TEST(CliInputErrors, NonNumbersOverflowsAndNonFiniteValuesExitWithCode3) {
  const auto out = testing::test_dir() / "out.off";
  const auto pqr = test::write_text("r.pqr", "ATOM 1 C ALA 1 abc 0 0 0 1.5\n");
  CliRun run = run_cli("surface " + pqr.string() + " -o " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(pqr.string() + ":1: x coordinate 'abc' is not a finite number"),
            std::string::npos)
      << run.err;

  // MRC with 2^22 x 2^21 x 2^21 one-byte samples: the product wrapped to 0 (SIGSEGV).
  std::string mrc(1024 + 64, '\0');
  const std::int32_t words[] = {1 << 22, 1 << 21, 1 << 21, 0};
  std::memcpy(mrc.data(), words, sizeof words);
  for (int k = 0; k < 3; ++k) {
    const std::int32_t one = 1, axis = k + 1;
    const float length = 1.0f;
    std::memcpy(mrc.data() + 4 * (7 + k), &one, 4);
    std::memcpy(mrc.data() + 4 * (10 + k), &length, 4);
    std::memcpy(mrc.data() + 4 * (16 + k), &axis, 4);
  }
  mrc[4 * 53] = 0x44;
  const auto map = test::write_text("big.mrc", mrc);
  run = run_cli("surface " + map.string() + " --isovalue 0.5 -o " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(map.string() + ": file has"), std::string::npos) << run.err;

  const auto dx = test::write_text(
      "nan.dx",
      "object 1 class gridpositions counts 2 2 2\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n"
      "delta 0 0 1\nobject 3 class array type double rank 0 items 8 data follows\n"
      "nan nan nan\nnan nan nan\nnan nan\n");
  run = run_cli("surface " + dx.string() + " --isovalue 0.5 -o " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(dx.string() + ":7: value 'nan' is not a finite number"), std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliInputErrors, FormatsListsVolumes) {
  const CliRun run = run_cli("formats");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string& text = run.out;
  EXPECT_NE(text.find(".dx"), std::string::npos);
  EXPECT_NE(text.find(".mrc"), std::string::npos);
}

}  // namespace
}  // namespace molmesh
