#include "molmesh/io/mesh_obj.hpp"

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {

SurfaceMesh parse_obj(std::string_view text, const std::string& name) {
  using namespace io_detail;
  require_no_nul(text, name);
  SurfaceMesh mesh;
  LineCursor lines(text);
  std::vector<std::string_view> f;
  std::vector<long long> corners;
  // Faces may refer to vertices defined later; check indices once everything is read.
  struct Face {
    std::vector<long long> corners;
    std::size_t line;
  };
  std::vector<Face> faces;
  while (next_content(lines, f)) {
    const std::size_t n = lines.line_number();
    if (f[0] == "v") {
      if (f.size() < 4) throw InputError(name, n, "vertex needs 'v x y z'");
      mesh.points.push_back(parse_point(f, 1, name, n));
    } else if (f[0] == "f") {
      corners.clear();
      for (std::size_t i = 1; i < f.size(); ++i) {
        const std::string_view corner = f[i].substr(0, f[i].find('/'));
        const auto index = parse_integer(corner);
        if (!index || *index == 0)
          throw InputError(name, n,
                           "face corner '" + std::string(f[i]) +
                               "' does not start with a vertex number (1-based)");
        // Relative indices count back from the vertices defined so far.
        corners.push_back(*index > 0 ? *index - 1
                                     : static_cast<long long>(mesh.points.size()) + *index);
      }
      if (corners.size() < 3)
        throw InputError(
            name, n, "face has " + std::to_string(corners.size()) + " corners (at least 3 needed)");
      faces.push_back({corners, n});
    }
  }
  for (const Face& face : faces) {
    try {
      append_polygon(face.corners, mesh.points.size(), mesh.triangles, name, face.line);
    } catch (const InputError&) {
      // Report in the file's own 1-based numbering.
      for (long long c : face.corners) {
        if (c < 0 || static_cast<std::size_t>(c) >= mesh.points.size())
          throw InputError(name, face.line,
                           "vertex " + std::to_string(c + 1) + " does not exist (the file has " +
                               std::to_string(mesh.points.size()) + " vertices)");
      }
      throw;
    }
  }
  return mesh;
}

void write_obj(std::ostream& out, const SurfaceMesh& mesh) {
  std::string text = "# written by molmesh\n";
  for (const Vec3& p : mesh.points) {
    text += "v ";
    io_detail::append_point(text, p);
    text += '\n';
    io_detail::flush_when_large(out, text);
  }
  for (const Triangle& t : mesh.triangles) {
    text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
            std::to_string(t[2] + 1) + "\n";
    io_detail::flush_when_large(out, text);
  }
  out << text;
}

}  // namespace molmesh
