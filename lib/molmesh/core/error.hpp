#pragma once
// Errors are exceptions carrying a message a user can act on. The CLI prints what() on
// one line and maps the type to an exit code (docs/cli.md).
//
// A message names an option the way the library spells it: its member in the options
// struct, backquoted (`size_factor`, `max_memory_bytes`, `level`), never a front end's
// flag or keyword. The CLI and the Python module put their own spelling in its place with
// spell_option_names().
#include <cstddef>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace molmesh {

// Something the user asked for cannot be done (bad option value, impossible geometry).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An option's value is outside what it may be: its stated range, or what the input allows
// (an isovalue <= 0 for atoms, a level the hierarchy does not have). The CLI's exit code 2,
// as for a bad value on the command line; Python's ValueError.
class OptionError : public Error {
 public:
  using Error::Error;
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

// `message` with each backquoted option name (`name`: letters, digits, '_') replaced by
// spell(name); names spell() returns empty for are left as they are.
std::string spell_option_names(std::string_view message,
                               const std::function<std::string(std::string_view)>& spell);
// The same with a table: library name -> the front end's spelling.
using OptionSpellings = std::map<std::string, std::string, std::less<>>;
std::string spell_option_names(std::string_view message, const OptionSpellings& spellings);

}  // namespace molmesh
