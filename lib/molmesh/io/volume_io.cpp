#include "molmesh/io/volume_io.hpp"

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"
#include "molmesh/io/volume_dx.hpp"
#include "molmesh/io/volume_mrc.hpp"

namespace molmesh {
namespace {

constexpr const char* kKnown = "expected .dx, .mrc, .map or .ccp4";

bool is_mrc(const std::string& ext) { return ext == ".mrc" || ext == ".map" || ext == ".ccp4"; }

}  // namespace

bool is_volume_path(const std::filesystem::path& path) {
  const std::string ext = io_detail::format_extension(path);
  return ext == ".dx" || is_mrc(ext);
}

Grid read_volume(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string ext = io_detail::format_extension(path);
  if (!is_volume_path(path))
    throw InputError(name, "unknown volume format '" + ext + "' (" + kKnown + ")");
  const std::string bytes = io_detail::read_file_contents(path);
  return ext == ".dx" ? parse_dx(bytes, name) : parse_mrc(bytes, name);
}

void write_volume(const std::filesystem::path& path, const Grid& grid) {
  const std::string name = path.string();
  const std::string ext = io_detail::format_extension(path);
  if (!is_volume_path(path) || path.extension() == ".gz")
    throw OutputError("cannot write " + name + ": unknown volume format '" + ext + "' (" + kKnown +
                      ")");
  if (grid.dims[0] < 1 || grid.dims[1] < 1 || grid.dims[2] < 1 || grid.values.size() != grid.size())
    throw OutputError("cannot write " + name + ": grid dimensions and values do not match");
  if (ext == ".dx") {
    write_file_atomically(path, [&](std::ostream& out) { write_dx(out, grid); });
  } else {
    write_file_atomically(
        path, [&](std::ostream& out) { write_mrc(out, grid); }, true);
  }
}

}  // namespace molmesh
