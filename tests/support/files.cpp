#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

namespace molmesh::testing {

namespace fs = std::filesystem;

fs::path test_dir(const std::string& tag) {
  std::string name = "molmesh_test";
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
    name += std::string("_") + info->test_suite_name() + "_" + info->name();
  else if (const auto* suite = ::testing::UnitTest::GetInstance()->current_test_suite())
    name += std::string("_") + suite->name();  // SetUpTestSuite: no test is running yet
  if (!tag.empty()) name += "_" + tag;
  name += "_" + std::to_string(::getpid());
  for (char& c : name)
    if (c == '/') c = '_';  // parameterised test names hold '/'
  const fs::path dir = fs::temp_directory_path() / name;
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace molmesh::testing
