// `molmesh export` on a real hierarchy, read back by independent readers (meshio, scipy,
// a numpy parser of PETSc's binary format; check_export.py) and compared with the HDF5.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/io_test_support.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

class ExportCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // Per process: ctest runs each test of the suite in its own process, in parallel.
    dir_ = testing::test_dir();
    h5_ = dir_ / "fas2.h5";
    hierarchy_ =
        testing::run_cli("-q hierarchy " + (fs::path(MOLMESH_TEST_DATA_DIR) / "fas2.pqr").string() +
                         " --t0 0.1,0.3 --domain exterior --outer-radius 60 -o " + h5_.string());
  }
  static inline fs::path dir_, h5_;
  static inline testing::CliRun hierarchy_;
};

TEST_F(ExportCli, IndependentReadersReadEveryLevel) {
  ASSERT_EQ(hierarchy_.exit_code, 0) << hierarchy_.err;
  const auto run = testing::run_cli("-q export " + h5_.string() + " --all-levels -o " +
                                    (dir_ / "fas2").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  // One line per file written: 5 per level and 4 per transfer.
  const std::string& listing = run.out;
  EXPECT_EQ(std::count(listing.begin(), listing.end(), '\n'), 2 * 5 + 4) << listing;
  const fs::path checker = fs::path(MOLMESH_TEST_DATA_DIR).parent_path() / "io" / "check_export.py";
  const testing::CommandRun check = testing::run_command(
      "/usr/bin/python3 " + testing::shell_quoted(checker.string()) + " " +
      testing::shell_quoted(h5_.string()) + " " + testing::shell_quoted((dir_ / "fas2").string()));
  EXPECT_EQ(check.exit_code, 0) << check.output();
}

TEST_F(ExportCli, OneLevelAndItsProlongation) {
  ASSERT_EQ(hierarchy_.exit_code, 0);
  const auto run =
      testing::run_cli("-q export " + h5_.string() + " --level 1 -o " + (dir_ / "one").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "one_L1_volume.m"));
  EXPECT_FALSE(fs::exists(dir_ / "one_L0_volume.m"));
  // Level 1 is the coarsest of two: no prolongation has it as the fine level.
  EXPECT_FALSE(fs::exists(dir_ / "one_P1_to_0_volume.petsc"));
}

TEST_F(ExportCli, ALevelTheFileDoesNotHaveIsAnError) {
  ASSERT_EQ(hierarchy_.exit_code, 0);
  const auto run =
      testing::run_cli("-q export " + h5_.string() + " --level 7 -o " + (dir_ / "bad").string());
  EXPECT_EQ(run.exit_code, 2);  // a bad option value (OptionError), like --level -1
  EXPECT_EQ(run.signal, 0);
  const std::string& log = run.err;
  EXPECT_NE(log.find("has 2 level(s)"), std::string::npos) << log;
  // The library's `level` is spelled as the flag the user typed.
  EXPECT_NE(log.find("--level 7:"), std::string::npos) << log;
  EXPECT_EQ(log.find('`'), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir_ / "bad_L0_volume.m"));
}

}  // namespace
}  // namespace molmesh
