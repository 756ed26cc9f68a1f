#pragma once
// Files for tests: a fresh scratch folder per test, whole-file reads and writes, and shell
// quoting for the commands tests run (support/process.hpp).
#include <filesystem>
#include <string>

namespace molmesh::testing {

// The running test's own folder (created on the first call; the same folder on every call of
// the test): under the temporary directory, named for its test suite, test, `tag` and this
// process, so parallel tests and runs never share one. Called from SetUpTestSuite, the
// suite's folder.
std::filesystem::path test_dir(const std::string& tag = "");

// The whole file as bytes; empty if it cannot be read.
std::string slurp(const std::filesystem::path& path);

// Writes `bytes` to `path` (binary, replacing it); returns `path`.
std::filesystem::path write_file(const std::filesystem::path& path, const std::string& bytes);

// `text` as one /bin/sh word (single-quoted, with embedded quotes escaped).
std::string shell_quoted(const std::string& text);

}  // namespace molmesh::testing
