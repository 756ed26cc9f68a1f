#pragma once
// Buffered text output for the mesh writers: numbers are formatted with std::to_chars
// (locale-free, no per-call stream overhead) into a large buffer that is handed to the
// stream in 1 MiB blocks. to_chars with an explicit format and precision produces exactly
// what printf does for the same conversion ("%.10e", "%.9g", ...), so switching a writer
// to it does not change a byte of its output.
#include <charconv>
#include <cstring>
#include <memory>
#include <ostream>
#include <string_view>

namespace molmesh::io_detail {

class TextOutput {
 public:
  explicit TextOutput(std::ostream& out) : out_(out), buffer_(new char[kBlock + kSlack]) {}
  TextOutput(const TextOutput&) = delete;
  TextOutput& operator=(const TextOutput&) = delete;

  TextOutput& text(std::string_view s) {
    if (s.size() > kBlock + kSlack - size_) {
      finish();
      if (s.size() > kBlock) {
        out_.write(s.data(), static_cast<std::streamsize>(s.size()));
        return *this;
      }
    }
    std::memcpy(buffer_.get() + size_, s.data(), s.size());
    size_ += s.size();
    return maybe_flush();
  }
  TextOutput& ch(char c) {
    buffer_[size_++] = c;
    return maybe_flush();
  }
  template <class Int>
  TextOutput& integer(Int value) {
    return advance(std::to_chars(free_begin(), free_end(), value));
  }
  // printf("%.<precision>e", value)
  TextOutput& scientific(double value, int precision) {
    return advance(
        std::to_chars(free_begin(), free_end(), value, std::chars_format::scientific, precision));
  }
  // printf("%.<precision>g", value)
  TextOutput& general(double value, int precision) {
    return advance(
        std::to_chars(free_begin(), free_end(), value, std::chars_format::general, precision));
  }
  // Hands the rest of the buffer to the stream; call once at the end.
  void finish() {
    out_.write(buffer_.get(), static_cast<std::streamsize>(size_));
    size_ = 0;
  }

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 20;
  // Below kBlock after every call, so at least kSlack bytes are free for the next one:
  // numbers are formatted in place (a temporary and an append each were a tenth of the
  // MCSF writer's time, issue 14). The longest number, a double with 17 digits, is < 40.
  static constexpr std::size_t kSlack = 4096;

  char* free_begin() { return buffer_.get() + size_; }
  char* free_end() { return buffer_.get() + kBlock + kSlack; }
  TextOutput& advance(std::to_chars_result result) {
    size_ = static_cast<std::size_t>(result.ptr - buffer_.get());
    return maybe_flush();
  }
  TextOutput& maybe_flush() {
    if (size_ >= kBlock) finish();
    return *this;
  }

  std::ostream& out_;
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0;
};

}  // namespace molmesh::io_detail
