#pragma once
// Errors are exceptions carrying a message a user can act on. The CLI prints what() on
// one line and maps the type to an exit code (docs/cli.md).
#include <cstddef>
#include <stdexcept>
#include <string>

namespace molmesh {

// Something the user asked for cannot be done (bad option value, impossible geometry).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file is missing, unreadable or malformed. The message starts with "file:line: " when a
// line is known, so editors and terminals can jump to it.
class InputError : public Error {
 public:
  InputError(const std::string& file, std::size_t line, const std::string& message);
  InputError(const std::string& file, const std::string& message);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }  // 0 when the problem is not on one line

 private:
  std::string file_;
  std::size_t line_ = 0;
};

// Writing an output failed; the target is left untouched.
class OutputError : public Error {
 public:
  using Error::Error;
};

}  // namespace molmesh
