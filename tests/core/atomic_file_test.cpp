#include "molmesh/core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "molmesh/core/error.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  auto dir = fs::temp_directory_path() / ("molmesh_" + name + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(AtomicFile, WritesCompleteFile) {
  auto dir = fresh_dir("atomic_ok");
  molmesh::write_file_atomically(dir / "out.txt", [](std::ostream& o) { o << "hello\n"; });
  EXPECT_EQ(read_all(dir / "out.txt"), "hello\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
}

TEST(AtomicFile, FailureLeavesPreviousContentAndNoTemporary) {
  auto dir = fresh_dir("atomic_fail");
  std::ofstream(dir / "out.txt") << "old\n";
  EXPECT_THROW(molmesh::write_file_atomically(dir / "out.txt",
                                              [](std::ostream& o) {
                                                o << "partial";
                                                throw molmesh::Error("boom");
                                              }),
               molmesh::Error);
  EXPECT_EQ(read_all(dir / "out.txt"), "old\n");
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
