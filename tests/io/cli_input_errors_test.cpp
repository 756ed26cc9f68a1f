// The command line turns the readers' InputErrors into exit code 3 and one line naming
// file and line (docs/cli.md); these runs stop at reading, so they are fast.
#include <gtest/gtest.h>

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
  const auto out = test::scratch_dir() / "out.off";
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
  const auto out = (test::scratch_dir() / "out.off").string();
  CliRun run = run_cli("surface " + pdb.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(pdb.string() + ":1:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--radii"), std::string::npos) << run.err;
  const auto table = test::write_text("radii.txt", "FE\n");
  run = run_cli("surface " + pdb.string() + " --radii " + table.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find(table.string() + ":1:"), std::string::npos) << run.err;
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
