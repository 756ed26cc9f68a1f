#pragma once
// Shared by the reader fuzz targets (tests/fuzz/fuzz_*.cpp). A reader may refuse its input
// with molmesh::Error (the CLI's exit 2/3); any other exception (bad_alloc, length_error:
// the CLI's exit 70) is a finding and aborts, like a crash, so libFuzzer keeps the input.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "molmesh/core/error.hpp"

namespace molmesh::fuzz {

inline std::string bytes(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

template <class F>
void expect_clean(F&& read) {
  try {
    read();
  } catch (const molmesh::Error& e) {
    // Refused cleanly. The message must be one printable line. MOLMESH_FUZZ_VERBOSE=1 shows
    // it (to check that seeds are read, not refused).
    if (std::getenv("MOLMESH_FUZZ_VERBOSE")) std::fprintf(stderr, "refused: %s\n", e.what());
    for (const char c : std::string_view(e.what()))
      if (c == '\n' || c == '\r' || c == '\0') {
        std::fprintf(stderr, "fuzz: control byte in message: %s\n", e.what());
        std::abort();
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: unexpected exception (not molmesh::Error): %s\n", e.what());
    std::abort();
  }
}

// A scratch file holding `contents` for readers that take a path; removed on destruction.
// Per process (libFuzzer forks workers), under $TMPDIR.
class ScratchFile {
 public:
  ScratchFile(std::string_view contents, const std::string& file_name) {
    dir_ = std::filesystem::temp_directory_path() / ("molmesh_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    path_ = dir_ / file_name;
    std::ofstream(path_, std::ios::binary)
        .write(contents.data(), static_cast<std::streamsize>(contents.size()));
  }
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path dir_, path_;
};

}  // namespace molmesh::fuzz
