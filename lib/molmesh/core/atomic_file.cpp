#include "molmesh/core/atomic_file.hpp"

#include <fstream>
#include <random>
#include <system_error>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  std::random_device entropy;
  std::string name = ".";
  name.append(path.filename().string()).append(".tmp").append(std::to_string(entropy() % 1000000));
  return path.parent_path() / name;
}

void remove_quietly(const std::filesystem::path& p) {
  std::error_code ignored;
  std::filesystem::remove(p, ignored);
}

}  // namespace

void write_path_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write) {
  const auto tmp = temporary_sibling(path);
  try {
    write(tmp);
  } catch (...) {
    remove_quietly(tmp);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    remove_quietly(tmp);
    throw OutputError("cannot write " + path.string() + ": " + ec.message());
  }
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write, bool binary) {
  write_path_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::out : std::ios::out);
    if (!out) throw OutputError("cannot create " + path.string() + " (is the folder writable?)");
    write(out);
    out.flush();
    if (!out) throw OutputError("write failed for " + path.string() + " (disk full?)");
  });
}

}  // namespace molmesh
