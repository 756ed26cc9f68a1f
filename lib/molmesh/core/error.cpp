#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

std::string located(const std::string& file, std::size_t line, const std::string& message) {
  std::string text = file;
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ").append(message);
  return text;
}

}  // namespace

InputError::InputError(const std::string& file, std::size_t line, const std::string& message)
    : Error(located(file, line, message)), file_(file), line_(line) {}

InputError::InputError(const std::string& file, const std::string& message)
    : Error(located(file, 0, message)), file_(file) {}

}  // namespace molmesh
