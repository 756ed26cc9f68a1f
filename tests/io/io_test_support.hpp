#pragma once
// Helpers for the io tests: scratch files in the per-test folder of support/files.hpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "molmesh/core/error.hpp"
#include "support/files.hpp"

namespace molmesh::test {

// `text` written to `file_name` in the running test's scratch folder (testing::test_dir).
inline std::filesystem::path write_text(const std::string& file_name, const std::string& text) {
  return testing::write_file(testing::test_dir() / file_name, text);
}

// Runs f, expects an InputError whose message contains every fragment.
template <class F>
void expect_input_error(F&& f, std::initializer_list<std::string> fragments) {
  try {
    f();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const auto& fragment : fragments)
      EXPECT_NE(what.find(fragment), std::string::npos)
          << "message: " << what << "\nmissing: " << fragment;
  }
}

}  // namespace molmesh::test
