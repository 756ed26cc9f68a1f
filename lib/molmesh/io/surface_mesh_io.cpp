#include "molmesh/io/surface_mesh_io.hpp"

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/mesh_obj.hpp"
#include "molmesh/io/mesh_off.hpp"
#include "molmesh/io/mesh_ply.hpp"
#include "molmesh/io/mesh_stl.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

constexpr const char* kKnown = "expected .off, .ply, .obj or .stl";

// Markers must be empty or one per element; anything else is a bug upstream, and writing
// it would produce a file that cannot be read back.
void check_mesh(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  const std::string name = path.string();
  if (!mesh.vertex_markers.empty() && mesh.vertex_markers.size() != mesh.points.size())
    throw OutputError("cannot write " + name + ": " + std::to_string(mesh.vertex_markers.size()) +
                      " vertex markers for " + std::to_string(mesh.points.size()) + " vertices");
  if (!mesh.face_markers.empty() && mesh.face_markers.size() != mesh.triangles.size())
    throw OutputError("cannot write " + name + ": " + std::to_string(mesh.face_markers.size()) +
                      " face markers for " + std::to_string(mesh.triangles.size()) + " triangles");
  for (const Triangle& t : mesh.triangles)
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.points.size())
        throw OutputError("cannot write " + name + ": triangle refers to vertex " +
                          std::to_string(v) + " of " + std::to_string(mesh.points.size()));
}

}  // namespace

bool is_surface_mesh_path(const std::filesystem::path& path) {
  const std::string ext = io_detail::format_extension(path);
  return ext == ".off" || ext == ".ply" || ext == ".obj" || ext == ".stl";
}

SurfaceMesh read_surface_mesh(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string ext = io_detail::format_extension(path);
  if (!is_surface_mesh_path(path))
    throw InputError(name, "unknown surface mesh format '" + ext + "' (" + kKnown + ")");
  const std::string bytes = io_detail::read_file_contents(path);
  if (ext == ".off") return parse_off(bytes, name);
  if (ext == ".ply") return parse_ply(bytes, name);
  if (ext == ".obj") return parse_obj(bytes, name);
  return parse_stl(bytes, name);
}

void write_surface_mesh(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  const std::string ext = io_detail::format_extension(path);
  if (!is_surface_mesh_path(path) || path.extension() == ".gz")
    throw OutputError("cannot write " + path.string() + ": unknown surface mesh format '" + ext +
                      "' (" + kKnown + ")");
  check_mesh(path, mesh);
  if (ext == ".off") {
    write_file_atomically(path, [&](std::ostream& out) { write_off(out, mesh); });
  } else if (ext == ".obj") {
    write_file_atomically(path, [&](std::ostream& out) { write_obj(out, mesh); });
  } else if (ext == ".ply") {
    write_file_atomically(
        path, [&](std::ostream& out) { write_ply(out, mesh); }, true);
  } else {
    write_file_atomically(
        path, [&](std::ostream& out) { write_stl(out, mesh); }, true);
  }
}

}  // namespace molmesh
