#include "molmesh/core/error.hpp"

#include <algorithm>

namespace molmesh {
namespace {

// Messages quote file contents, which may hold any byte. A NUL would cut what() short and a
// CR or escape sequence would garble the terminal, so control bytes are shown as \xHH
// (tab kept). Every InputError passes here: the one place messages are made safe.
std::string printable(const std::string& raw) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(raw.size());
  for (const char c : raw) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u == 0x7f) {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

std::string located(const std::string& file, std::size_t line, const std::string& message) {
  std::string text = file;
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ").append(message);
  return printable(text);
}

}  // namespace

InputError::InputError(const std::string& file, std::size_t line, const std::string& message)
    : Error(located(file, line, message)), file_(file), line_(line) {}

InputError::InputError(const std::string& file, const std::string& message)
    : Error(located(file, 0, message)), file_(file) {}

std::string spell_option_names(std::string_view message,
                               const std::function<std::string(std::string_view)>& spell) {
  const auto is_name_char = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    const std::size_t open = message.find('`', i);
    if (open == std::string_view::npos) break;
    std::size_t close = open + 1;
    while (close < message.size() && is_name_char(message[close])) ++close;
    out.append(message.substr(i, open - i));
    if (close < message.size() && message[close] == '`' && close > open + 1) {
      const std::string_view name = message.substr(open + 1, close - open - 1);
      const std::string spelled = spell(name);
      out.append(spelled.empty() ? message.substr(open, close - open + 1) : spelled);
      i = close + 1;
    } else {
      out += '`';
      i = open + 1;
    }
  }
  out.append(message.substr(std::min(i, message.size())));
  return out;
}

std::string spell_option_names(std::string_view message, const OptionSpellings& spellings) {
  return spell_option_names(message, [&](std::string_view name) -> std::string {
    const auto it = spellings.find(name);
    return it == spellings.end() ? std::string() : it->second;
  });
}

}  // namespace molmesh
