#pragma once
// Buffered text output for the mesh writers: numbers are formatted with std::to_chars
// (locale-free, no per-call stream overhead) into a large buffer that is handed to the
// stream in 1 MiB blocks. to_chars with an explicit format and precision produces exactly
// what printf does for the same conversion ("%.10e", "%.9g", ...), so switching a writer
// to it does not change a byte of its output.
#include <charconv>
#include <ostream>
#include <string>
#include <string_view>

namespace molmesh::io_detail {

class TextOutput {
 public:
  explicit TextOutput(std::ostream& out) : out_(out) { buffer_.reserve(kBlock + 4096); }
  TextOutput(const TextOutput&) = delete;
  TextOutput& operator=(const TextOutput&) = delete;

  TextOutput& text(std::string_view s) {
    buffer_.append(s);
    return maybe_flush();
  }
  TextOutput& ch(char c) {
    buffer_.push_back(c);
    return maybe_flush();
  }
  template <class Int>
  TextOutput& integer(Int value) {
    char tmp[24];
    const auto result = std::to_chars(tmp, tmp + sizeof tmp, value);
    buffer_.append(tmp, static_cast<std::size_t>(result.ptr - tmp));
    return maybe_flush();
  }
  // printf("%.<precision>e", value)
  TextOutput& scientific(double value, int precision) {
    return real(value, std::chars_format::scientific, precision);
  }
  // printf("%.<precision>g", value)
  TextOutput& general(double value, int precision) {
    return real(value, std::chars_format::general, precision);
  }
  // Hands the rest of the buffer to the stream; call once at the end.
  void finish() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 20;

  TextOutput& real(double value, std::chars_format format, int precision) {
    char tmp[64];
    const auto result = std::to_chars(tmp, tmp + sizeof tmp, value, format, precision);
    buffer_.append(tmp, static_cast<std::size_t>(result.ptr - tmp));
    return maybe_flush();
  }
  TextOutput& maybe_flush() {
    if (buffer_.size() >= kBlock) finish();
    return *this;
  }

  std::ostream& out_;
  std::string buffer_;
};

}  // namespace molmesh::io_detail
