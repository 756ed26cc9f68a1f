#include "molmesh/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "molmesh/core/error.hpp"
#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

TEST(AtomicFile, WritesCompleteFile) {
  auto dir = molmesh::testing::test_dir("atomic_ok");
  molmesh::write_file_atomically(dir / "out.txt", [](std::ostream& o) { o << "hello\n"; });
  EXPECT_EQ(molmesh::testing::slurp(dir / "out.txt"), "hello\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
}

TEST(AtomicFile, FailureLeavesPreviousContentAndNoTemporary) {
  auto dir = molmesh::testing::test_dir("atomic_fail");
  std::ofstream(dir / "out.txt") << "old\n";
  EXPECT_THROW(molmesh::write_file_atomically(dir / "out.txt",
                                              [](std::ostream& o) {
                                                o << "partial";
                                                throw molmesh::Error("boom");
                                              }),
               molmesh::Error);
  EXPECT_EQ(molmesh::testing::slurp(dir / "out.txt"), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
}

TEST(AtomicFile, UnwritableFolderIsAnOutputError) {
  EXPECT_THROW(molmesh::write_file_atomically("/nonexistent-folder/x.txt",
                                              [](std::ostream& o) { o << "x"; }),
               molmesh::OutputError);
}

TEST(InputErrorMessage, NamesFileAndLine) {
  molmesh::InputError e("mol.pqr", 12, "expected 10 fields");
  EXPECT_STREQ(e.what(), "mol.pqr:12: expected 10 fields");
  EXPECT_EQ(e.line(), 12u);
}

}  // namespace
