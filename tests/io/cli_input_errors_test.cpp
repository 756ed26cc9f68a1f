// The command line turns the readers' InputErrors into exit code 3 and one line naming
// file and line (docs/cli.md); these runs stop at reading, so they are fast.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/io_test_support.hpp"

namespace molmesh {
namespace {

struct CliRun {
  int exit_code = -1;
  std::string stderr_text;
};

CliRun run_cli(const std::string& arguments) {
  const auto err = test::scratch_dir() / "stderr.txt";
  const std::string command =
      std::string(MOLMESH_CLI_PATH) + " " + arguments + " > /dev/null 2> " + err.string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::slurp(err)};
}

TEST(CliInputErrors, MalformedPqrExitsWithCode3AndTheLine) {
  const auto pqr = test::write_text(
      "bad.pqr", "REMARK\nATOM 1 N ALA 1 0 0 0 0 1.8\nATOM 2 C ALA 1 0 0 0 0 -1\n");
  const auto out = test::scratch_dir() / "out.off";
  const CliRun run = run_cli("surface " + pqr.string() + " -o " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("molmesh: error: " + pqr.string() + ":3: negative radius -1"),
            std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliInputErrors, BadRadiusTableAndUnknownElement) {
  const auto pdb = test::write_text(
      "fe.pdb",
      "HETATM    1 FE   HEM A 200      10.000  10.000  10.000  1.00  0.00          FE  \n");
  const auto out = (test::scratch_dir() / "out.off").string();
  CliRun run = run_cli("surface " + pdb.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find(pdb.string() + ":1:"), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("--radii"), std::string::npos) << run.stderr_text;
  const auto table = test::write_text("radii.txt", "FE\n");
  run = run_cli("surface " + pdb.string() + " --radii " + table.string() + " -o " + out);
  EXPECT_EQ(run.exit_code, 3) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find(table.string() + ":1:"), std::string::npos) << run.stderr_text;
}

TEST(CliInputErrors, FormatsListsVolumes) {
  const auto out = test::scratch_dir() / "formats.txt";
  ASSERT_EQ(std::system((std::string(MOLMESH_CLI_PATH) + " formats > " + out.string()).c_str()), 0);
  const std::string text = test::slurp(out);
  EXPECT_NE(text.find(".dx"), std::string::npos);
  EXPECT_NE(text.find(".mrc"), std::string::npos);
}

}  // namespace
}  // namespace molmesh
